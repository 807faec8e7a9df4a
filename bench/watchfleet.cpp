// SPDX-License-Identifier: MIT
// bench_watch's fleet form (BENCH_FORM=fleet, issue 44): one `bridgescope watch` over a reference
// bridge of many mappings, no window. bench_loadgen publishes round-robin on every MQTT topic at a
// total rate (default 10,000 links at 5,000 msg/s: each link every 2 s), the reference bridge
// (`bridgescope bridge`) carries them to ROS, and mosquitto_sub receives the same MQTT traffic in
// the same run: the peer of the watch's CPU per message. It measures, with /metrics as the only
// window into the watch (scraped every BENCH_SCRAPE_S, as a Prometheus would):
//   - how long until the watch lists every link;
//   - its idle CPU on links that never heard anything;
//   - how long after the first message every link's destination has counted: the reference bridge
//     advertises a link's ROS topic at its first message, the watch subscribes to it then;
//   - its CPU per message against mosquitto_sub's, RSS before, under and after the load;
//   - every link in /metrics, the scrape's size and time, the event lines it wrote;
//   - its idle CPU right after the load, and once the links are past every window (settled).
//
//   BENCH_FORM=fleet build-release/bench/bench_watch     (BENCH_LINKS, BENCH_RATE, BENCH_SECONDS,
//                                                         BENCH_IDLE_S, BENCH_SETTLE_S, BENCH_SCRAPE_S)
//   BENCH_WATCH_BINARY=OTHER/bridgescope ...             the watch of another build (an A/B; the
//                                                         reference bridge stays this build's)
//   BENCH_WATCH_LOG=FILE ...                             the watch's standard error (progress lines)
//   BENCH_ROS_PEER=1 ...                                 bench_rossub subscribes to every link's ROS
//                                                         topic beside the watch, as it does: the peer
//                                                         of its time until every link is live and of
//                                                         its ROS side's cost (the bridge then sends
//                                                         every message twice: not for the other rows)
//   BENCH_ROS_PEER=instead ...                           bench_rossub in the watch's place, nothing else
//                                                         changed: how long a bare roscpp subscriber
//                                                         takes until it has heard every topic
#include "watchfleet.h"

#include "benchutil.h"
#include "peakrss.h"
#include "ros/rosmasterapi.h"
#include "testservers.h"

#include <map>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using namespace Qt::StringLiterals;

QString fleetTopic(int i)
{
    return u"fleet/vehicle_%1/sensor_%2"_s.arg(i / 100, 3, 10, QChar(u'0')).arg(i % 100, 2, 10, QChar(u'0'));
}

namespace {

/// What one scrape of the watch says of its links.
struct Scrape
{
    QByteArray body;
    double ms = 0;
    int links = 0; ///< links with a destination series
    int live = 0; ///< of which the destination counted a message
    double messages = 0; ///< both sides, all links

    static Scrape of(quint16 port)
    {
        Scrape s;
        QElapsedTimer t;
        t.start();
        s.body = TestServers::httpGet(port, u"/metrics"_s);
        s.ms = double(t.nsecsElapsed()) / 1e6;
        for (const QByteArray& line : s.body.split('\n')) {
            if (!line.startsWith("bridgescope_link_messages_total{"))
                continue;
            const double v = line.mid(line.lastIndexOf(' ') + 1).toDouble();
            s.messages += v;
            if (line.contains("side=\"destination\"")) {
                ++s.links;
                s.live += v > 0 ? 1 : 0;
            }
        }
        return s;
    }
};

/// The children and the figures they give.
struct Fleet
{
    TestServers servers;
    QString program;
    QString watchProgram; ///< BENCH_WATCH_BINARY, else `program`
    QString configPath;
    quint16 metricsPort = TestServers::freePort();
    QProcess bridge;
    QProcess watch;
    QProcess sub;
    QProcess loadgen;
    QProcess rosPeer; ///< BENCH_ROS_PEER: a bare roscpp subscriber to every link's topic
    quint64 rosPeerReceived = 0;
    quint64 rosPeerHeard = 0;
    quint64 rosPeerTopics = 0;
    QElapsedTimer load; ///< from the load's start
    double rosPeerAllHeardS = -1; ///< when the peer had heard every topic, from the load's start
    double rosPeer99HeardS = -1; ///< when it had heard 99 % of them
    quint64 subLines = 0;
    quint64 eventBytes = 0;
    quint64 eventLines = 0;
    std::map<QString, int> eventReasons; ///< "start stall", "end stall", "held_back", ...

