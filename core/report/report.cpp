// SPDX-License-Identifier: MIT
#include "report.h"

#include "text/nameelider.h"
#include "latency/seriesid.h"
#include "report/runloader.h"

#include <algorithm>
#include <QFileInfo>
#include <QSet>

using namespace Qt::StringLiterals;

std::unique_ptr<ReportRun> Report::compute(RunData&& data, const std::optional<Pipeline>& pipeline,
                                           const Options& options, const Progress& progress, int percent)
{
    auto run = std::make_unique<ReportRun>();
    run->info = data.info;
    run->droppedBeforeImport = data.droppedBeforeImport;
    run->events = std::move(data.events);
    run->name = data.info.name;
    Pipeline p = pipeline ? *pipeline : data.info.pipeline;
    p.setWindow(int(options.window));
    if (options.oneClock)
        p.setOneClock(true);
    run->info.pipeline = p;
    run->engine = std::make_unique<LatencyEngine>(p);
    run->engine->setTimeoutNs(data.info.timeoutNs > 0 ? data.info.timeoutNs
                                                      : SampleJoiner::kDefaultTimeoutNs);
    std::vector<std::vector<qint64>>& samples = run->samples;
    run->engine->setSampleListener(
        [&samples](qint64, const std::vector<qint64>& times) { samples.push_back(times); });
    // Ctrl+C is polled while replaying too: a run of millions of stamps takes a while.
    const bool finished = data.replay(*run->engine, [&] { return !progress || progress(percent); });
    run->engine->setSampleListener({});
    if (!finished)
        return nullptr;
    const LatencyEngine& e = *run->engine;
    for (int s = e.pipeline().stageCount() - 1; s >= 0; --s) // backwards: the first of a label wins
        run->stageByLabel.insert(e.info(e.pipelineSeries().stageSeries(s)).label,
                                 e.pipelineSeries().stageSeries(s));
    return run;
}

Result<Report> Report::build(const QStringList& inputs, const std::optional<Pipeline>& pipeline,
                             const Options& options, QStringList* warnings, const Progress& progress)
{
    if (inputs.isEmpty())
        return LocatedError {tr("no input files")};
    std::vector<RunData> data;
    QStringList kinds;
    for (qsizetype i = 0; i < inputs.size(); ++i) {
        const QString& path = inputs[i];
        const Progress part = [&](int percent) {
            return !progress || progress(int((100 * i + percent) * 9 / (10 * inputs.size())));
        };
        RunLoader::Options loadOptions;
        loadOptions.skipBadRows = options.skipBadRows;
        Result<RunData> run = RunLoader::load(path, loadOptions, warnings, part);
        if (!run)
            return run.error();
        if (pipeline) {
            // Every topic the pipeline names must be in the input, or nothing would ever complete.
            const Pipeline inInput(run->topics); // matches either spelling, by hash
            for (const QString& topic : pipeline->topics()) {
                const bool found = inInput.indexOf(topic) >= 0;
                if (!found && !run->stamps.empty())
                    return LocatedError {tr("%1: no stamps of topic %2 (it has: %3)")
                                             .arg(path, topic, run->topics.join(u", "_s))};
            }
        }
        if (run->info.name.isEmpty())
            run->info.name = QFileInfo(path).completeBaseName();
        kinds << RunLoader::kindName(RunLoader::kindOf(path));
        data.push_back(std::move(*run));
    }
    Report report;
    report.m_options = options;
    const auto cancelled = [] { return LocatedError {tr("cancelled")}; };
    if (options.join && data.size() > 1) {
        RunData joined = RunLoader::join(std::move(data));
        report.m_runs.push_back(compute(std::move(joined), pipeline, options, progress, 90));
        if (!report.m_runs.back())
            return cancelled();
        report.m_runs.back()->path = inputs.join(u", "_s);
        report.m_runs.back()->kind = kinds.first();
    } else {
        for (std::size_t i = 0; i < data.size(); ++i) {
            const int percent = 90 + int(10 * i / data.size());
            report.m_runs.push_back(compute(std::move(data[i]), pipeline, options, progress, percent));
            if (!report.m_runs.back())
                return cancelled();
            report.m_runs.back()->path = inputs[qsizetype(i)];
            report.m_runs.back()->kind = kinds[qsizetype(i)];
            if (progress && !progress(90 + int(10 * (i + 1) / data.size())))
                return cancelled();
        }
    }
    return report;
}

Report Report::fromRuns(std::vector<RunData> runs, const std::optional<Pipeline>& pipeline,
                        const Options& options)
{
    Report report;
    report.m_options = options;
    for (RunData& r : runs) {
        const QString name = r.info.name;
        report.m_runs.push_back(compute(std::move(r), pipeline, options));
        report.m_runs.back()->kind = tr("run");
        report.m_runs.back()->name = name;
    }
    return report;
}

