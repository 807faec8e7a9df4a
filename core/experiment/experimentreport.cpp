// SPDX-License-Identifier: MIT
#include "experimentreport.h"

#include "experiment/experimentfindings.h"
#include "files/atomicfile.h"
#include "experiment/experimentfolder.h"
#include "latency/latencyengine.h"
#include "latency/latencyseries.h"
#include "latency/palette.h"
#include "record/runfile.h"
#include "report/ecdfsvg.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
using Statistic = ExperimentReport::Statistic;

/// The stage groups of a pipeline, in the order the paper's tables have them.
QList<ExperimentReport::Group> groupsOf(const Pipeline& p)
{
    QList<ExperimentReport::Group> groups;
    const auto add = [&](const QString& label, int stage) {
        for (auto& g : groups)
            if (g.label == label) {
                g.stages << stage;
                return;
            }
        groups.append({label, {stage}, false});
    };
    QList<int> interfaces;
    QList<int> transfers;
    for (int s = 0; s < p.stageCount(); ++s) {
        const QString a = p.component(s);
        if (p.isCrossing(s)) {
            // Both ways in one group, named in the order the pipeline meets the hosts.
            QString from = p.host(s);
            QString to = p.host(s + 1);
            const auto firstOf = [&p](const QString& host) {
                for (int t = 0; t < p.topicCount(); ++t)
                    if (p.host(t) == host)
                        return t;
                return p.topicCount();
            };
            if (firstOf(to) < firstOf(from))
                std::swap(from, to);
            add(u"%1 ↔ %2"_s.arg(from, to), s);
        } else if (a == p.component(s + 1) && !a.isEmpty() && p.topics()[s] != p.topics()[s + 1]) {
            if (a.contains(u"mqtt_interface"_s) || a.contains(u"bridge"_s))
                interfaces << s;
            else
                add(a, s);
        } else {
            transfers << s;
        }
    }
    if (!interfaces.isEmpty())
        groups.prepend({u"interfaces"_s, interfaces, false}); // stable: keys of the JSON
    if (!transfers.isEmpty())
        groups.append({u"transfers"_s, transfers, false});
    groups.append({u"total"_s, {}, true});
    return groups;
}

/// Replays a complete cell's run: its groups' and stages' statistics into `cell`, and per group
/// the samples' values in ns (exact statistics, as the engine's), which are returned.
std::vector<LatencySeries> replay(const RunData& run, const QList<ExperimentReport::Group>& groups, int stageCount,
                                  ExperimentReport::Cell* cell)
{
    std::vector<LatencySeries> series(std::size_t(groups.size()));
    std::vector<LatencySeries> stages(static_cast<std::size_t>(stageCount));
    for (LatencySeries& s : series)
        s.setWindow(0); // every sample of the run, not the last 600
    for (LatencySeries& s : stages)
        s.setWindow(0);
    LatencyEngine engine(run.info.pipeline);
    engine.setWindow(0);
    if (run.info.timeoutNs > 0)
        engine.setTimeoutNs(run.info.timeoutNs);
    engine.setSampleListener([&series, &stages, &groups](qint64, const std::vector<qint64>& t) {
        for (std::size_t s = 0; s < stages.size() && s + 1 < t.size(); ++s)
            stages[s].append(t[s + 1] - t[s]);
        for (qsizetype g = 0; g < groups.size(); ++g) {
            qint64 sum = groups[g].total ? t.back() - t.front() : 0;
            for (int s : groups[g].stages)
                sum += t[std::size_t(s) + 1] - t[std::size_t(s)];
            series[std::size_t(g)].append(sum);
        }
    });
    run.replay(engine);
    for (const LatencySeries& s : series)
        cell->groups << s.stats();
    for (const LatencySeries& s : stages)
        cell->stages << s.stats();
    cell->total = std::make_shared<const LatencySeries>(series.back()); // the total is last
    return series;
}

