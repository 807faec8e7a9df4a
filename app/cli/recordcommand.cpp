// SPDX-License-Identifier: MIT
#include "recordcommand.h"

#include "app/cli/clioutput.h"
#include "app/cli/rosoptions.h"
#include "app/cli/sourcecheck.h"
#include "files/regularfile.h"
#include "yaml/secrets.h"
#include "yaml/yamllimits.h"
#include "latency/latencywarnings.h"
#include "record/runrecorder.h"
#include "ros/rosmasterapi.h"
#include "session/liveparts.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <algorithm>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class Record
{
    Q_DECLARE_TR_FUNCTIONS(RecordCommand)
};

/// What the command line asks for.
struct RecordRequest
{
    Pipeline pipeline;
    MqttProfile profile;
    QString masterUri;
    bool ros1 = true;
    std::optional<Ros2Options> ros2; ///< set: stamps from this ROS 2 domain too
    QString runPath;
    RunInfo info;
    qint64 samples = 0; ///< 0: no limit
    double seconds = 0; ///< 0: no limit
    bool allowEmpty = false; ///< a run without any stamp is a success
};

/// The run's name, notes and the bridge config kept with it; false after saying why.
bool readRunInfo(const QCommandLineParser& parser, const QCommandLineOption& name,
                 const QCommandLineOption& notes, const QCommandLineOption& config, RecordRequest* request)
{
    RunInfo& info = request->info;
    info.name = parser.isSet(name) ? parser.value(name) : QFileInfo(request->runPath).completeBaseName();
    info.notes = parser.value(notes);
    if (!parser.isSet(config))
        return true;
    const Result<QByteArray> yaml = RegularFile::readHead(parser.value(config), YamlLimits::maxBytes + 1);
    if (!yaml) {
        err(Record::tr("%1: %2").arg(parser.value(config), yaml.error().toString()));
        return false;
    }
    info.bridgeConfigPath = QFileInfo(parser.value(config)).absoluteFilePath();
    info.bridgeConfig = *yaml;
    bool parsed = true;
    Secrets::redactYaml(info.bridgeConfig, nullptr, &parsed);
    if (!parsed)
        err(Record::tr("%1 is not YAML: the run keeps no copy of it (its credentials could not be found)")
                .arg(parser.value(config)));
    return true;
}

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseRecord(const QStringList& arguments, RecordRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption pipeline(
        u"pipeline"_s, Record::tr("Pipeline YAML (the suite's metrics-logger file)."), u"PIPE.yaml"_s);
    const QCommandLineOption broker(u"broker"_s, Record::tr("Broker URL (default tcp://localhost:1883)."),
                                    u"URL"_s, u"tcp://localhost:1883"_s);
    const QCommandLineOption master(u"ros-master"_s, Record::tr("ROS master URI (default $ROS_MASTER_URI)."),
                                    u"URI"_s, RosMasterApi::defaultMasterUri());
    const QCommandLineOption samples(u"samples"_s, Record::tr("Stop after N complete samples."), u"N"_s);
    const QCommandLineOption seconds(u"seconds"_s, Record::tr("Stop after S seconds."), u"S"_s);
    const QCommandLineOption output({u"o"_s, u"output"_s},
                                    Record::tr("The run file to write (never overwritten)."), u"RUN"_s);
    const QCommandLineOption name(u"name"_s, Record::tr("Name of the run (default: the file's name)."),
                                  u"NAME"_s);
    const QCommandLineOption notes(u"notes"_s, Record::tr("Notes to keep with the run."), u"TEXT"_s);
    const QCommandLineOption config(u"config"_s, Record::tr("The bridge config in use, kept with the run."),
                                    u"BRIDGE.yaml"_s);
    const QCommandLineOption allowEmpty(
        u"allow-empty"_s, Record::tr("Exit 0 even when no stamp was recorded (an empty run on purpose)."));
    const QCommandLineOption oneClock(
        u"one-clock"_s, Record::tr("Every stamp comes from one clock (one machine): each direction's own "
                                   "one-way latency, no clock offset (kept with the run)."));
    parser.addOptions(
        {pipeline, broker, master, samples, seconds, output, name, notes, config, allowEmpty, oneClock});
    RosOptions ros;
    ros.addTo(parser);
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope record"_s,
        Record::tr(
            "Records a measurement run: every stamp of the pipeline from ROS 1, ROS 2 (--ros 2 or both) and "
            "MQTT, committed to the run "
            "file at least every 200 ms, until N samples are complete, S seconds passed, or Ctrl+C. A broker "
            "or master that cannot be reached, or no stamp at all, is said within 5 s; it keeps trying.\n"
            "Exit status: 0 recorded, 1 nothing recorded (without --allow-empty) or the run file could not "
            "be written, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    if (!parser.isSet(pipeline) || !parser.isSet(output)) {
        err(Record::tr("record needs --pipeline and -o; see bridgescope record --help"));
        return ExitUsage;
    }
    bool ok = true;
    request->samples = parser.isSet(samples) ? parser.value(samples).toLongLong(&ok) : 0;
    if (!ok || request->samples < 0) {
        err(Record::tr("--samples takes a number of samples"));
        return ExitUsage;
    }
    if (parser.isSet(seconds) && !CliOutput::readSeconds(parser.value(seconds), &request->seconds)) {
        err(CliOutput::secondsError());
        return ExitUsage;
    }
    request->allowEmpty = parser.isSet(allowEmpty);
    if (const Status read = ros.read(parser); !read) {
        err(read.error().toString());
        return ExitUsage;
    }
    for (const QString& line : ros.notes())
        err(line);
    request->ros1 = ros.ros1;
    request->ros2 = ros.ros2 ? std::optional<Ros2Options>(ros.ros2Options) : std::nullopt;
    const Result<Pipeline> pipe = Pipeline::readFile(parser.value(pipeline));
    request->profile = MqttProfile::fromUrl(parser.value(broker));
    if (!pipe) {
        err(pipe.error().toString());
        return ExitUsage;
    }
    if (const Status valid = request->profile.validate(); !valid) {
        err(valid.error().toString());
        return ExitUsage;
    }
    request->pipeline = *pipe;
    if (parser.isSet(oneClock))
        request->pipeline.setOneClock(true);
    request->masterUri = parser.value(master);
    request->runPath = parser.value(output);
    if (!readRunInfo(parser, name, notes, config, request))
        return ExitUsage;
    if (QFileInfo::exists(request->runPath)) { // before any connection is made
        err(Record::tr("%1 exists already; a run is never overwritten").arg(request->runPath));
        return ExitUsage;
    }
    return -1;
}

