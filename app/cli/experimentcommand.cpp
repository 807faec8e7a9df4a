// SPDX-License-Identifier: MIT
#include "experimentcommand.h"

#include "app/cli/clioutput.h"
#include "experiment/experimentevent.h"
#include "experiment/experimentrunner.h"
#include "mqtt/mqttprofile.h"

#include <utility>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;
using CliOutput::out;

// The command's exit statuses are the protocol's (the Experiments page reads them as ExperimentExit).
static_assert(int(ExperimentExit::Complete) == CliOutput::ExitOk);
static_assert(int(ExperimentExit::CellFailed) == CliOutput::ExitFailed);
static_assert(int(ExperimentExit::Usage) == CliOutput::ExitUsage);
static_assert(int(ExperimentExit::Stopped) == CliOutput::ExitCancelled);

namespace {
constexpr qsizetype kMaxTotalsPerLine = 10'000;

class Experiment
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentCommand)
};

/// What the command line asks for.
struct ExperimentRequest
{
    ExperimentPlan plan;
    QByteArray planText;
    QString directory;
    bool resume = false;
    bool dryRun = false;
};

/// --broker and --ros-master instead of the plan's servers (a plan holds no credentials: it is
/// copied next to its runs; the command line may, and main() hides them from ps). A ROS 2 plan
/// has no master: --broker alone, and --ros-master is refused.
bool overrideServers(const QString& broker, const QString& master, ExperimentPlan* plan)
{
    if (broker.isEmpty() && master.isEmpty())
        return true;
    if (plan->ros == 2 && !master.isEmpty()) {
        err(Experiment::tr("--ros-master: the plan runs on ROS 2 (ros: 2), which has no master"));
        return false;
    }
    const QString brokerUrl = broker.isEmpty() ? plan->brokerUrl : broker;
    const QString masterUri = master.isEmpty() ? plan->rosMasterUri : master;
    if (brokerUrl.isEmpty() || (masterUri.isEmpty() && plan->ros != 2)) {
        err(Experiment::tr("--broker and --ros-master go together, unless the plan's servers give the other"));
        return false;
    }
    if (const Status valid = MqttProfile::fromUrl(brokerUrl).validate(); !valid) {
        err(valid.error().toString());
        return false;
    }
    plan->brokerUrl = brokerUrl;
    plan->rosMasterUri = masterUri;
    return true;
}

int parseExperiment(const QStringList& arguments, ExperimentRequest* request)
{
    QCommandLineParser parser;
    const QCommandLineOption output(
        {u"o"_s, u"output"_s}, Experiment::tr("The experiment's folder: its plan, state and a run per cell."),
        u"DIR"_s);
    const QCommandLineOption resume(
        u"resume"_s,
        Experiment::tr("Go on with DIR: skip the complete cells, redo the one that was "
                       "cut off and those that failed."));
    const QCommandLineOption dryRun(
        u"dry-run"_s, Experiment::tr("List the cells and the time they will take; run nothing."));
    const QCommandLineOption broker(
        u"broker"_s,
        Experiment::tr("Run every cell on this broker instead of the plan's servers; it may carry a user "
                       "and password, which no file, log or command line of a child gets."),
        u"URL"_s);
    const QCommandLineOption master(
        u"ros-master"_s, Experiment::tr("The ROS master that goes with --broker (default: the plan's)."),
        u"URI"_s);
    parser.addOptions({output, resume, dryRun, broker, master});
    parser.addPositionalArgument(u"PLAN"_s, Experiment::tr("The experiment plan (docs/formats.md)."),
                                 u"PLAN.yaml"_s);
    const int parsed = CliOutput::parseCommand(
        parser, arguments, u"bridgescope experiment"_s,
        Experiment::tr(
            "Runs an experiment plan unattended: every cell of its matrix (payload, rate, QoS, TLS, "
            "announcement, queue size, bridge implementation, link profile) on its own lab, "
            "recorded as a run in DIR. Progress on standard error; on standard output one JSON line "
            "per cell started and finished, and a progress line a second with the totals (ms) of the "
            "samples since the last; Ctrl+C stops after cleaning up, and "
            "--resume goes on. bridgescope report DIR makes the tables.\n"
            "Exit status: 0 every cell complete, 1 a cell failed, 2 bad options or plan, 130 "
            "stopped."));
    if (parsed >= 0)
        return parsed;
    if (parser.positionalArguments().size() != 1) {
        err(Experiment::tr("experiment takes one plan; see bridgescope experiment --help"));
        return ExitUsage;
    }
    request->dryRun = parser.isSet(dryRun);
    request->resume = parser.isSet(resume);
    request->directory = parser.value(output);
    if (request->directory.isEmpty() && !request->dryRun) {
        err(Experiment::tr("experiment needs -o DIR, the folder its runs go to"));
        return ExitUsage;
    }
    const QString path = parser.positionalArguments().first();
    Result<ExperimentPlan> plan = ExperimentPlan::readFile(path, &request->planText);
    if (!plan) {
        err(plan.error().toString());
        return ExitUsage;
    }
    if (plan->name.isEmpty())
        plan->name = QFileInfo(path).completeBaseName();
    if (!overrideServers(parser.value(broker), parser.value(master), &*plan))
        return ExitUsage;
    request->plan = *plan;
    return -1;
}

int dryRun(const ExperimentPlan& plan)
{
    double total = 0;
    out(Experiment::tr("%1: %n cell(s), %2 samples each after %3 of warm-up", nullptr, int(plan.cells.size()))
            .arg(plan.name)
            .arg(plan.samples)
            .arg(plan.warmup));
    for (const ExperimentCell& c : plan.cells) {
        const double s = plan.expectedSeconds(c);
        total += s;
        out(u"  %1  %2  %3"_s.arg(c.id().leftJustified(40), ExperimentPlan::durationText(s).rightJustified(8),
                                  c.label()));
        if (!c.settings.problem.isEmpty())
            out(Experiment::tr("    fails: %1").arg(c.settings.problem));
    }
    out(Experiment::tr("about %1 in all").arg(ExperimentPlan::durationText(total)));
    return ExitOk;
}