    double watchCpu() const { return Bench::processCpuSeconds(watch.processId()); }
    double subCpu() const { return Bench::processCpuSeconds(sub.processId()); }
    double rosPeerCpu() const { return Bench::processCpuSeconds(rosPeer.processId()); }
    double watchRssMiB() const { return double(childKb(watch.processId(), "VmRSS:")) / 1024; }
    double watchPeakMiB() const { return double(PeakRss::of(watch.processId())) / (1024 * 1024); }

    /// VmRSS of a child (PeakRss gives its VmHWM; Bench::statusKb this process's own).
    static long long childKb(qint64 pid, const char* field)
    {
        QFile f(u"/proc/%1/status"_s.arg(pid));
        if (!f.open(QIODevice::ReadOnly))
            return -1;
        for (const QByteArray& line : f.readAll().split('\n'))
            if (line.startsWith(field))
                return line.mid(qsizetype(qstrlen(field))).trimmed().split(' ').first().toLongLong();
        return -1;
    }

    bool start(int links);
    bool startRosPeer(int links);
    /// CPU % of one core the watch takes over `seconds`, nothing else asked of it.
    double idleCpuPercent(int seconds)
    {
        const double c0 = watchCpu();
        QTest::qWait(seconds * 1000); // the span measured
        return 100 * (watchCpu() - c0) / seconds;
    }
    void stop()
    {
        for (QProcess* p : {&loadgen, &watch, &bridge, &sub, &rosPeer}) {
            p->terminate();
            p->waitForFinished(10000);
        }
    }
};

bool Fleet::start(int links)
{
    if (!servers.startMosquitto(
            TestMosquittoOptions {true, {}, {}, {}, {}, false, u"max_queued_messages 0\n"_s})
        || !servers.startRosMaster()) {
        std::fprintf(stderr, "cannot start the servers: %s\n", qPrintable(servers.errorString()));
        return false;
    }
    QString config
        = u"broker:\n  host: 127.0.0.1\n  port: %1\nclient:\n  id: fleet_bridge\nbridge:\n  mqtt2ros:\n"_s
              .arg(servers.mosquittoPort());
    for (int i = 0; i < links; ++i)
        config += u"    - {mqtt_topic: %1, ros_topic: /%1, primitive: true}\n"_s.arg(fleetTopic(i));
    configPath = servers.tempPath() + u"/fleet.yaml"_s;
    QFile f(configPath);
    if (!f.open(QIODevice::WriteOnly) || f.write(config.toUtf8()) < 0)
        return false;
    f.close();
    bridge.setProcessEnvironment(servers.rosEnvironment());
    bridge.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    bridge.start(program, {u"bridge"_s, configPath});
    watch.setProcessEnvironment(servers.rosEnvironment());
    if (const QString log = qEnvironmentVariable("BENCH_WATCH_LOG"); !log.isEmpty())
        watch.setStandardErrorFile(log); // its progress lines, every 10 s
    QObject::connect(&watch, &QProcess::readyReadStandardOutput, [this] {
        const QByteArray out = watch.readAllStandardOutput();
        eventBytes += quint64(out.size());
        eventLines += quint64(out.count('\n'));
        for (const QByteArray& line : out.split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            const QString kind = o.value(u"event"_s).toString();
            for (const QJsonValue& r : o.value(u"reasons"_s).toArray())
                ++eventReasons[kind + u' ' + r.toString()];
            if (kind == u"held_back"_s)
                ++eventReasons[kind];
        }
    });
    const QByteArray peer = qgetenv("BENCH_ROS_PEER");
    if (peer != "instead")
        watch.start(watchProgram,
                    {u"watch"_s, configPath, u"--ros-master"_s, servers.rosMasterUri(), u"--metrics"_s,
                     u"127.0.0.1:%1"_s.arg(metricsPort)});
    QObject::connect(&sub, &QProcess::readyReadStandardOutput,
                     [this] { subLines += quint64(sub.readAllStandardOutput().count('\n')); });
    sub.start(u"mosquitto_sub"_s,
              {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(servers.mosquittoPort()), u"-t"_s,
               u"fleet/#"_s, u"-F"_s, u"%t"_s});
    return bridge.waitForStarted() && (peer == "instead" || watch.waitForStarted()) && sub.waitForStarted()
        && (peer.isEmpty() || startRosPeer(links));
}

bool Fleet::startRosPeer(int links)
{
    rosPeerTopics = quint64(links);
    QFile topics(servers.tempPath() + u"/fleet-topics.txt"_s);
    if (!topics.open(QIODevice::WriteOnly))
        return false;
    for (int i = 0; i < links; ++i)
        topics.write(u"/%1\n"_s.arg(fleetTopic(i)).toUtf8());
    topics.close();
    QObject::connect(&rosPeer, &QProcess::readyReadStandardOutput, [this] {
        while (rosPeer.canReadLine()) {
            const QList<QByteArray> f = rosPeer.readLine().trimmed().split(' ');
            if (f.size() == 2) {
                rosPeerReceived = f[0].toULongLong();
                rosPeerHeard = f[1].toULongLong();
                const double nowS = load.isValid() ? double(load.elapsed()) / 1000 : -1;
                if (rosPeer99HeardS < 0 && rosPeerHeard * 100 >= rosPeerTopics * 99)
                    rosPeer99HeardS = nowS;
                if (rosPeerAllHeardS < 0 && rosPeerHeard >= rosPeerTopics)
                    rosPeerAllHeardS = nowS;
            }
        }
    });
    rosPeer.setProcessEnvironment(servers.rosEnvironment());
    rosPeer.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    rosPeer.start(QCoreApplication::applicationDirPath() + u"/bench_rossub"_s,
                  {servers.rosMasterUri(), u"/fleet/"_s, u"0"_s, QString::number(links), topics.fileName()});
    return rosPeer.waitForStarted();
}

/// Seconds until the master lists a subscriber on every link's ROS topic (-1: not within
/// `timeoutS`): the watch's subscriptions are made (the bridge advertises at a link's first message).
double untilSubscribed(const Fleet& fleet, int links, int timeoutS)
{
    const RosMasterApi master(fleet.servers.rosMasterUri());
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutS * 1000LL) {
        int subscribed = 0;
        if (const auto graph = master.graph(10000))
            for (const TopicInfo& topic : graph->topics)
                subscribed += topic.name.startsWith(u"/fleet/"_s) && !topic.subscribers.isEmpty() ? 1 : 0;
        if (subscribed >= links)
            return double(t.elapsed()) / 1000;
        QTest::qWait(1000); // the master's pace: a graph of 10,000 topics takes it a while
    }
    return -1;
}

