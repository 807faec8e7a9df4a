// SPDX-License-Identifier: MIT
#include "recordcommand.h"

#include "app/cli/clioutput.h"
#include "record/runrecorder.h"
#include "ros/rosmasterapi.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTimer>

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
} // namespace

int runRecordCommand(const QStringList& arguments)
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
    parser.addOptions({pipeline, broker, master, samples, seconds, output, name, notes, config});
    QStringList args = arguments;
    args.replace(0, u"bridgescope record"_s);
    const int parsed = CliOutput::parseCommand(
        parser, args,
        Record::tr(
            "Records a measurement run: every stamp of the pipeline from ROS and MQTT, committed to the run "
            "file at least every 200 ms, until N samples are complete, S seconds passed, or Ctrl+C.\n"
            "Exit status: 0 recorded, 1 the run file could not be written, 2 bad options."));
    if (parsed >= 0)
        return parsed;
    if (!parser.isSet(pipeline) || !parser.isSet(output)) {
        err(Record::tr("record needs --pipeline and -o; see bridgescope record --help"));
        return ExitUsage;
    }
    bool ok = true;
    const qint64 wantSamples = parser.isSet(samples) ? parser.value(samples).toLongLong(&ok) : 0;
    if (!ok || wantSamples < 0) {
        err(Record::tr("--samples takes a number of samples"));
        return ExitUsage;
    }
    const double wantSeconds = parser.isSet(seconds) ? parser.value(seconds).toDouble(&ok) : 0;
    if (!ok || wantSeconds < 0) {
        err(Record::tr("--seconds takes a number of seconds"));
        return ExitUsage;
    }
    QString why;
    const std::optional<Pipeline> pipe = Pipeline::load(parser.value(pipeline), &why);
    if (!pipe) {
        err(why);
        return ExitUsage;
    }
    MqttProfile profile = MqttProfile::fromUrl(parser.value(broker));
    if (!profile.validate(&why)) {
        err(why);
        return ExitUsage;
    }
    RunInfo info;
    info.name = parser.isSet(name) ? parser.value(name) : QFileInfo(parser.value(output)).completeBaseName();
    info.notes = parser.value(notes);
    if (parser.isSet(config)) {
        QFile f(parser.value(config));
        if (!f.open(QIODevice::ReadOnly)) {
            err(Record::tr("%1: %2").arg(parser.value(config), f.errorString()));
            return ExitUsage;
        }
        info.bridgeConfigPath = QFileInfo(f).absoluteFilePath();
        info.bridgeConfig = f.readAll();
    }

    if (QFileInfo::exists(parser.value(output))) { // before any connection is made
        err(Record::tr("%1 exists already; a run is never overwritten").arg(parser.value(output)));
        return ExitUsage;
    }

    LiveSession live;
    live.setRosMasterUri(parser.value(master));
    live.connectBroker(profile);
    MeasureSession measure(&live);
    measure.setPipeline(*pipe);
    if (!measure.startRecording(parser.value(output), info, &why)) {
        err(why);
        return ExitUsage;
    }
    int exitCode = ExitOk;
    QElapsedTimer clock;
    clock.start();
    QObject::connect(&measure, &MeasureSession::recordingFailed, [&exitCode](const QString& failure) {
        err(Record::tr("recording failed: %1").arg(failure));
        exitCode = ExitFailed;
        QCoreApplication::exit(ExitFailed);
    });
    QTimer check;
    CliOutput::whenStopRequested(&check, [] { QCoreApplication::exit(ExitOk); });
    qint64 lastReport = 0;
    QObject::connect(&check, &QTimer::timeout, [&] {
        const LatencyEngine& e = measure.engine();
        const bool enough = wantSamples > 0 && e.samples() >= wantSamples;
        const bool late = wantSeconds > 0 && clock.elapsed() >= qint64(wantSeconds * 1000);
        if (enough || late) {
            QCoreApplication::exit(ExitOk);
            return;
        }
        if (clock.elapsed() - lastReport >= 1000) {
            lastReport = clock.elapsed();
            // Committed first: after a crash the file holds at least what this line says.
            err(Record::tr("%1 s: %2 stamps committed, %3 complete samples, %4 dropped, %5 waiting")
                    .arg(clock.elapsed() / 1000)
                    .arg(measure.recorder()->committedStamps())
                    .arg(e.samples())
                    .arg(e.counters().dropped())
                    .arg(e.pending()));
        }
    });
    check.start(50);
    QCoreApplication::exec();
    if (exitCode != 0)
        return exitCode;
    live.drainNow(); // what arrived in the last moment
    const qint64 complete = measure.engine().samples();
    if (!measure.stopRecording(&why)) {
        err(Record::tr("recording failed: %1").arg(why));
        return ExitFailed;
    }
    out(Record::tr("%1: %2 complete samples, %3 stamps")
            .arg(parser.value(output))
            .arg(complete)
            .arg(measure.recorder()->committedStamps()));
    return ExitOk;
}