/// Writes `e` as the line the Experiments page reads (ExperimentEvent's codec).
void printEvent(const ExperimentEvent& e)
{
    out(QString::fromUtf8(e.toLine()));
}

void printCell(const ExperimentRunner& runner, int index, ExperimentEvent::Kind kind)
{
    const ExperimentCell& cell = runner.plan().cells[index];
    const CellStatus& s = runner.statuses()[index];
    ExperimentEvent e;
    e.kind = kind;
    e.index = index;
    e.cell = cell.id();
    e.levels = cell.levels;
    e.state = s.state;
    e.samples = s.samples;
    e.run = s.run;
    e.reason = s.reason;
    e.link = s.link;
    printEvent(e);
}

void printThroughput(const ThroughputPoint& p)
{
    ExperimentEvent e;
    e.kind = ExperimentEvent::Kind::Throughput;
    e.rateHz = p.rateHz;
    e.throughputSamples = double(p.samples);
    e.expected = double(p.expected);
    e.dropped = double(p.dropped);
    e.p50Ms = p.p50Ms;
    e.sustainable = p.sustainable;
    printEvent(e);
}

int runExperiment(const ExperimentRequest& request)
{
    ExperimentRunner::Options options;
    options.resume = request.resume;
    ExperimentRunner runner(request.plan, request.planText, request.directory, options);
    if (const Status prepared = runner.prepare(); !prepared) {
        err(prepared.error().toString());
        return ExitUsage;
    }
    for (const QString& note : runner.resumeNotes())
        err(note);
    const int cells = int(request.plan.cells.size());
    // The running cell's totals since the last progress line: what the Experiments page plots live.
    QList<double> totals;
    bool warmingUp = false;
    const auto printProgress = [&](int i) {
        ExperimentEvent e;
        e.kind = ExperimentEvent::Kind::Progress;
        e.index = i;
        e.samples = runner.runningSamples();
        e.of = request.plan.samples;
        e.warmingUp = warmingUp;
        e.remainingS = qRound(runner.remainingSeconds());
        e.totalMs = std::exchange(totals, {});
        printEvent(e);
    };
    QObject::connect(&runner, &ExperimentRunner::progress,
                     [&](int, qint64, bool warming) { warmingUp = warming; });
    QObject::connect(&runner, &ExperimentRunner::totals, [&](int, const QList<double>& ms) {
        totals += ms;
        if (totals.size() > kMaxTotalsPerLine) // bounded lines at any rate; the run file has them all
            totals.remove(0, totals.size() - kMaxTotalsPerLine);
    });
    QObject::connect(&runner, &ExperimentRunner::cellStarted, [&](int i) {
        totals.clear();
        warmingUp = true;
        printCell(runner, i, ExperimentEvent::Kind::Started);
        err(Experiment::tr("cell %1/%2: %3").arg(i + 1).arg(cells).arg(request.plan.cells[i].label()));
    });
    QObject::connect(&runner, &ExperimentRunner::cellFinished, [&](int i) {
        if (!totals.isEmpty())
            printProgress(i);
        printCell(runner, i, ExperimentEvent::Kind::Finished);
        const CellStatus& s = runner.statuses()[i];
        if (s.state == CellStatus::Failed)
            err(Experiment::tr("cell %1/%2 failed: %3").arg(i + 1).arg(cells).arg(s.reason));
    });
    QObject::connect(&runner, &ExperimentRunner::warning, [&](int i, const QString& text) {
        err(Experiment::tr("cell %1/%2: %3").arg(i + 1).arg(cells).arg(text));
    });
    QObject::connect(&runner, &ExperimentRunner::probeStarted, [](int bytes, double rate) {
        err(Experiment::tr("throughput: %1 bytes at %2 Hz").arg(bytes).arg(rate));
    });
    QObject::connect(&runner, &ExperimentRunner::probeFinished, printThroughput);
    std::optional<int> done;
    QObject::connect(&runner, &ExperimentRunner::finished,
                     [&](bool all) { done = int(all ? ExperimentExit::Complete : ExperimentExit::CellFailed); });
    runner.start();
    const int status = CliOutput::runUntil([&](qint64) { return done; },
                                           [&](qint64) {
                                               const int i = runner.runningCell();
                                               if (i < 0)
                                                   return;
                                               printProgress(i);
                                               err(Experiment::tr("cell %1/%2: %3/%4 samples, about %5 left")
                                                       .arg(i + 1)
                                                       .arg(cells)
                                                       .arg(runner.runningSamples())
                                                       .arg(request.plan.samples)
                                                       .arg(ExperimentPlan::durationText(
                                                           runner.remainingSeconds())));
                                           });
    if (!done) { // Ctrl+C or SIGTERM
        runner.stop();
        err(Experiment::tr("stopped; bridgescope experiment --resume goes on"));
        return CliOutput::ExitCancelled;
    }
    int complete = 0;
    for (const CellStatus& s : runner.statuses())
        complete += s.state == CellStatus::Complete;
    err(Experiment::tr("%1 of %2 cells complete in %3").arg(complete).arg(cells).arg(request.directory));
    return status;
}
} // namespace

int runExperimentCommand(const QStringList& arguments)
{
    ExperimentRequest request;
    if (const int status = parseExperiment(arguments, &request); status >= 0)
        return status;
    if (request.dryRun)
        return dryRun(request.plan);
    return runExperiment(request);
}