/// Scrapes every `everyS` seconds until `done` says so or `timeoutS` passes; the seconds it took (-1: never).
double scrapeUntil(Fleet& fleet, int everyS, int timeoutS, const std::function<bool(const Scrape&)>& done,
                   Scrape* last = nullptr)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutS * 1000LL) {
        const Scrape s = Scrape::of(fleet.metricsPort);
        if (last)
            *last = s;
        if (done(s))
            return double(t.elapsed()) / 1000;
        QTest::qWait(everyS * 1000); // the scrape interval, as a Prometheus would
    }
    return -1;
}
/// BENCH_ROS_PEER=instead: the same bridge, load and master, bench_rossub in the watch's place.
int runRosPeerInstead(Fleet& fleet, int links, int rate, int seconds)
{
    const double subscribedS = untilSubscribed(fleet, links, 300);
    QTest::qWait(2000); // the last subscriptions' connections, as for the watch
    fleet.loadgen.start(QCoreApplication::applicationDirPath() + u"/bench_loadgen"_s,
                        {fleet.servers.brokerUrl(), QString::number(links), QString::number(rate),
                         QString::number(seconds), u"32"_s});
    fleet.load.start();
    QTest::qWaitFor([&] { return fleet.rosPeerAllHeardS >= 0; }, (seconds - 30) * 1000);
    const double cpu0 = fleet.rosPeerCpu();
    const quint64 received0 = fleet.rosPeerReceived;
    const qint64 spanStart = fleet.load.elapsed();
    QTest::qWaitFor([] { return false; }, int(std::max<qint64>(0, (seconds - 3) * 1000LL - spanStart)));
    const double cpu = fleet.rosPeerCpu() - cpu0;
    const quint64 received = fleet.rosPeerReceived - received0;
    const double spanS = double(fleet.load.elapsed() - spanStart) / 1000;
    fleet.loadgen.waitForFinished(20000);
    const double idle0 = fleet.rosPeerCpu();
    QTest::qWait(20000); // the span measured: roscpp at rest with every connection open
    const double idle = 100 * (fleet.rosPeerCpu() - idle0) / 20;
    Bench::header("value");
    Bench::row(u"seconds until the master lists bench_rossub's subscription on every topic"_s, subscribedS);
    Bench::row(u"peer: seconds from the first message until bench_rossub heard every topic"_s,
               fleet.rosPeerAllHeardS,
               u"%1 of %2 topics heard at the load's end"_s.arg(fleet.rosPeerHeard).arg(links));
    Bench::row(u"peer: seconds from the first message until bench_rossub heard 99 % of the topics"_s,
               fleet.rosPeer99HeardS);
    Bench::row(u"peer: bench_rossub CPU per message after that (us)"_s,
               received ? cpu / double(received) * 1e6 : 0,
               u"%1 messages over %2 s"_s.arg(received).arg(spanS, 0, 'f', 0));
    Bench::row(u"peer: bench_rossub idle CPU after the load (% of a core)"_s, idle,
               u"%1 topics connected, nothing sent"_s.arg(fleet.rosPeerHeard));
    fleet.stop();
    return 0;
}
} // namespace

