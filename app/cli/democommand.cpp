// SPDX-License-Identifier: MIT
#include "democommand.h"

#include "app/cli/clioutput.h"
#include "yaml/secrets.h"
#include "demo/demolab.h"
#include "record/runrecorder.h"
#include "report/report.h"
#include "report/reportformats.h"
#include "ros/demonodes.h"
#include "bridge/ros2demonodes.h"
#include "session/liveparts.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QTemporaryDir>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class Demo
{
    Q_DECLARE_TR_FUNCTIONS(DemoCommand)
};

/// What the command line asks for.
struct DemoRequest
{
    DemoLab::Options lab;
    double seconds = 0; ///< 0: until Ctrl+C
    ReportFormats::Format summary = ReportFormats::Format::Markdown;
    QString runPath; ///< empty: a scratch file
};

/// --ros and --ros-domain into `lab`; false after saying what is wrong.
bool readRos(const QString& ros, const QString& domain, DemoLab::Options* lab)
{
    if (ros != u"1"_s && ros != u"2"_s) {
        err(Demo::tr("--ros takes 1 or 2"));
        return false;
    }
    lab->ros = ros.toInt();
    if (domain.isEmpty())
        return true;
    bool ok = false;
    lab->rosDomain = domain.toInt(&ok);
    if (!ok || lab->rosDomain < 0 || lab->rosDomain > Ros2Options::kMaxDomain) {
        err(Demo::tr("--ros-domain takes a domain id from 0 to %1").arg(Ros2Options::kMaxDomain));
        return false;
    }
    return true;
}

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseDemo(const QStringList& arguments, DemoRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption seconds(u"seconds"_s, Demo::tr("Run for N seconds (default: until Ctrl+C)."),
                                     u"N"_s);
    const QCommandLineOption output({u"o"_s, u"output"_s}, Demo::tr("Keep the recording as this run file."),
                                    u"RUN"_s);
    const QCommandLineOption format(u"format"_s, Demo::tr("Summary at the end: md (default) or json."),
                                    u"FORMAT"_s, u"md"_s);
    const QCommandLineOption size(u"size"_s, Demo::tr("Point cloud size in bytes (default 180000)."),
                                  u"BYTES"_s, u"180000"_s);
    const QCommandLineOption broker(u"broker"_s, Demo::tr("Use this broker instead of a private mosquitto."),
                                    u"URL"_s);
    const QCommandLineOption master(
        u"ros-master"_s, Demo::tr("Use this ROS master instead of a private rosmaster."), u"URI"_s);
    const QCommandLineOption ros(u"ros"_s,
                                 Demo::tr("1: ROS 1 nodes around a private rosmaster (default); 2: DDS nodes "
                                          "and ROS 2 bridges on a free private domain on 127.0.0.1."),
                                 u"1|2"_s, u"1"_s);
    const QCommandLineOption domain(u"ros-domain"_s, Demo::tr("With --ros 2: this domain instead of a free one."),
                                    u"ID"_s);
    const QCommandLineOption cloudHost(
        u"cloud-host"_s,
        Demo::tr("Run the cloud's bridge, object detection and clock service on this host over OpenSSH "
                 "(ssh://user@host[:port]; keys or an agent, never a password)."),
        u"URL"_s);
    const QCommandLineOption cloudProgram(
        u"cloud-program"_s, Demo::tr("With --cloud-host: bridgescope's path there (default: this one's)."),
        u"PATH"_s);
    parser.addOptions({seconds, output, format, size, broker, master, ros, domain, cloudHost, cloudProgram});
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope demo"_s,
        Demo::tr(
            "Runs the demo lab without a window: a private mosquitto and rosmaster, a vehicle and a cloud "
            "reference bridge, a 0.18 MB point cloud at 10 Hz, a 40 ms object detection in the cloud whose "
            "clock is 35 ms ahead, and stamps at every component; records every stamp and prints the "
            "latency report at the end. Everything it started stops with it, on this host and on the "
            "cloud's (--cloud-host).\n"
            "Exit status: 0 samples measured, 1 the lab failed or measured nothing, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    bool ok = true;
    if (parser.isSet(seconds) && !CliOutput::readSeconds(parser.value(seconds), &request->seconds)) {
        err(CliOutput::secondsError());
        return ExitUsage;
    }
    if (!ReportFormats::parse(parser.value(format), &request->summary)
        || (request->summary != ReportFormats::Format::Markdown
            && request->summary != ReportFormats::Format::Json)) {
        err(Demo::tr("--format takes md or json"));
        return ExitUsage;
    }
    request->lab.payloadBytes = parser.value(size).toInt(&ok);
    if (!ok || request->lab.payloadBytes < 16) {
        err(Demo::tr("--size takes a number of bytes (at least 16)"));
        return ExitUsage;
    }
    request->lab.brokerUrl = parser.value(broker);
    request->lab.rosMasterUri = parser.value(master);
    if (!readRos(parser.value(ros), parser.isSet(domain) ? parser.value(domain) : QString(), &request->lab))
        return ExitUsage;
    if (parser.isSet(cloudHost)) {
        const Result<RemoteHost> host = RemoteHost::parse(parser.value(cloudHost));
        if (!host) {
            err(Demo::tr("--cloud-host: %1").arg(host.error().toString()));
            return ExitUsage;
        }
        request->lab.cloudHost
            = DemoLab::FarHost {*host, parser.value(cloudProgram), SshOptions::fromEnvironment()};
    } else if (parser.isSet(cloudProgram)) {
        err(Demo::tr("--cloud-program needs --cloud-host"));
        return ExitUsage;
    }
    request->runPath = parser.value(output);
    if (!request->runPath.isEmpty() && QFileInfo::exists(request->runPath)) {
        err(Demo::tr("%1 exists already; a run is never overwritten").arg(request->runPath));
        return ExitUsage;
    }
    return -1;
}

/// Starts the lab, records its stamps to `runPath` until the end, stops the lab. The exit status.
int runDemo(const DemoRequest& request, const QString& runPath)
{
    CliOutput::catchStopSignals();
    DemoLab lab;
    err(Demo::tr("starting the demo lab…"));
    if (const Status started = lab.start(request.lab); !started) {
        err(Demo::tr("the demo lab did not start: %1").arg(started.error().toString()));
        return ExitFailed;
    }
    if (lab.ros() == 2)
        err((lab.isLocalhostOnly() ? Demo::tr("broker %1, ROS 2 domain %2 (this host only), configs in %3")
                                   : Demo::tr("broker %1, ROS 2 domain %2, configs in %3"))
                .arg(Secrets::urlWithoutCredentials(lab.brokerUrl()))
                .arg(lab.rosDomain())
                .arg(lab.directory()));
    else
        err(Demo::tr("broker %1, ROS master %2, configs in %3")
                .arg(Secrets::urlWithoutCredentials(lab.brokerUrl()), lab.rosMasterUri(), lab.directory()));
    if (lab.isFar(u"cloud"_s))
        err(Demo::tr("the cloud's side runs on %1, reaching this host at %2")
                .arg(request.lab.cloudHost->host.url(), lab.listenAddress(u"cloud"_s)));
    const Result<Pipeline> pipeline = Pipeline::readFile(lab.pipelinePath());
    if (!pipeline) {
        err(pipeline.error().toString());
        return ExitFailed;
    }
    LiveSession live;
    if (lab.ros() == 2) {
        if (const Status joined = live.startRos2(lab.ros2Options()); !joined) {
            err(joined.error().toString());
            return ExitFailed;
        }
    } else {
        live.setRosMasterUri(lab.rosMasterUri());
    }
    live.connectBroker(MqttProfile::fromUrl(lab.brokerUrl()));
    MeasureSession measure(LiveParts::measure(&live));
    measure.setRos1(lab.ros() == 1); // a ROS 2 lab has no master: none is asked, none is named in the run
    measure.setPipeline(*pipeline);
    RunInfo info;
    info.name = Demo::tr("demo lab");
    info.notes = Demo::tr("bridgescope demo: %1 bytes at %2 Hz")
                     .arg(request.lab.payloadBytes)
                     .arg(request.lab.rateHz);
    if (const Result<void> started = measure.startRecording(runPath, info); !started) {
        err(started.error().toString());
        return ExitFailed;
    }
    // Until the time is up, Ctrl+C or the lab fails; a line of progress a second.
    int exitCode = CliOutput::runUntil(
        [&](qint64 elapsedMs) -> std::optional<int> {
            if (request.seconds > 0 && elapsedMs >= qint64(request.seconds * 1000))
                return ExitOk;
            if (lab.isRunning())
                return std::nullopt;
            err(Demo::tr("the demo lab failed: %1").arg(lab.failure()));
            return ExitFailed;
        },
        [&](qint64 elapsedMs) {
            const LatencyEngine& e = measure.engine();
            const LatencyStats total = e.series(e.totalSeries()).stats();
            err(Demo::tr("%1 s: %2 complete samples, total latency mean %3 ms")
                    .arg(elapsedMs / 1000)
                    .arg(e.samples())
                    .arg(total.count > 0 ? QString::number(total.mean, 'f', 1) : u"–"_s));
        });
    live.drainNow();
    if (const Result<void> stopped = measure.stopRecording(); !stopped) {
        err(Demo::tr("recording failed: %1").arg(stopped.error().toString()));
        exitCode = ExitFailed;
    }
    lab.stop();
    return exitCode;
}

/// Prints the latency report of the recorded run; fails when it holds no complete sample.
int printDemo(const DemoRequest& request, const QString& runPath)
{
    const Result<Report> report = Report::build({runPath}, std::nullopt, {});
    if (!report) {
        err(report.error().toString());
        return ExitFailed;
    }
    const QByteArray text = request.summary == ReportFormats::Format::Json ? ReportFormats::json(*report)
                                                                           : ReportFormats::markdown(*report);
    out(QString::fromUtf8(text).trimmed());
    if (!request.runPath.isEmpty())
        err(Demo::tr("the run is in %1").arg(runPath));
    return report->runs().front()->engine->samples() > 0 ? ExitOk : ExitFailed;
}
} // namespace