QJsonObject statsJson(const LatencyStats& s)
{
    const auto n = [](double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); };
    return {{u"count"_s, double(s.count)}, {u"mean"_s, n(s.mean)}, {u"median"_s, n(s.median)},
            {u"std"_s, n(s.std)},          {u"min"_s, n(s.min)},   {u"max"_s, n(s.max)},
            {u"p99"_s, n(s.p99)}};
}

QJsonArray throughputJson(const QList<ThroughputResult>& results)
{
    QJsonArray out;
    for (const ThroughputResult& r : results)
        out.append(r.toJson());
    return out;
}

QString fileSafe(const QString& s)
{
    QString out;
    for (const QChar c : s)
        out += c.isLetterOrNumber() || c == u'-' || c == u'_' ? c : u'_';
    return out;
}
} // namespace

QString ExperimentReport::formatMs(double v)
{
    if (!std::isfinite(v))
        return u"–"_s;
    return QString::number(v, 'f', std::abs(v) < 1 ? 2 : 1);
}

QString ExperimentReport::levelsText(const ExperimentCell& c)
{
    QStringList parts;
    for (const auto& [factor, level] : c.levels)
        parts << factor + u'=' + level;
    return parts.join(u", "_s);
}

bool ExperimentReport::hasMethodTable() const
{
    return m_plan.factors.contains(u"bridge"_s) && !m_stageLabels.isEmpty();
}

QString ExperimentReport::figurePath(const QString& figurePrefix, const QString& factor)
{
    return figurePrefix + u'-' + fileSafe(factor) + u"-ecdf.svg"_s;
}

QByteArray ExperimentReport::ecdfSvg(int table, int width, int height) const
{
    if (table < 0 || table >= m_tables.size())
        return {};
    QList<EcdfSvg::Curve> curves;
    const FactorTable& t = m_tables[table];
    for (const Column& c : t.columns)
        if (c.total && c.total->count() > 0)
            curves.append({t.factor + u' ' + c.level, seriesColor(int(curves.size())), c.total.get()});
    if (curves.isEmpty())
        return {};
    return EcdfSvg::render(curves, width, height, tr("Total latency by %1").arg(t.factor));
}

bool ExperimentReport::isExperiment(const QString& path)
{
    return ExperimentFolder::isExperiment(path);
}

Result<ExperimentReport> ExperimentReport::load(const QString& directory, const Progress& progress)
{
    const QDir dir(directory);
    const Result<ExperimentPlan> plan = ExperimentPlan::readFile(ExperimentFolder(directory).planPath());
    if (!plan)
        return plan.error();
    const Result<QList<CellStatus>> statuses = ExperimentFolder(directory).readState(*plan);
    if (!statuses)
        return statuses.error();

    ExperimentReport r;
    r.m_plan = *plan;
    if (r.m_plan.name.isEmpty())
        r.m_plan.name = dir.dirName();
    r.m_dir = directory;
    std::optional<Pipeline> pipeline;
    // Per cell and group the samples' group values, in ns (exact statistics, as the engine's).
    std::vector<std::vector<LatencySeries>> values(std::size_t(plan->cells.size()));
    for (qsizetype i = 0; i < plan->cells.size(); ++i) {
        Cell cell {plan->cells[i], (*statuses)[i], {}, {}, {}, {}};
        if (cell.status.state == CellStatus::Complete) {
            const Progress part = [&](int percent) {
                return !progress || progress(int((100 * i + percent) / plan->cells.size()));
            };
            const Result<RunData> run = RunFile::read(dir.filePath(cell.status.run), part);
            if (!run && progress && !progress(int(100 * i / plan->cells.size())))
                return LocatedError {tr("cancelled")};
            if (!run) {
                cell.problem = run.error().toString();
            } else if (pipeline && run->info.pipeline.topics() != pipeline->topics()) {
                cell.problem = tr("its pipeline differs from the first cell's");
            } else {
                if (!pipeline) {
                    pipeline = run->info.pipeline;
                    r.m_groups = groupsOf(*pipeline);
                    for (int s = 0; s < pipeline->stageCount(); ++s)
                        r.m_stageLabels << pipeline->stageLabel(s);
                }
                values[std::size_t(i)] = replay(*run, r.m_groups, pipeline->stageCount(), &cell);
            }
        }
        r.m_cells << cell;
    }

    r.buildTables(values);
    r.m_throughput = ExperimentFolder(directory).readThroughput();
    return r;
}

