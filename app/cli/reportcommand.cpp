// SPDX-License-Identifier: MIT
#include "reportcommand.h"

#include "app/cli/clioutput.h"
#include "files/atomicfile.h"
#include "experiment/experimentreport.h"
#include "latency/latencywarnings.h"
#include "report/report.h"
#include "report/reportformats.h"

#include <cstdio>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <unistd.h>
#include <variant>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitCancelled;
using CliOutput::ExitFailed;
using CliOutput::ExitOk;
using CliOutput::ExitUsage;

namespace {
class ReportText
{
    Q_DECLARE_TR_FUNCTIONS(ReportCommand)
};

/// What the command line asks for.
struct ReportRequest
{
    QStringList inputs;
    std::optional<Pipeline> pipeline;
    Report::Options options;
    ReportFormats::Format format = ReportFormats::Format::Json;
    bool perSample = false;
    QString output; ///< empty: stdout
    QString statistics; ///< of an experiment's tables: "mean,median,std,p99"
};

/// The command line of `bridgescope report`.
struct ReportArguments
{
    const QCommandLineOption pipeline {
        u"pipeline"_s, ReportText::tr("Pipeline YAML (the suite's metrics-logger file; hosts: optional)."),
        u"PIPE.yaml"_s};
    const QCommandLineOption format {
        u"format"_s, ReportText::tr("json (default), csv, md, tex, html or pdf."), u"FORMAT"_s, u"json"_s};
    const QCommandLineOption window {
        u"window"_s, ReportText::tr("Statistics over the last N samples (default 0: all)."), u"N"_s, u"0"_s};
    const QCommandLineOption output {
        {u"o"_s, u"output"_s}, ReportText::tr("Write to FILE instead of stdout."), u"FILE"_s};
    const QCommandLineOption join {
        u"join"_s, ReportText::tr("Join several inputs into one run instead of comparing them.")};
    const QCommandLineOption perSample {
        u"per-sample-ms"_s,
        ReportText::tr("csv: one row per sample of stage latencies in ms, not the stamps.")};
    const QCommandLineOption skip {
        u"skip-bad-rows"_s,
        ReportText::tr("Skip CSV rows that cannot be read (each is reported) instead of failing.")};
    const QCommandLineOption title {u"title"_s, ReportText::tr("Title of the report."), u"TEXT"_s};
    const QCommandLineOption statistics {
        u"stat"_s,
        ReportText::tr("An experiment's tables: mean (default), median, std, p99, or several (mean,p99)."),
        u"LIST"_s, u"mean"_s};
    const QCommandLineOption oneClock {
        u"one-clock"_s,
        ReportText::tr("Every stamp comes from one clock (one machine): each direction's own one-way "
                       "latency, no clock offset.")};