int runWatchFleet(const QString& program)
{
    const int links = Bench::envInt("BENCH_LINKS", 10000);
    const int rate = Bench::envInt("BENCH_RATE", 5000);
    const int seconds = Bench::envInt("BENCH_SECONDS", 150);
    const int idleS = Bench::envInt("BENCH_IDLE_S", 20);
    const int settleS = Bench::envInt("BENCH_SETTLE_S", 70, 0);
    const int scrapeS = Bench::envInt("BENCH_SCRAPE_S", 5);
    Fleet fleet;
    fleet.program = program;
    fleet.watchProgram = qEnvironmentVariable("BENCH_WATCH_BINARY", program);
    if (!fleet.start(links))
        return 1;
    if (qgetenv("BENCH_ROS_PEER") == "instead")
        return runRosPeerInstead(fleet, links, rate, seconds);
    std::printf("bench_watch fleet: %d links, %d msg/s in all (each link every %.1f s), %d s of load\n"
                "watch: %s\n\n",
                links, rate, double(links) / rate, seconds, qPrintable(fleet.watchProgram));
    const double listedS = scrapeUntil(fleet, 1, 60, [&](const Scrape& s) { return s.links >= links; });
    const double subscribedS = untilSubscribed(fleet, links, 300);
    QTest::qWait(2000); // the last subscriptions' connections
    const double rssIdle = fleet.watchRssMiB();
    const double idleUnheard = fleet.idleCpuPercent(idleS);

    fleet.loadgen.start(QCoreApplication::applicationDirPath() + u"/bench_loadgen"_s,
                        {fleet.servers.brokerUrl(), QString::number(links), QString::number(rate),
                         QString::number(seconds), u"32"_s});
    QElapsedTimer& load = fleet.load;
    load.start();
    Scrape atLive;
    double live99S = -1;
    const double liveS = scrapeUntil(
        fleet, scrapeS, seconds - 30,
        [&](const Scrape& s) {
            if (live99S < 0 && s.live * 100 >= links * 99)
                live99S = double(load.elapsed()) / 1000;
            return s.live >= links;
        },
        &atLive);
    // The steady span: from every link live (or the ramp's end) to the load's last seconds.
    const double cpu0 = fleet.watchCpu(), sub0 = fleet.subCpu(), peer0 = fleet.rosPeerCpu();
    const quint64 lines0 = fleet.subLines, peerReceived0 = fleet.rosPeerReceived;
    const qint64 spanStart = load.elapsed();
    const double counted0 = atLive.messages;
    while (load.elapsed() < (seconds - 3) * 1000LL) // the load's end, but for its last seconds
        QTest::qWait(scrapeS * 1000); // a scrape interval
    const double watchCpu = fleet.watchCpu() - cpu0, subCpu = fleet.subCpu() - sub0;
    const double peerCpu = fleet.rosPeerCpu() - peer0;
    const quint64 peerReceived = fleet.rosPeerReceived - peerReceived0;
    const double spanS = double(load.elapsed() - spanStart) / 1000;
    QTest::qWait(200); // mosquitto_sub's last lines of the span
    const quint64 subMessages = fleet.subLines - lines0;
    Scrape loaded = Scrape::of(fleet.metricsPort);
    loaded.messages -= counted0; // what the watch counted in the span (the scrapes bound it)
    const double rssLoaded = fleet.watchRssMiB();
    fleet.loadgen.waitForFinished(20000);
    const double idleAfter = fleet.idleCpuPercent(idleS);
    if (settleS > 0)
        QTest::qWait(settleS * 1000); // past every window of the links (the latency window: 60 s)
    const double idleSettled = settleS > 0 ? fleet.idleCpuPercent(idleS) : qQNaN();
    const Scrape last = Scrape::of(fleet.metricsPort);

    Bench::header("value");
    Bench::row(u"seconds until /metrics lists every link"_s, listedS);
    Bench::row(u"  then until the master lists the watch's subscription on every link"_s, subscribedS);
    Bench::row(u"watch RSS, links never heard (MiB)"_s, rssIdle,
               u"%1 kB a link"_s.arg(rssIdle * 1024 / links, 0, 'f', 1));
    Bench::row(u"watch idle CPU, links never heard (% of a core)"_s, idleUnheard, u"goal <= 2 %"_s);
    Bench::row(
        u"seconds from the first message until every link is live"_s, liveS,
        u"%1 of %2 links live at the last scrape (goal: all within 60 s)"_s.arg(atLive.live).arg(links));
    Bench::row(u"  seconds until 99 % of the links are live"_s, live99S,
               u"scraped every %1 s"_s.arg(scrapeS));
    if (fleet.rosPeer.processId() > 0) {
        Bench::row(u"peer: seconds from the first message until bench_rossub heard every topic"_s,
                   fleet.rosPeerAllHeardS,
                   u"%1 of %2 topics heard at the load's end"_s.arg(fleet.rosPeerHeard).arg(links));
        Bench::row(u"peer: bench_rossub CPU per message in the steady span (us)"_s,
                   peerReceived ? peerCpu / double(peerReceived) * 1e6 : 0,
                   u"%1 messages"_s.arg(peerReceived));
    }
    Bench::row(u"peer: messages mosquitto_sub received"_s, double(subMessages));
    Bench::row(u"messages the watch counted (both ends) in the steady span"_s, loaded.messages,
               u"%1 s, from every link live to the load's end"_s.arg(spanS, 0, 'f', 0));
    const double subPer = subMessages ? subCpu / double(subMessages) * 1e6 : 0;
    const double watchPer = loaded.messages > 0 ? watchCpu / loaded.messages * 1e6 : 0;
    Bench::row(u"peer: mosquitto_sub CPU per message (us)"_s, subPer);
    Bench::row(u"watch CPU per message (us)"_s, watchPer,
               u"%1x mosquitto_sub (goal <= 2x); %2 % of a core over %3 s"_s
                   .arg(subPer > 0 ? watchPer / subPer : 0, 0, 'f', 2)
                   .arg(100 * watchCpu / spanS, 0, 'f', 1)
                   .arg(spanS, 0, 'f', 0));
    Bench::row(u"watch RSS under the load (MiB)"_s, rssLoaded,
               u"%1 kB a link; peak %2 MiB"_s.arg(rssLoaded * 1024 / links, 0, 'f', 1)
                   .arg(fleet.watchPeakMiB(), 0, 'f', 0));
    Bench::row(u"links in /metrics at the end of the load"_s, loaded.links, u"of %1"_s.arg(links));
    Bench::row(u"/metrics scrape under the load (ms)"_s, loaded.ms,
               u"%1 kB"_s.arg(loaded.body.size() / 1024));
    QStringList reasons;
    for (const auto& [what, n] : fleet.eventReasons)
        reasons << u"%1 %2"_s.arg(n).arg(what);
    Bench::row(u"event lines the watch wrote"_s, double(fleet.eventLines),
               u"%1 kB: %2"_s.arg(double(fleet.eventBytes) / 1024, 0, 'f', 0).arg(reasons.join(u", "_s)));
    Bench::row(u"watch idle CPU right after the load (%)"_s, idleAfter);
    if (settleS > 0)
        Bench::row(u"watch idle CPU %1 s later, past every window (%)"_s.arg(settleS), idleSettled,
                   u"goal <= 2 %"_s);
    Bench::row(u"/metrics scrape idle (ms)"_s, last.ms, u"%1 links"_s.arg(last.links));
    Bench::gate("watchfleet_cpu_per_message_vs_mosquitto_sub", subPer > 0 ? watchPer / subPer : 0);
    Bench::gate("watchfleet_seconds_to_every_link_live", liveS < 0 ? 1e9 : liveS);
    Bench::gate("watchfleet_seconds_to_99_percent_live", live99S < 0 ? 1e9 : live99S);
    Bench::gate("watchfleet_links_missing_from_metrics", double(links - loaded.links));
    Bench::gate("watchfleet_idle_cpu_percent_after_load", idleAfter);
    if (settleS > 0)
        Bench::gate("watchfleet_idle_cpu_percent_settled", idleSettled);
    fleet.stop();
    return 0;
}
