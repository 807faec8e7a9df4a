// SPDX-License-Identifier: MIT
#include "watchcommand.h"

#include "app/cli/clioutput.h"
#include "app/cli/rosoptions.h"
#include "app/cli/sourcecheck.h"
#include "base/wallclock.h"
#include "config/configreader.h"
#include "latency/pipeline.h"
#include "models/mqtttopictree.h"
#include "record/runrecorder.h"
#include "ros/rosmasterapi.h"
#include "ros/rosmonitor.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "watch/eventthrottle.h"
#include "watch/livewatch.h"
#include "watch/watchmetrics.h"
#include "watch/watchsession.h"
#include "yaml/yamlreader.h"

#include <climits>
#include <QCommandLineParser>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSet>
#include <QTimer>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class Watch
{
    Q_DECLARE_TR_FUNCTIONS(WatchCommand)
};

/// What the command line asks for.
struct WatchRequest
{
    QList<WatchSession::Config> configs; ///< (name, file, config)
    MqttProfile broker;
    QString masterUri;
    WatchRules rules;
    QString metrics; ///< HOST:PORT, empty: none
    QList<WatchMetrics::Label> labels; ///< --label: on every metric
    QString eventsFile; ///< empty: none
    QString runPath; ///< -o: the events are recorded in this run file; empty: none
    RunInfo info; ///< of that run
    double seconds = 0; ///< 0: until Ctrl+C
    bool allowEmpty = false; ///< neither broker nor master reached is a success
    bool ros1 = true; ///< the ROS 1 master is watched (not with --ros 2)
    bool discover = true; ///< also the links mqtt_client announces that no config has
    std::optional<Pipeline> pipeline; ///< --pipeline: latency of the mappings with stamp topics, and recorded
    std::optional<Ros2Options> ros2; ///< --ros 2 or both: the ROS 2 domain joined as well
};

/// Reads the configs; their names are the files' base names (made unique).
bool readConfigs(const QStringList& paths, WatchRequest* request)
{
    QSet<QString> names;
    for (const QString& path : paths) {
        const Result<QByteArray> bytes = YamlReader::readFile(path);
        if (!bytes) {
            err(bytes.error().toString());
            return false;
        }
        const ConfigReadResult read = ConfigReader::read(*bytes);
        if (!read.parsed) {
            err(Watch::tr("%1: not a bridge config: %2")
                    .arg(path, read.problems.isEmpty() ? QString() : read.problems.first().message));
            return false;
        }
        QString name = QFileInfo(path).completeBaseName();
        for (int n = 2; names.contains(name); ++n)
            name = QFileInfo(path).completeBaseName() + u'#' + QString::number(n);
        names.insert(name);
        request->configs.append({name, QFileInfo(path).absoluteFilePath(), read.config});
        if (request->info.bridgeConfigPath.isEmpty()) { // a run keeps one config: the first
            request->info.bridgeConfigPath = QFileInfo(path).absoluteFilePath();
            request->info.bridgeConfig = *bytes;
        }
    }
    if (paths.size() > 1)
        request->info.notes = Watch::tr("Watched configs: %1").arg(paths.join(u", "_s));
    return true;
}

/// The broker of the first config (its host, port, TLS and credentials), for a watch without --broker.
MqttProfile brokerOf(const BridgeConfig& c)
{
    const bool tls = c.effective(OptionScope::Broker, u"tls.enabled"_s) == u"true"_s;
    MqttProfile p = MqttProfile::fromUrl(u"%1://%2:%3"_s.arg(tls ? u"ssl"_s : u"tcp"_s,
                                                             c.effective(OptionScope::Broker, u"host"_s),
                                                             c.effective(OptionScope::Broker, u"port"_s)));
    if (tls)
        p.caFile = c.effective(OptionScope::Broker, u"tls.ca_certificate"_s);
    p.username = c.effective(OptionScope::Broker, u"user"_s);
    p.password = c.effective(OptionScope::Broker, u"pass"_s);
    return p;
}