    QList<QCommandLineOption> all() const
    {
        return {pipeline, format, window, output, join, perSample, skip, title, statistics, oneClock};
    }
};

/// Parses and checks the command line. -1 to go on with `request`, otherwise the exit status.
int parseReport(const QStringList& arguments, ReportRequest* request)
{
    QCommandLineParser parser;
    const QString description = ReportText::tr(
        "Reports the latency statistics of measured runs: every stage, the total and, with hosts in the "
        "pipeline, "
        "the communication round trip, its one-way half and the clock offset. INPUT is a run (bridgescope "
        "record), the benchmarking suite's timestamp CSV or a ROS bag with TimeStamped topics; several "
        "inputs "
        "are compared side by side (the paper's Table I and Fig. 5), or joined into one run with --join. "
        "An experiment's folder (bridgescope experiment) gives a table per factor, its levels as columns "
        "and the stage groups as rows.\n"
        "Exit status: 0 report written, 1 a run with a pipeline has no complete sample, 2 bad options or "
        "input, 130 "
        "cancelled.");
    const ReportArguments a;
    parser.addOptions(a.all());
    parser.addPositionalArgument(
        u"INPUT"_s, ReportText::tr("Runs, suite timestamp CSV files or bags; or an experiment's folder."),
        u"INPUT..."_s);
    const int parsed = CliOutput::parseCommand(parser, arguments, u"bridgescope report"_s, description);
    if (parsed >= 0)
        return parsed;
    if (!ReportFormats::parse(parser.value(a.format), &request->format)) {
        err(ReportText::tr("unknown format %1 (known: json, csv, md, tex, html, pdf)")
                .arg(parser.value(a.format)));
        return ExitUsage;
    }
    bool ok = false;
    Report::Options& options = request->options;
    options.window = parser.value(a.window).toLongLong(&ok);
    if (!ok || options.window < 0) {
        err(ReportText::tr("--window takes a number of samples (0: all)"));
        return ExitUsage;
    }
    options.join = parser.isSet(a.join);
    options.skipBadRows = parser.isSet(a.skip);
    options.oneClock = parser.isSet(a.oneClock);
    options.title = parser.value(a.title);
    request->perSample = parser.isSet(a.perSample);
    request->output = parser.value(a.output);
    request->statistics = parser.value(a.statistics);
    request->inputs = parser.positionalArguments();
    if (request->inputs.isEmpty()) {
        err(ReportText::tr("no input files; see bridgescope report --help"));
        return ExitUsage;
    }
    if (parser.isSet(a.pipeline)) {
        Result<Pipeline> pipeline = Pipeline::readFile(parser.value(a.pipeline));
        if (!pipeline) {
            err(pipeline.error().toString());
            return ExitUsage;
        }
        request->pipeline = std::move(pipeline).value();
    }
    return -1;
}

/// Reads the inputs, with progress on a terminal; Ctrl+C cancels. The report, or the exit status.
std::variant<Report, int> buildReport(const ReportRequest& request)
{
    CliOutput::catchStopSignals();
    const bool tty = ::isatty(STDERR_FILENO);
    QElapsedTimer clock;
    clock.start();
    qint64 shown = -1000;
    const Progress progress = [&](int percent) {
        if (tty && clock.elapsed() > 1000 && clock.elapsed() - shown >= 200) {
            shown = clock.elapsed();
            std::fprintf(stderr, "\r%s", qPrintable(ReportText::tr("reading… %1 %").arg(percent)));
            std::fflush(stderr);
        }
        return !CliOutput::stopRequested();
    };
    QStringList warnings;
    Result<Report> report
        = Report::build(request.inputs, request.pipeline, request.options, &warnings, progress);
    if (tty && shown >= 0)
        std::fprintf(stderr, "\r\033[K");
    if (CliOutput::stopRequested()) {
        err(ReportText::tr("cancelled; nothing written"));
        return ExitCancelled;
    }
    if (!report) {
        err(report.error().toString());
        return ExitUsage;
    }
    for (const QString& w : std::as_const(warnings))
        err(ReportText::tr("%1 (row skipped)").arg(w));
    return std::move(*report);
}

/// The tables of an experiment's folder.
int experimentReport(const ReportRequest& request)
{
    const Result<QList<ExperimentReport::Statistic>> statistics
        = ExperimentReport::parseStatistics(request.statistics);
    if (!statistics) {
        err(statistics.error().toString());
        return ExitUsage;
    }
    // Its runs are read like any other: Ctrl+C and SIGTERM end a long read.
    CliOutput::catchStopSignals();
    const Result<ExperimentReport> report
        = ExperimentReport::load(request.inputs.first(), [](int) { return !CliOutput::stopRequested(); });
    if (CliOutput::stopRequested()) {
        err(ReportText::tr("cancelled; nothing written"));
        return ExitCancelled;
    }
    if (!report) {
        err(report.error().toString());
        return ExitUsage;
    }
    const Result<QByteArray> text = report->exportTo(request.output, request.format, *statistics);
    if (!text) {
        err(text.error().toString());
        return ExitUsage;
    }
    if (request.output.isEmpty())
        CliOutput::writeStdout(*text); // a failed write is reported by finish() below
    return CliOutput::finish(ExitOk);
}

/// Renders the report and writes it to the file or stdout; nothing is written when cancelled.
int writeReport(const ReportRequest& request, const Report& report)
{
    const Result<QByteArray> text = ReportFormats::render(report, request.format, request.perSample);
    if (!text) {
        err(text.error().toString());
        return ExitUsage;
    }
    if (CliOutput::stopRequested()) { // formatting thousands of stages takes a while too
        err(ReportText::tr("cancelled; nothing written"));
        return ExitCancelled;
    }
    if (request.output.isEmpty()) {
        CliOutput::writeStdout(*text); // a failed write is reported by finish() below
    } else if (const Status written = AtomicFile::write(request.output, *text, false); !written) {
        err(written.error().toString());
        return ExitUsage;
    }
    int status = ExitOk;
    for (const auto& run : report.runs()) {
        // Said on stderr too: a figure that contradicts the pipeline must not pass as a result.
        const QList<LatencyWarning> warnings = LatencyWarnings::of(*run->engine);
        for (const QString& line : LatencyWarnings::lines(warnings))
            err(ReportText::tr("%1: not a measurement: %2").arg(run->path, line));
        if (!warnings.isEmpty())
            err(LatencyWarnings::fixOnCommandLine());
        if (run->engine->samples() == 0 && !run->engine->pipeline().isEmpty()) { // a watch has no pipeline
            err(ReportText::tr("%1: no complete sample").arg(run->path));
            status = ExitFailed;
        }
    }
    return CliOutput::finish(status);
}
} // namespace

int runReportCommand(const QStringList& arguments)
{
    ReportRequest request;
    if (const int status = parseReport(arguments, &request); status >= 0)
        return status;
    if (request.inputs.size() == 1 && ExperimentReport::isExperiment(request.inputs.first()))
        return experimentReport(request);
    std::variant<Report, int> built = buildReport(request);
    if (const int* status = std::get_if<int>(&built))
        return *status;
    return writeReport(request, std::get<Report>(built));
}
