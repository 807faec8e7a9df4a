// SPDX-License-Identifier: MIT
#include "reportcommand.h"

#include "app/cli/clioutput.h"
#include "base/atomicfile.h"
#include "report/report.h"
#include "report/reportformats.h"

#include <cstdio>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <unistd.h>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::ExitCancelled;
using CliOutput::ExitUsage;
using CliOutput::out;

namespace {
class ReportText
{
    Q_DECLARE_TR_FUNCTIONS(ReportCommand)
};
} // namespace

int runReportCommand(const QStringList& arguments)
{
    QCommandLineParser parser;
    const QString description = ReportText::tr(
        "Reports the latency statistics of measured runs: every stage, the total and, with hosts in the "
        "pipeline, "
        "the communication round trip, its one-way half and the clock offset. INPUT is a run (bridgescope "
        "record), the benchmarking suite's timestamp CSV or a ROS bag with TimeStamped topics; several "
        "inputs "
        "are compared side by side (the paper's Table I and Fig. 5), or joined into one run with --join.\n"
        "Exit status: 0 report written, 1 a run has no complete sample, 2 bad options or input, 130 "
        "cancelled.");
    const QCommandLineOption pipeline(
        u"pipeline"_s, ReportText::tr("Pipeline YAML (the suite's metrics-logger file; hosts: optional)."),
        u"PIPE.yaml"_s);
    const QCommandLineOption format(u"format"_s, ReportText::tr("json (default), csv, md, tex, html or pdf."),
                                    u"FORMAT"_s, u"json"_s);
    const QCommandLineOption window(
        u"window"_s, ReportText::tr("Statistics over the last N samples (default 0: all)."), u"N"_s, u"0"_s);
    const QCommandLineOption output({u"o"_s, u"output"_s}, ReportText::tr("Write to FILE instead of stdout."),
                                    u"FILE"_s);
    const QCommandLineOption join(
        u"join"_s, ReportText::tr("Join several inputs into one run instead of comparing them."));
    const QCommandLineOption perSample(
        u"per-sample-ms"_s,
        ReportText::tr("csv: one row per sample of stage latencies in ms, not the stamps."));
    const QCommandLineOption skip(
        u"skip-bad-rows"_s,
        ReportText::tr("Skip CSV rows that cannot be read (each is reported) instead of failing."));
    const QCommandLineOption title(u"title"_s, ReportText::tr("Title of the report."), u"TEXT"_s);
    parser.addOptions({pipeline, format, window, output, join, perSample, skip, title});
    parser.addPositionalArgument(u"INPUT"_s, ReportText::tr("Runs, suite timestamp CSV files or bags."),
                                 u"INPUT..."_s);
    QStringList args = arguments;
    args.replace(0, u"bridgescope report"_s);
    const int parsed = CliOutput::parseCommand(parser, args, description);
    if (parsed >= 0)
        return parsed;
    ReportFormats::Format fmt;
    if (!ReportFormats::parse(parser.value(format), &fmt)) {
        err(ReportText::tr("unknown format %1 (known: json, csv, md, tex, html, pdf)")
                .arg(parser.value(format)));
        return ExitUsage;
    }
    bool ok = false;
    Report::Options options;
    options.window = parser.value(window).toLongLong(&ok);
    if (!ok || options.window < 0) {
        err(ReportText::tr("--window takes a number of samples (0: all)"));
        return ExitUsage;
    }
    options.join = parser.isSet(join);
    options.skipBadRows = parser.isSet(skip);
    options.title = parser.value(title);
    const QStringList inputs = parser.positionalArguments();
    if (inputs.isEmpty()) {
        err(ReportText::tr("no input files; see bridgescope report --help"));
        return ExitUsage;
    }
    std::optional<Pipeline> pipe;
    QString why;
    if (parser.isSet(pipeline)) {
        pipe = Pipeline::load(parser.value(pipeline), &why);
        if (!pipe) {
            err(why);
            return ExitUsage;
        }
    }

    // Progress on a terminal; Ctrl+C cancels, and nothing is written then.
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
    std::optional<Report> report = Report::build(inputs, pipe, options, &why, &warnings, progress);
    if (tty && shown >= 0)
        std::fprintf(stderr, "\r\033[K");
    if (CliOutput::stopRequested()) {
        err(ReportText::tr("cancelled; nothing written"));
        return ExitCancelled;
    }
    if (!report) {
        err(why);
        return ExitUsage;
    }
    for (const QString& w : std::as_const(warnings))
        err(ReportText::tr("%1 (row skipped)").arg(w));

    const QByteArray text = ReportFormats::render(*report, fmt, parser.isSet(perSample), &why);
    if (text.isEmpty() && !why.isEmpty()) {
        err(why);
        return ExitUsage;
    }
    if (CliOutput::stopRequested()) { // formatting thousands of stages takes a while too
        err(ReportText::tr("cancelled; nothing written"));
        return ExitCancelled;
    }
    if (parser.isSet(output)) {
        if (!AtomicFile::write(parser.value(output), text, &why, false)) {
            err(why);
            return ExitUsage;
        }
    } else if (fmt == ReportFormats::Format::Pdf) {
        std::fwrite(text.constData(), 1, std::size_t(text.size()), stdout);
    } else {
        std::fwrite(text.constData(), 1, std::size_t(text.size()), stdout);
        std::fflush(stdout);
    }
    int status = 0;
    for (const auto& run : report->runs()) {
        if (run->engine->samples() == 0) {
            err(ReportText::tr("%1: no complete sample").arg(run->path));
            status = 1;
        }
    }
    return status;
}