/// The command's options.
struct WatchOptions
{
    const QCommandLineOption broker {u"broker"_s,
                                     Watch::tr("Broker URL (default: the first config's broker)."), u"URL"_s};
    const QCommandLineOption master {u"ros-master"_s, Watch::tr("ROS master URI (default $ROS_MASTER_URI)."),
                                     u"URI"_s, RosMasterApi::defaultMasterUri()};
    const QCommandLineOption rules {
        u"rules"_s, Watch::tr("Rules YAML: thresholds for all links and per link."), u"RULES.yaml"_s};
    const QCommandLineOption metrics {
        u"metrics"_s,
        Watch::tr("Serve Prometheus metrics at http://HOST:PORT/metrics (e.g. 127.0.0.1:9464)."),
        u"HOST:PORT"_s};
    const QCommandLineOption label {
        u"label"_s,
        Watch::tr("A label on every metric, e.g. site=garage or host=vehicle-3 (default host: this "
                  "machine's name); repeat it for more."),
        u"NAME=VALUE"_s};
    const QCommandLineOption events {u"events-jsonl"_s,
                                     Watch::tr("Append every event to FILE as a JSON line."), u"FILE"_s};
    const QCommandLineOption seconds {u"seconds"_s, Watch::tr("Stop after S seconds (default: at Ctrl+C)."),
                                      u"S"_s};
    const QCommandLineOption output {{u"o"_s, u"output"_s},
                                     Watch::tr("Record the events in this run file (never overwritten); "
                                               "bridgescope report lists them."),
                                     u"RUN.bsrun"_s};
    const QCommandLineOption name {u"name"_s, Watch::tr("The run's name (default: the file's base name)."),
                                   u"NAME"_s};
    const QCommandLineOption notes {u"notes"_s, Watch::tr("Notes kept with the run."), u"TEXT"_s};
    const QCommandLineOption noDiscover {
        u"no-discover"_s,
        Watch::tr("Watch only the configs' mappings, not the links mqtt_client announces on the broker.")};
    const QCommandLineOption pipeline {
        u"pipeline"_s,
        Watch::tr(
            "The timestamp topics' pipeline: a mapping with a timestamp_topic_prefix takes its latency from "
            "PREFIX/in to PREFIX/out, and -o records the samples as well."),
        u"PIPELINE.yaml"_s};
    const QCommandLineOption allowEmpty {
        u"allow-empty"_s,
        Watch::tr("Exit 0 even when nothing was heard (neither the broker nor the master "
                  "reached, nobody on the ROS 2 domain).")};

    void addTo(QCommandLineParser& parser) const
    {
        parser.addOptions({broker, master, rules, metrics, label, events, seconds, output, name, notes,
                           noDiscover, pipeline, allowEmpty});
    }
};

/// The files the options name (rules, pipeline) and the broker: false after saying what is wrong.
bool readOptionFiles(const QCommandLineParser& parser, const WatchOptions& o, WatchRequest* request)
{
    request->broker = parser.isSet(o.broker) ? MqttProfile::fromUrl(parser.value(o.broker))
                                             : brokerOf(request->configs.first().config);
    if (const Status valid = request->broker.validate(); !valid) {
        err(valid.error().toString());
        return false;
    }
    if (parser.isSet(o.rules)) {
        const Result<WatchRules> r = WatchRules::readFile(parser.value(o.rules));
        if (!r) {
            err(r.error().toString());
            return false;
        }
        request->rules = *r;
    }
    if (parser.isSet(o.pipeline)) {
        Result<Pipeline> pipeline = Pipeline::readFile(parser.value(o.pipeline));
        if (!pipeline) {
            err(pipeline.error().toString());
            return false;
        }
        request->pipeline = std::move(pipeline).value();
    }
    return true;
}