void ExperimentReport::buildTables(const std::vector<std::vector<LatencySeries>>& values)
{
    // A table per factor: its levels in the order the cells have them, each pooling its cells.
    for (const QString& factor : std::as_const(m_plan.factors)) {
        FactorTable table {factor, {}};
        for (qsizetype i = 0; i < m_cells.size(); ++i) {
            QString level;
            for (const auto& [f, l] : m_cells[i].cell.levels)
                if (f == factor)
                    level = l;
            if (level.isEmpty())
                continue;
            auto column = std::find_if(table.columns.begin(), table.columns.end(),
                                       [&](const Column& c) { return c.level == level; });
            if (column == table.columns.end()) {
                table.columns.append({level, {}, {}, {}});
                column = table.columns.end() - 1;
            }
            if (!m_cells[i].groups.isEmpty())
                column->cells << int(i);
        }
        for (Column& column : table.columns) {
            for (qsizetype g = 0; g < m_groups.size(); ++g) {
                LatencySeries pooled;
                pooled.setWindow(0);
                for (int i : std::as_const(column.cells))
                    for (qint64 v : values[std::size_t(i)][std::size_t(g)].values())
                        pooled.append(v);
                column.groups << pooled.stats();
                if (m_groups[g].total && !column.cells.isEmpty())
                    column.total = std::make_shared<const LatencySeries>(std::move(pooled));
            }
        }
        m_tables << table;
    }
}

Result<QList<Statistic>> ExperimentReport::parseStatistics(const QString& list)
{
    QList<Statistic> out;
    for (const QString& name : list.split(u',', Qt::SkipEmptyParts)) {
        const QString n = name.trimmed();
        if (n == u"mean"_s)
            out << Statistic::Mean;
        else if (n == u"median"_s)
            out << Statistic::Median;
        else if (n == u"std"_s)
            out << Statistic::Std;
        else if (n == u"p99"_s)
            out << Statistic::P99;
        else
            return LocatedError {tr("'%1' is not a statistic (mean, median, std, p99)").arg(n)};
    }
    if (out.isEmpty())
        out << Statistic::Mean;
    return out;
}

QString ExperimentReport::statisticName(Statistic s)
{
    switch (s) {
    case Statistic::Mean:
        return tr("mean");
    case Statistic::Median:
        return tr("median");
    case Statistic::Std:
        return tr("std");
    case Statistic::P99:
        return tr("p99");
    }
    return {};
}

double ExperimentReport::value(const LatencyStats& s, Statistic statistic)
{
    switch (statistic) {
    case Statistic::Mean:
        return s.mean;
    case Statistic::Median:
        return s.median;
    case Statistic::Std:
        return s.std;
    case Statistic::P99:
        return s.p99;
    }
    return LatencyStats::nan();
}

QStringList ExperimentReport::findings() const
{
    return ExperimentFindings::of(*this);
}

QString ExperimentReport::rosText() const
{
    return m_plan.ros == 2 ? tr("ROS 2 (DDS, a private domain)") : tr("ROS 1");
}

Result<QByteArray> ExperimentReport::exportTo(const QString& path, ReportFormats::Format format,
                                              const QList<Statistic>& statistics) const
{
    // Written to a file, the Markdown links each factor's ECDF, written beside it as SVG.
    QString prefix;
    if (format == ReportFormats::Format::Markdown && !path.isEmpty()) {
        prefix = figurePrefixOf(path);
        if (Status written = writeFigures(prefix); !written)
            return written.error();
    }
    const QByteArray bytes = render(format, statistics, prefix);
    if (path.isEmpty())
        return bytes;
    if (Status written = AtomicFile::write(path, bytes, false); !written)
        return written.error();
    return bytes;
}