QString Report::title() const
{
    if (!m_options.title.isEmpty())
        return m_options.title;
    // Names cut where they are laid out: a 5-million-character name took minutes in a PDF.
    if (m_runs.size() == 1)
        return (hasLatency() ? tr("Latency report: %1") : tr("Watch report: %1"))
            .arg(NameElider::elideTail(m_runs.front()->name));
    QStringList names;
    for (const auto& r : m_runs)
        names << NameElider::elideTail(r->name);
    return tr("Latency comparison: %1").arg(names.join(u", "_s));
}

bool Report::hasPipeline() const
{
    return std::any_of(m_runs.cbegin(), m_runs.cend(),
                       [](const auto& r) { return r->engine->pipeline().topicCount() > 0; });
}

bool Report::hasLatency() const
{
    return hasPipeline() || std::any_of(m_runs.cbegin(), m_runs.cend(), [](const auto& r) {
               return !r->engine->pipelineSeries().externalWithValues().isEmpty();
           });
}

bool Report::hasEvents() const
{
    return std::any_of(m_runs.cbegin(), m_runs.cend(), [](const auto& r) { return !r->events.empty(); });
}

QList<Report::Row> Report::rows() const
{
    QList<Row> out;
    QSet<QString> seen;
    for (const auto& run : m_runs) {
        const LatencyEngine& e = *run->engine;
        for (int s = 0; s < e.pipeline().stageCount(); ++s) {
            const LatencyEngine::SeriesInfo& info = e.info(e.pipelineSeries().stageSeries(s));
            if (seen.contains(info.label))
                continue;
            seen.insert(info.label);
            out.append({info.label, info.id, info.crossing, false, false});
        }
    }
    if (hasPipeline())
        out.append({tr("total"), SeriesId::ofKind(SeriesKind::Total).toString(), false, true, false});
    bool roundTrip = false;
    bool offset = false;
    bool legs = false;
    for (const auto& run : m_runs) {
        roundTrip = roundTrip || run->engine->pipelineSeries().roundTripSeries() >= 0;
        offset = offset || run->engine->pipelineSeries().clockOffsetSeries() >= 0;
        legs = legs || run->engine->pipelineSeries().thereSeries() >= 0;
    }
    if (roundTrip) {
        out.append({tr("communication, one way (half the round trip)"),
                    SeriesId::ofKind(SeriesKind::OneWay).toString(), false, false, true});
        out.append({tr("communication, round trip"), SeriesId::ofKind(SeriesKind::RoundTrip).toString(),
                    false, false, true});
    }
    if (legs) {
        out.append({tr("communication, there"), SeriesId::ofKind(SeriesKind::There).toString(), false, false, true});
        out.append({tr("communication, back"), SeriesId::ofKind(SeriesKind::Back).toString(), false, false, true});
    }
    if (offset)
        out.append(
            {tr("clock offset"), SeriesId::ofKind(SeriesKind::ClockOffset).toString(), false, false, true});
    // Measured clocks: each crossing corrected, and the asymmetry beside the paper's one way.
    bool asymmetry = false;
    for (const auto& run : m_runs) {
        const PipelineSeries& series = run->engine->pipelineSeries();
        asymmetry = asymmetry || series.asymmetrySeries() >= 0;
        for (int s = 0; s < run->engine->pipeline().stageCount(); ++s) {
            const int corrected = series.correctedSeries(s);
            if (corrected < 0 || seen.contains(series.info(corrected).id))
                continue;
            seen.insert(series.info(corrected).id);
            out.append({series.info(corrected).label, series.info(corrected).id, true, false, true});
        }
    }
    if (asymmetry)
        out.append({tr("path asymmetry (there − half the round trip)"),
                    SeriesId::ofKind(SeriesKind::Asymmetry).toString(), false, false, true});
    QList<Row> external;
    for (const auto& run : m_runs)
        for (int i : run->engine->pipelineSeries().externalWithValues()) {
            const LatencyEngine::SeriesInfo& info = run->engine->info(i);
            if (!seen.contains(info.id)) {
                seen.insert(info.id);
                external.append({info.label, info.id, false, false, false});
            }
        }
    std::sort(external.begin(), external.end(), [](const Row& a, const Row& b) { return a.label < b.label; });
    return out + external;
}

std::optional<double> Report::uncertaintyMs(const ReportRun& run, const Row& row) const
{
    const int index = run.engine->indexOf(row.seriesId);
    return index < 0 ? std::nullopt : run.engine->pipelineSeries().uncertaintyMs(index);
}

std::optional<LatencyStats> Report::stats(const ReportRun& run, const Row& row) const
{
    const LatencyEngine& e = *run.engine;
    if (const std::optional<SeriesId> id = SeriesId::parse(row.seriesId);
        id && id->kind == SeriesKind::Stage) {
        const int series = run.stageByLabel.value(row.label, -1); // a scan per row was quadratic
        return series < 0 ? std::nullopt : std::make_optional(e.series(series).stats());
    }
    const int index = e.indexOf(row.seriesId);
    if (index < 0)
        return std::nullopt;
    return e.series(index).stats();
}