/// The run's outputs: metrics, events file, run file with its name and notes. False after saying
/// what is wrong.
bool readOutputs(const QCommandLineParser& parser, const WatchOptions& o, WatchRequest* request)
{
    request->metrics = parser.value(o.metrics);
    if (const Status address
        = parser.isSet(o.metrics) ? WatchMetrics::checkAddress(request->metrics) : Status();
        !address) {
        err(address.error()
                .toString()); // a port beyond 65535 or no host: the command line is wrong, not the network
        return false;
    }
    if (parser.isSet(o.label) && !parser.isSet(o.metrics)) {
        err(Watch::tr("--label names the metrics: give --metrics HOST:PORT too"));
        return false;
    }
    const QStringList labels = parser.values(o.label);
    if (labels.size() > WatchMetrics::kMaxOwnLabels) {
        err(Watch::tr("at most %1 --label options").arg(WatchMetrics::kMaxOwnLabels));
        return false;
    }
    for (const QString& text : labels) {
        const Result<WatchMetrics::Label> l = WatchMetrics::parseLabel(text);
        if (!l) {
            err(l.error().toString());
            return false;
        }
        request->labels.push_back(*l);
    }
    request->eventsFile = parser.value(o.events);
    request->runPath = parser.value(o.output);
    if ((parser.isSet(o.name) || parser.isSet(o.notes)) && !parser.isSet(o.output)) {
        err(Watch::tr("--name and --notes describe a run: give -o RUN.bsrun too"));
        return false;
    }
    request->info.name
        = parser.isSet(o.name) ? parser.value(o.name) : QFileInfo(request->runPath).completeBaseName();
    if (parser.isSet(o.notes))
        request->info.notes = parser.value(o.notes)
            + (request->info.notes.isEmpty() ? QString() : u"\n"_s + request->info.notes);
    return true;
}

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseWatch(const QStringList& arguments, WatchRequest* request)
{
    QCommandLineParser parser;
    const WatchOptions o;
    o.addTo(parser);
    RosOptions ros;
    ros.addTo(parser);
    parser.addPositionalArgument(u"CONFIG"_s, Watch::tr("mqtt_client configs whose mappings are watched."),
                                 u"[CONFIG.yaml...]"_s);
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope watch"_s,
        Watch::tr(
            "Watches every mapping of the configs as a link, until Ctrl+C: rate at both ends, messages "
            "lost, Header.seq gaps, stalls, the source stopping, latency of stamped messages and the "
            "bridges' state; and, from their MQTT end, the links mqtt_client announces on the broker "
            "that no config maps. Every change of a link's state is an event, printed as a JSON line.\n"
            "A broker or master that cannot be reached is said within 5 s; it keeps trying.\n"
            "Exit status: 0 stopped, 1 nothing heard: no broker, no master, nobody on ROS 2 (without "
            "--allow-empty), the metrics port was not served or the run file not written, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    request->discover = !parser.isSet(o.noDiscover);
    if (parser.positionalArguments().isEmpty() && (!parser.isSet(o.broker) || !request->discover)) {
        err(Watch::tr("watch needs a bridge config, or --broker to watch the links announced there; see "
                      "bridgescope watch --help"));
        return ExitUsage;
    }
    if (!readConfigs(parser.positionalArguments(), request))
        return ExitUsage;
    if (parser.isSet(o.seconds) && !CliOutput::readSeconds(parser.value(o.seconds), &request->seconds)) {
        err(CliOutput::secondsError());
        return ExitUsage;
    }
    request->allowEmpty = parser.isSet(o.allowEmpty);
    if (!readOptionFiles(parser, o, request))
        return ExitUsage;
    if (const Status read = ros.read(parser); !read) {
        err(read.error().toString());
        return ExitUsage;
    }
    for (const QString& line : ros.notes())
        err(line);
    request->ros2 = ros.ros2 ? std::optional<Ros2Options>(ros.ros2Options) : std::nullopt;
    request->ros1 = ros.ros1;
    request->masterUri = parser.value(o.master);
    return readOutputs(parser, o, request) ? -1 : ExitUsage;
}

/// The Prometheus endpoint at HOST:PORT, said on stderr; none after saying why.
std::unique_ptr<WatchMetrics> serveMetrics(const QString& hostPort, const QList<WatchMetrics::Label>& labels)
{
    Result<std::unique_ptr<WatchMetrics>> served = WatchMetrics::serve(hostPort, labels);
    if (!served) {
        err(served.error().toString());
        return nullptr;
    }
    std::unique_ptr<WatchMetrics> metrics = std::move(served).value();
    // The port that was bound: with port 0 the system chose it.
    const QString host = hostPort.left(hostPort.lastIndexOf(u':'));
    err(Watch::tr("metrics at http://%1:%2/metrics").arg(host).arg(metrics->port()));
    return metrics;
}

/// Starts the run file of -o: in the measurement's recorder with a pipeline, else in the watch's own.
bool startRecording(const WatchRequest& request, LiveWatch& watch)
{
    RunInfo info = request.info;
    info.startedNs = wallClockNs();
    info.broker = request.broker.url;
    info.rosMaster = request.masterUri;
    info.describeThisMachine();
    if (const Result<void> started = watch.startRecording(request.runPath, info); !started) {
        err(started.error().toString());
        return false;
    }
    return true;
}

/// The configs' MQTT topics, each once, in their order.
QStringList mappedMqttTopics(const WatchRequest& request)
{
    QStringList watchedTopics;
    QSet<QString> seenTopics; // a list's contains() is quadratic in a config of 1,000 links
    for (const WatchSession::Config& c : request.configs)
        for (const Mapping& m : c.config.mappings)
            if (!seenTopics.contains(m.mqttTopic())) {
                seenTopics.insert(m.mqttTopic());
                watchedTopics << m.mqttTopic();
            }
    return watchedTopics;
}

/// What a watch saw, counted over its links and events.
struct WatchTally
{
    int levels[3] = {0, 0, 0}; ///< links by LinkLevel (those seen)
    int unknown = 0; ///< links the watch cannot see a side of now
    quint64 sourceMessages = 0;
    quint64 destinationMessages = 0;
    quint64 lost = 0; ///< by the counts: a lower bound while the sources run (LinkTraffic::refreshLoss)
    quint64 observedLost = 0; ///< by content: each message that went in and never came out
    quint64 stalls = 0;
    int links = 0;

    static WatchTally of(const LinkMonitor& monitor)
    {
        WatchTally t;
        t.links = monitor.linkCount();
        for (int i = 0; i < monitor.linkCount(); ++i) {
            if (monitor.unknown(i).isEmpty())
                ++t.levels[int(monitor.level(i))];
            else
                ++t.unknown;
            const LinkFigures f = monitor.figures(i);
            t.sourceMessages += f.source.messages;
            t.destinationMessages += f.destination.messages;
            t.lost += f.lost;
            t.observedLost += f.observedLost;
            t.stalls += f.stalls;
        }
        return t;
    }
};

/// The summary a watch ends with: a sentence on stderr, one JSON line on stdout ("event": "summary").
void printSummary(const LinkMonitor& monitor, qint64 elapsedMs, int events, int alerts, quint64 heldBack,
                  const RosMonitor& ros1)
{
    const WatchTally t = WatchTally::of(monitor);
    // Both losses: the counts' is a lower bound while a source runs (what it sent in the last second
    // is not judged), the content's is exact where the two ends were matched; a summary of 10 %
    // dropped in 13 s read "lost 3" with the counts' alone.
    err(Watch::tr("watch ended after %1 s: links %2 (%3 ok, %4 warning, %5 alert, %6 unknown), events %7 (%8 "
                  "alerts), messages %9 at the sources and %10 at the destinations, lost %11 by the counts "
                  "and %13 by content, stalls %12")
            .arg(elapsedMs / 1000)
            .arg(t.links)
            .arg(t.levels[0])
            .arg(t.levels[1])
            .arg(t.levels[2])
            .arg(t.unknown)
            .arg(events)
            .arg(alerts)
            .arg(t.sourceMessages)
            .arg(t.destinationMessages)
            .arg(t.lost)
            .arg(t.stalls)
            .arg(t.observedLost));
    const QJsonObject summary {{u"event"_s, u"summary"_s},
                               {u"seconds"_s, double(elapsedMs) / 1000},
                               {u"links"_s, t.links},
                               {u"events"_s, events},
                               {u"alerts"_s, alerts},
                               {u"source_messages"_s, double(t.sourceMessages)},
                               {u"destination_messages"_s, double(t.destinationMessages)},
                               {u"lost"_s, double(t.lost)},
                               {u"observed_lost"_s, double(t.observedLost)},
                               {u"stalls"_s, double(t.stalls)},
                               {u"ok"_s, t.levels[0]},
                               {u"warning"_s, t.levels[1]},
                               {u"alert"_s, t.levels[2]},
                               {u"unknown"_s, t.unknown},
                               {u"held_back"_s, double(heldBack)},
                               {u"ros_publishers_asked_again"_s, double(ros1.publishersAskedAgain())},
                               {u"ros_subscriptions_made_again"_s, double(ros1.subscriptionsMadeAgain())}};
    if (heldBack > 0)
        err(Watch::tr("%n event line(s) held back by the storm bound (%1 a second after a burst of %2): "
                      "counted in the held_back lines",
                      nullptr, int(std::min<quint64>(heldBack, INT_MAX)))
                .arg(EventThrottle::kPerSecond)
                .arg(EventThrottle::kBurst));
    out(QString::fromUtf8(QJsonDocument(summary).toJson(QJsonDocument::Compact)));
}

/// The line said every 10 s: the links by level, and every budget that cut something.
QString progressLine(qint64 elapsedMs, const WatchSession& watch, const MqttTopicTree* topics,
                     const WatchMetrics* metrics, const RosMonitor* ros1, const Ros2Participant* ros2)
{
    const LinkMonitor* monitor = watch.monitor();
    const WatchTally tally = WatchTally::of(*monitor);
    QString line = Watch::tr("%1 s: %2 ok, %3 warning, %4 alert")
                       .arg(elapsedMs / 1000)
                       .arg(tally.levels[0])
                       .arg(tally.levels[1])
                       .arg(tally.levels[2]);
    if (tally.unknown > 0)
        line += Watch::tr(", %1 unknown (the watch's own connection is down)").arg(tally.unknown);
    if (const quint64 evicted = topics->topicData().store().evictedPayloads())
        line += Watch::tr("; %1 payloads evicted from the topic history (budget %2 MiB)")
                    .arg(evicted)
                    .arg(topics->topicData().store().historyBudget() / (1024 * 1024));
    if (const quint64 untracked = topics->topicData().store().untrackedMessages())
        line += Watch::tr("; %1 messages on topics not tracked (budget %2 topics, %3 MiB of names)")
                    .arg(untracked)
                    .arg(topics->topicData().store().topicBudget())
                    .arg(topics->topicData().store().structureBudget() / (1024 * 1024));
    if (const int unwatched = watch.unwatchedLinks())
        line += Watch::tr("; %1 announced links not watched (cap %2)")
                    .arg(unwatched)
                    .arg(WatchSession::kMaxDiscoveredLinks);
    if (const quint64 untimed = watch.droppedHeads())
        line += Watch::tr("; %1 messages not timed (more between two reads than the watch keeps)").arg(untimed);
    if (metrics && metrics->droppedClients())
        line += Watch::tr("; %1 metrics clients dropped").arg(metrics->droppedClients());
    if (const quint64 again = ros1 ? ros1->publishersAskedAgain() : 0)
        line += Watch::tr("; ROS publishers asked again for %1 topics (the master listed them, none "
                          "connected), %2 subscribed again, %3 silent now")
                    .arg(again)
                    .arg(ros1->subscriptionsMadeAgain())
                    .arg(ros1->silentSubscriptions());
    if (ros2 && ros2->graph().omitted)
        line += u"; "_s + ros2->graph().omittedText();
    if (ros2 && !ros2->restartText().isEmpty())
        line += u"; "_s + ros2->restartText();
    return line;
}

/// Sets the live session up for a watch and joins ROS 2 when asked; false after saying why not.
bool prepareLive(LiveSession& live, const WatchRequest& request)
{
    // The topic tree's and ROS topics' figures are for views, which a watch has none of (the link
    // monitor reads its own): every drain they cost 7 % of the watch's CPU at 1,000 links, and once
    // a second a fifth of its idle CPU at 10,000 (perf, bench_watch).
    live.setNoTopicViews();
    live.setRosMasterUri(request.masterUri);
    if (request.ros2) {
        if (const Status joined = live.startRos2(*request.ros2); !joined) {
            err(joined.error().toString());
            return false;
        }
    }
    // the DDS process ended (a hostile datagram, a runaway): said as it happens, and started again
    sayRos2Restarts(live.ros2());
    return true;
}

/// The event lines, on stdout and in the --events-jsonl file: an event storm (thousands of links
/// stalling at once) is bounded, the lines past the bucket counted and said once a second.
struct EventLines
{
    QFile* file = nullptr;
    EventThrottle throttle;

    void write(const QJsonObject& o)
    {
        const QByteArray line = QJsonDocument(o).toJson(QJsonDocument::Compact);
        out(QString::fromUtf8(line));
        if (file->isOpen()) {
            file->write(line + '\n');
            file->flush();
        }
    }
    void print(const WatchEvent& e)
    {
        if (throttle.admit(e, wallClockNs()))
            write(e.toJson());
    }
    void sayHeldBack(EventThrottle::Line when)
    {
        if (const auto line = throttle.heldBackLine(wallClockNs(), when))
            write(*line);
    }
};

/// Watches until the time is up or Ctrl+C; events on stdout (and the file), a summary on stderr.
int runWatch(const WatchRequest& request)
{
    std::unique_ptr<WatchMetrics> metrics;
    if (!request.metrics.isEmpty() && !(metrics = serveMetrics(request.metrics, request.labels)))
        return ExitFailed;
    QFile events(request.eventsFile);
    if (!request.eventsFile.isEmpty() && !events.open(QIODevice::WriteOnly | QIODevice::Append)) {
        err(Watch::tr("%1: %2").arg(request.eventsFile, events.errorString()));
        return ExitUsage;
    }
    // With a pipeline the measurement records the run (its stamps and the events); without one the
    // run holds the events alone.
    LiveWatch assembly(request.pipeline ? LiveWatch::Measuring::Yes : LiveWatch::Measuring::No);
    LiveSession& live = *assembly.live();
    if (!prepareLive(live, request))
        return ExitFailed;
    WatchSession& watch = *assembly.watch();
    watch.setRules(request.rules);
    watch.setDiscovering(request.discover);
    static_cast<void>(watch.setConfigs(request.configs)); // the command sets no link limit: it cannot fail
    LinkMonitor* monitor = watch.monitor();
    monitor->setHistoryPoints(0); // the command draws no chart: no history (19 KiB a link)
    if (request.pipeline)
        assembly.measure()->setPipeline(*request.pipeline);
    if (!request.runPath.isEmpty() && !startRecording(request, assembly))
        return ExitUsage;
    RunRecorder* recorder = assembly.recorder();
    bool recordFailed = false;
    QObject::connect(recorder, &RunRecorder::failed, [&recordFailed](const QString& failure) {
        err(Watch::tr("recording stopped: %1").arg(failure));
        recordFailed = true;
    });
    live.connectBroker(request.broker);
    int eventsSeen = 0;
    int alertsSeen = 0;
    QObject::connect(monitor, &LinkMonitor::eventStarted, [&](const WatchEvent& e) {
        ++eventsSeen;
        alertsSeen += e.level == LinkLevel::Alert;
    });
    EventLines lines;
    lines.file = &events;
    QObject::connect(monitor, &LinkMonitor::eventStarted, [&lines](const WatchEvent& e) { lines.print(e); });
    QObject::connect(monitor, &LinkMonitor::eventEnded, [&lines](const WatchEvent& e) { lines.print(e); });
    // The metrics follow the counts four times a second (rates and percentiles change once a second).
    QTimer metricsTimer;
    if (metrics) {
        QObject::connect(&metricsTimer, &QTimer::timeout,
                         [&] { metrics->update(*monitor, live.mqttTopics(), watch.unwatchedLinks()); });
        metricsTimer.start(250);
    }
    err(Watch::tr("watching %n link(s) of %1; Ctrl+C stops", nullptr, monitor->linkCount())
            .arg(request.broker.url));
    SourceCheck sources(
        live, request.ros1 && !request.configs.isEmpty(), [&live] { return qint64(live.mqtt()->received()); },
        Watch::tr("MQTT message"));
    sources.setTopics(mappedMqttTopics(request));
    qint64 watchedMs = 0;
    const int status = CliOutput::runUntil(
        [&](qint64 elapsedMs) -> std::optional<int> {
            watchedMs = elapsedMs;
            if (request.seconds > 0 && elapsedMs >= qint64(request.seconds * 1000))
                return ExitOk;
            return std::nullopt;
        },
        [&](qint64 elapsedMs) {
            lines.sayHeldBack(EventThrottle::Line::Paced);
            sources.check(elapsedMs);
            if (elapsedMs / 1000 % 10 == 0)
                err(progressLine(elapsedMs, watch, live.mqttTopics(), metrics.get(), live.rosMonitor(),
                                 live.ros2()));
        });
    monitor->closeAll(wallClockNs());
    lines.sayHeldBack(EventThrottle::Line::Last);
    printSummary(*monitor, watchedMs, eventsSeen, alertsSeen, lines.throttle.heldBack(), *live.rosMonitor());
    if (recorder->isRecording()) {
        if (const Result<void> stopped = assembly.stopRecording(); !stopped) {
            err(Watch::tr("%1: %2").arg(request.runPath, stopped.error().toString()));
            return ExitFailed;
        }
        err(Watch::tr("events recorded in %1").arg(request.runPath));
    }
    sources.check(0); // how the sources are now, said or not
    // Heard nothing on any graph (ROS 2: nobody else on the domain): a failure, ROS 2 as ROS 1.
    if (const QString nothing = sources.nothingHeard(request.ros1, request.ros2.has_value());
        status == ExitOk && !request.allowEmpty && !nothing.isEmpty()) {
        err(Watch::tr("nothing was watched: %1; --allow-empty accepts that").arg(nothing));
        return ExitFailed;
    }
    return recordFailed ? ExitFailed : status;
}
} // namespace

int runWatchCommand(const QStringList& arguments)
{
    WatchRequest request;
    if (const int status = parseWatch(arguments, &request); status >= 0)
        return status;
    return runWatch(request);
}
