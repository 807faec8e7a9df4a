// SPDX-License-Identifier: MIT
#include "reportcommand.h"

#include "clioutput.h"
#include "common/atomicfile.h"
#include "latency/latencyengine.h"
#include "latency/latencyreport.h"
#include "record/runloader.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonDocument>

using namespace Qt::StringLiterals;
using CliOutput::err;
using CliOutput::out;

namespace {
class Report
{
    Q_DECLARE_TR_FUNCTIONS(ReportCommand)
};
} // namespace

int runReportCommand(const QStringList& arguments)
{
    QCommandLineParser parser;
    const QString description = Report::tr(
        "Computes the latency statistics of measurement files (the benchmarking suite's timestamp CSV) "
        "over the whole run: every stage, the total and, with hosts in the pipeline, the communication "
        "round trip, its one-way half and the clock offset. Several inputs are joined into one run.\n"
        "Exit status: 0 report written, 1 no complete sample, 2 bad options or unreadable input.");
    const QCommandLineOption pipeline(
        u"pipeline"_s, Report::tr("Pipeline YAML (the suite's metrics-logger file; hosts: optional)."),
        u"PIPE.yaml"_s);
    const QCommandLineOption format(u"format"_s, Report::tr("Output format: json (default)."), u"FORMAT"_s,
                                    u"json"_s);
    const QCommandLineOption window(
        u"window"_s, Report::tr("Statistics over the last N samples (default 0: all)."), u"N"_s, u"0"_s);
    const QCommandLineOption output({u"o"_s, u"output"_s}, Report::tr("Write to FILE instead of stdout."),
                                    u"FILE"_s);
    parser.addOptions({pipeline, format, window, output});
    parser.addPositionalArgument(u"INPUT"_s, Report::tr("Suite timestamp CSV files."), u"INPUT..."_s);
    QStringList args = arguments;
    args.replace(0, u"bridgescope report"_s);
    const int parsed = CliOutput::parseCommand(parser, args, description);
    if (parsed >= 0)
        return parsed;
    if (parser.value(format) != u"json"_s) {
        err(Report::tr("unknown format %1 (known: json)").arg(parser.value(format)));
        return 2;
    }
    bool ok = false;
    const qint64 windowSamples = parser.value(window).toLongLong(&ok);
    if (!ok || windowSamples < 0) {
        err(Report::tr("--window takes a number of samples (0: all)"));
        return 2;
    }
    const QStringList inputs = parser.positionalArguments();
    if (inputs.isEmpty()) {
        err(Report::tr("no input files; see bridgescope report --help"));
        return 2;
    }
    std::optional<Pipeline> pipe;
    QString why;
    if (parser.isSet(pipeline)) {
        pipe = Pipeline::load(parser.value(pipeline), &why);
        if (!pipe) {
            err(why);
            return 2;
        }
    }
    const std::optional<LoadedRun> run = RunLoader::load(inputs, pipe, &why);
    if (!run) {
        err(why);
        return 2;
    }
    for (const QString& problem : run->problems)
        err(Report::tr("%1 (row skipped)").arg(problem));
    if (run->malformed > run->problems.size())
        err(Report::tr("%1 more rows skipped").arg(run->malformed - run->problems.size()));

    LatencyEngine engine(run->pipeline);
    engine.setWindow(windowSamples);
    for (const std::vector<qint64>& sample : run->samples)
        engine.addSample(sample);
    QJsonObject doc = LatencyReport::json(engine, run->incomplete);
    if (run->malformed)
        doc.insert(u"malformed_rows"_s, run->malformed);
    const QByteArray text = QJsonDocument(doc).toJson(QJsonDocument::Indented);
    if (parser.isSet(output)) {
        if (!AtomicFile::write(parser.value(output), text, &why, false)) {
            err(why);
            return 2;
        }
    } else {
        out(QString::fromUtf8(text).trimmed());
    }
    if (run->samples.empty()) {
        err(Report::tr("no complete sample in the input"));
        return 1;
    }
    return 0;
}