int runDemoCommand(const QStringList& arguments)
{
    DemoRequest request;
    if (const int status = parseDemo(arguments, &request); status >= 0)
        return status;
    QTemporaryDir scratch;
    const QString runPath = request.runPath.isEmpty() ? scratch.filePath(u"demo.bsrun"_s) : request.runPath;
    if (const int status = runDemo(request, runPath); status != ExitOk)
        return status;
    return printDemo(request, runPath);
}

int runDemoNodeCommand(const QStringList& arguments)
{
    QCommandLineParser parser;
    const QCommandLineOption master(u"ros-master"_s, Demo::tr("ROS master URI (default $ROS_MASTER_URI)."),
                                    u"URI"_s);
    const QCommandLineOption size(u"size"_s, Demo::tr("vehicle: point cloud size in bytes."), u"BYTES"_s,
                                  u"180000"_s);
    const QCommandLineOption rate(u"rate"_s, Demo::tr("vehicle: point clouds per second."), u"HZ"_s, u"10"_s);
    const QCommandLineOption detection(u"detection-ms"_s, Demo::tr("cloud: mean detection time."), u"MS"_s,
                                       u"40"_s);
    const QCommandLineOption offset(u"clock-offset-ms"_s, Demo::tr("This host's clock error."), u"MS"_s,
                                    u"0"_s);
    const QCommandLineOption ros(u"ros"_s, Demo::tr("1: a ROS 1 node (default); 2: a ROS 2 node over DDS."),
                                 u"1|2"_s, u"1"_s);
    const QCommandLineOption domain(u"ros-domain"_s, Demo::tr("ROS 2 domain id (default 0)."), u"ID"_s, u"0"_s);
    parser.addOptions({master, size, rate, detection, offset, ros, domain});
    parser.addPositionalArgument(u"ROLE"_s, Demo::tr("vehicle or cloud."), u"vehicle|cloud"_s);
    const int parsed
        = CliOutput::parseCommand(parser, arguments, u"bridgescope demo-node"_s,
                                  Demo::tr("One of the demo lab's ROS nodes; the lab starts them."));
    if (parsed >= 0)
        return parsed;
    const QString role = parser.positionalArguments().value(0);
    if (role != u"vehicle"_s && role != u"cloud"_s) {
        err(Demo::tr("demo-node takes vehicle or cloud"));
        return ExitUsage;
    }
    DemoLab::Options lab;
    if (!readRos(parser.value(ros), parser.value(domain), &lab))
        return ExitUsage;
    DemoNodes::Options o;
    o.masterUri = parser.value(master);
    o.payloadBytes = parser.value(size).toInt();
    o.rateHz = parser.value(rate).toDouble();
    o.detectionMs = parser.value(detection).toDouble();
    o.clockOffsetNs = qint64(parser.value(offset).toDouble() * 1e6);
    CliOutput::catchStopSignals();
    CliOutput::keepFreedMemory();
    const auto stop = [] { return CliOutput::stopRequested(); };
    Status ran;
    if (lab.ros == 2) {
        Ros2DemoNodes::Options o2;
        static_cast<DemoNodes::Options&>(o2) = o;
        // The lab's domain stays on 127.0.0.1 unless its sides span hosts (ROS_LOCALHOST_ONLY=0).
        o2.dds = {lab.rosDomain, qEnvironmentVariable("ROS_LOCALHOST_ONLY").trimmed() != u"0"_s};
        if (!o2.dds.localhostOnly)
            o2.dds.staticPeers = Ros2Options::fromEnvironment().staticPeers;
        ran = role == u"vehicle"_s ? Ros2DemoNodes::runVehicle(o2, stop) : Ros2DemoNodes::runCloud(o2, stop);
    } else {
        ran = role == u"vehicle"_s ? DemoNodes::runVehicle(o, stop) : DemoNodes::runCloud(o, stop);
    }
    if (!ran && !CliOutput::stopRequested()) {
        err(Demo::tr("demo-node %1: %2").arg(role, ran.error().toString()));
        return ExitFailed;
    }
    return ExitOk;
}