Status ExperimentReport::writeFigures(const QString& figurePrefix) const
{
    for (int t = 0; t < int(m_tables.size()); ++t) {
        const QByteArray svg = ecdfSvg(t);
        if (svg.isEmpty())
            continue;
        if (Status written = AtomicFile::write(figurePath(figurePrefix, m_tables[t].factor), svg, false);
            !written)
            return written;
    }
    return {};
}

QString ExperimentReport::figurePrefixOf(const QString& reportPath)
{
    const QFileInfo file(reportPath);
    return file.dir().filePath(file.completeBaseName());
}

QByteArray ExperimentReport::toJson() const
{
    QJsonArray groups;
    for (const Group& g : m_groups) {
        QJsonArray stages;
        for (int s : g.stages)
            stages.append(s);
        groups.append(QJsonObject {{u"label"_s, g.label}, {u"stages"_s, stages}, {u"total"_s, g.total}});
    }
    const auto groupStats = [this](const QList<LatencyStats>& stats) {
        QJsonObject o;
        for (qsizetype g = 0; g < stats.size() && g < m_groups.size(); ++g)
            o.insert(m_groups[g].label, statsJson(stats[g]));
        return o;
    };
    QJsonArray cells;
    for (const Cell& c : m_cells) {
        QJsonObject o {{u"id"_s, c.cell.id()},
                       {u"levels"_s, RunInfo::levelsJson(c.cell.levels)},
                       {u"ros"_s, m_plan.ros},
                       {u"state"_s, CellStatus::stateName(c.status.state)},
                       {u"run"_s, c.status.run},
                       {u"groups"_s, groupStats(c.groups)}};
        if (!c.status.reason.isEmpty())
            o.insert(u"reason"_s, c.status.reason);
        if (!c.problem.isEmpty())
            o.insert(u"problem"_s, c.problem);
        cells.append(o);
    }
    QJsonArray tables;
    for (const FactorTable& t : m_tables) {
        QJsonArray columns;
        for (const Column& c : t.columns) {
            QJsonArray ids;
            for (int i : c.cells)
                ids.append(m_cells[i].cell.id());
            columns.append(
                QJsonObject {{u"level"_s, c.level}, {u"cells"_s, ids}, {u"groups"_s, groupStats(c.groups)}});
        }
        tables.append(QJsonObject {{u"factor"_s, t.factor}, {u"columns"_s, columns}});
    }
    const QJsonObject root {{u"experiment"_s, m_plan.name},
                            {u"samples_per_cell"_s, m_plan.samples},
                            {u"factors"_s, QJsonArray::fromStringList(m_plan.factors)},
                            {u"groups"_s, groups},
                            {u"tables"_s, tables},
                            {u"cells"_s, cells},
                            {u"throughput"_s, throughputJson(m_throughput)},
                            {u"findings"_s, QJsonArray::fromStringList(findings())}};
    return QJsonDocument(root).toJson();
}

QString ExperimentReport::toCsv() const
{
    QString csv = u"cell,levels,state,group,count,mean_ms,median_ms,std_ms,min_ms,max_ms,p99_ms,ros\n"_s;
    const auto field = [](QString s) {
        if (s.contains(u',') || s.contains(u'"') || s.contains(u'\n'))
            s = u"\""_s + s.replace(u"\""_s, u"\"\""_s) + u"\""_s;
        return s;
    };
    const auto n = [](double v) { return std::isfinite(v) ? QString::number(v, 'g', 12) : QString(); };
    for (const Cell& c : m_cells) {
        for (qsizetype g = 0; g < c.groups.size(); ++g) {
            const LatencyStats& s = c.groups[g];
            csv += QStringList {field(c.cell.id()),
                                field(levelsText(c.cell)),
                                CellStatus::stateName(c.status.state),
                                field(m_groups[g].label),
                                QString::number(s.count),
                                n(s.mean),
                                n(s.median),
                                n(s.std),
                                n(s.min),
                                n(s.max),
                                n(s.p99),
                                QString::number(m_plan.ros)}
                       .join(u',')
                + u'\n';
        }
    }
    return csv;
}