/// The malformed stamps so far, as the window's Measure page says them: "3 malformed stamps: 2 on
/// /a, 1 on b (last: ...)"; empty when there were none.
QString malformedLine(const MeasureSession& measure)
{
    const quint64 bad = measure.malformedStamps();
    if (bad == 0)
        return {};
    const auto [worst, topics] = measure.worstMalformedTopics(3);
    QStringList names;
    for (const auto& [count, topic] : worst)
        names << Record::tr("%1 on %2").arg(count).arg(topic);
    if (topics > qsizetype(worst.size()))
        names << Record::tr("%n more topic(s)", nullptr, int(topics - qsizetype(worst.size())));
    return Record::tr("%1 malformed stamps: %2 (last: %3)").arg(bad).arg(names.join(u", "), measure.lastStampError());
}

/// Records until enough samples, the time is up, Ctrl+C or a failed write; progress on stderr.
int runRecord(const RecordRequest& request)
{
    LiveSession live;
    live.setRosMasterUri(request.masterUri);
    live.connectBroker(request.profile);
    if (request.ros2) {
        if (const Status joined = live.startRos2(*request.ros2); !joined) {
            err(joined.error().toString());
            return ExitFailed;
        }
    }
    sayRos2Restarts(live.ros2());
    MeasureSession measure(LiveParts::measure(&live));
    measure.setRos1(request.ros1);
    measure.setPipeline(request.pipeline);
    if (const Result<void> started = measure.startRecording(request.runPath, request.info); !started) {
        err(started.error().toString());
        return ExitUsage;
    }
    QObject::connect(&measure, &MeasureSession::recordingFailed, [](const QString& failure) {
        err(Record::tr("recording failed: %1").arg(failure));
        QCoreApplication::exit(ExitFailed);
    });
    const LatencyEngine& e = measure.engine();
    // The master matters when ROS 1 is asked for and the pipeline has a ROS topic (MQTT topics
    // have no leading '/').
    const bool needsMaster = request.ros1 && std::any_of(request.pipeline.topics().cbegin(), request.pipeline.topics().cend(),
                                         [](const QString& t) { return t.startsWith(u'/'); });
    SourceCheck sources(
        live, needsMaster, [&measure] { return measure.recorder()->committedStamps(); },
        Record::tr("stamp"));
    sources.setTopics(request.pipeline.topics());
    const int status = CliOutput::runUntil(
        [&](qint64 elapsedMs) -> std::optional<int> {
            const bool enough = request.samples > 0 && e.samples() >= request.samples;
            const bool late = request.seconds > 0 && elapsedMs >= qint64(request.seconds * 1000);
            return enough || late ? std::optional<int>(ExitOk) : std::nullopt;
        },
        [&](qint64 elapsedMs) {
            sources.check(elapsedMs);
            // Committed first: after a crash the file holds at least what this line says.
            const QString bad = malformedLine(measure);
            err(Record::tr("%1 s: %2 stamps committed, %3 complete samples, %4 dropped, %5 waiting")
                    .arg(elapsedMs / 1000)
                    .arg(measure.recorder()->committedStamps())
                    .arg(e.samples())
                    .arg(e.counters().dropped())
                    .arg(e.pending())
                + (bad.isEmpty() ? QString() : u"; "_s + bad));
        });
    if (status != ExitOk)
        return status;
    live.drainNow(); // what arrived in the last moment
    const qint64 complete = e.samples();
    if (const Result<void> stopped = measure.stopRecording(); !stopped) {
        err(Record::tr("recording failed: %1").arg(stopped.error().toString()));
        return ExitFailed;
    }
    const qint64 stamps = measure.recorder()->committedStamps();
    out(Record::tr("%1: %2 complete samples, %3 stamps").arg(request.runPath).arg(complete).arg(stamps));
    // The hosts' clocks as measured (kept in the run), or which host's clock service did not answer.
    if (const QString clocks = measure.clocksText(); !clocks.isEmpty())
        err(clocks);
    const QList<LatencyWarning> warnings = LatencyWarnings::of(e);
    for (const QString& line : LatencyWarnings::lines(warnings))
        err(Record::tr("not a measurement: %1").arg(line));
    if (!warnings.isEmpty())
        err(LatencyWarnings::fixOnCommandLine());
    if (const QString bad = malformedLine(measure); !bad.isEmpty())
        err(bad); // not recorded: the run holds only the stamps that read
    if (stamps == 0 && !request.allowEmpty) {
        const QString nothing = sources.nothingHeard(request.ros1, request.ros2.has_value());
        err(Record::tr("nothing was recorded (%1); --allow-empty accepts an empty run")
                .arg(nothing.isEmpty() ? Record::tr("no stamp of the pipeline's topics arrived") : nothing));
        return ExitFailed;
    }
    return ExitOk;
}
} // namespace

int runRecordCommand(const QStringList& arguments)
{
    RecordRequest request;
    if (const int status = parseRecord(arguments, &request); status >= 0)
        return status;
    return runRecord(request);
}
