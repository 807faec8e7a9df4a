// SPDX-License-Identifier: MIT
#include "experimentreport.h"

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

std::optional<ExperimentReport> ExperimentReport::load(const QString& directory, QString* error,
                                                       const Progress& progress)
{
    const auto fail = [&](const QString& why) -> std::optional<ExperimentReport> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    const QDir dir(directory);
    const Result<ExperimentPlan> plan = ExperimentPlan::readFile(ExperimentFolder(directory).planPath());
    if (!plan)
        return fail(plan.error().toString());
    QString why;
    const std::optional<QList<CellStatus>> statuses = ExperimentFolder(directory).readState(*plan, &why);
    if (!statuses)
        return fail(why);

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
                return fail(tr("cancelled"));
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

std::optional<QList<Statistic>> ExperimentReport::parseStatistics(const QString& list, QString* error)
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
        else {
            if (error)
                *error = tr("'%1' is not a statistic (mean, median, std, p99)").arg(n);
            return std::nullopt;
        }
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

std::optional<ShiftEstimate> ExperimentReport::shiftOf(const LatencySeries& low, const LatencySeries& high)
{
    // The values in each series' window: the last count() of those it keeps.
    const auto window = [](const LatencySeries& s) {
        const std::vector<qint64>& v = s.values();
        return std::vector<qint64>(v.end() - qsizetype(std::min<qint64>(s.count(), qint64(v.size()))),
                                   v.end());
    };
    return ShiftEstimate::of(window(low), window(high), low.msPerUnit());
}

QString ExperimentReport::shiftText(const ShiftEstimate& shift)
{
    return tr("%1 ms [%2, %3] ms, 95 %")
        .arg(formatMs(shift.shiftMs), formatMs(shift.lowMs), formatMs(shift.highMs));
}

QString ExperimentReport::differenceFinding(const QString& factor, const QString& lowLevel, double lowMs,
                                            const QString& highLevel, double highMs,
                                            const std::optional<ShiftEstimate>& shift)
{
    if (shift && !shift->significant())
        return tr("%1: no significant difference between %2 and %3: the totals shift by %4 (the means: "
                  "%5 and %6 ms)")
            .arg(factor, lowLevel, highLevel, shiftText(*shift), formatMs(lowMs), formatMs(highMs));
    QString line
        = tr("%1: the total mean is lowest at %2 (%3 ms) and highest at %4 (%5 ms), %6 ms more (%7 %)")
              .arg(factor, lowLevel, formatMs(lowMs), highLevel, formatMs(highMs), formatMs(highMs - lowMs))
              .arg(lowMs > 0 ? QString::number(qRound(100 * (highMs - lowMs) / lowMs)) : u"–"_s);
    if (shift)
        line += tr("; the totals shift by %1").arg(shiftText(*shift));
    else
        line += tr(" (too few samples for an interval)");
    return line;
}

QStringList ExperimentReport::findings() const
{
    QStringList out;
    for (const Cell& c : m_cells) {
        if (c.status.state == CellStatus::Failed)
            out << tr("Cell %1 (%2) failed: %3").arg(c.cell.id(), c.cell.label(), c.status.reason);
        else if (c.status.state != CellStatus::Complete)
            out << tr("Cell %1 (%2) is not done (%3): --resume finishes it.")
                       .arg(c.cell.id(), c.cell.label(), CellStatus::stateName(c.status.state));
        else if (!c.problem.isEmpty())
            out << tr("Cell %1 is left out: %2").arg(c.cell.id(), c.problem);
    }
    for (const ThroughputResult& t : m_throughput)
        if (t.complete && !t.points.isEmpty())
            out << (t.maxSustainableHz() > 0
                        ? tr("Throughput with %1 (%2 bytes): up to %3 Hz sustained, %4 MB/s.")
                              .arg(t.level)
                              .arg(t.payloadBytes)
                              .arg(t.maxSustainableHz())
                              .arg(formatMs(t.megabytesPerSecond()))
                        : tr("Throughput with %1 (%2 bytes): not even %3 Hz was sustained.")
                              .arg(t.level)
                              .arg(t.payloadBytes)
                              .arg(t.points.first().rateHz));
    const int total = int(m_groups.size()) - 1;
    for (const FactorTable& t : m_tables) {
        QList<const Column*> measured;
        for (const Column& c : t.columns)
            if (!c.cells.isEmpty() && std::isfinite(c.groups[total].mean))
                measured << &c;
        if (measured.size() < 2)
            continue;
        const auto [low, high]
            = std::minmax_element(measured.cbegin(), measured.cend(), [total](auto a, auto b) {
                  return a->groups[total].mean < b->groups[total].mean;
              });
        const double lo = (*low)->groups[total].mean;
        const double hi = (*high)->groups[total].mean;
        const std::optional<ShiftEstimate> shift
            = (*low)->total && (*high)->total ? shiftOf(*(*low)->total, *(*high)->total) : std::nullopt;
        if (shift && !shift->significant()) {
            out << differenceFinding(t.factor, (*low)->level, lo, (*high)->level, hi, shift) + u'.';
            continue; // nothing moved that the samples can tell apart from chance
        }
        // The group that moved most between the two levels.
        int most = -1;
        double moved = 0;
        for (int g = 0; g < total; ++g) {
            const double d = (*high)->groups[g].mean - (*low)->groups[g].mean;
            if (std::isfinite(d) && std::abs(d) > std::abs(moved)) {
                moved = d;
                most = g;
            }
        }
        QString line = differenceFinding(t.factor, (*low)->level, lo, (*high)->level, hi, shift);
        if (most >= 0)
            line += tr("; most of it in %1 (%2 ms).").arg(m_groups[most].label, formatMs(moved));
        else
            line += u'.';
        out << line;
        // What the bridge notes already explain.
        const auto levelMean = [&](const QString& level, int group) {
            for (const Column* c : measured)
                if (c->level == level)
                    return c->groups[group].mean;
            return LatencyStats::nan();
        };
        if (t.factor == u"qos"_s
            && levelMean(u"0"_s, total) < std::max(levelMean(u"1"_s, total), levelMean(u"2"_s, total)))
            out << tr("QoS 1 and 2 wait for the broker's acknowledgements (PUBACK; PUBREC, PUBREL, PUBCOMP), "
                      "and a client without TCP_NODELAY (Paho) can wait for a delayed ACK of up to 40 ms "
                      "on each.");
        if (t.factor == u"announce"_s && levelMean(u"once"_s, total) < levelMean(u"every_message"_s, total))
            out << tr("Announcing the type before every message (mqtt_client 2.2.1) puts a small publish in "
                      "front of each message; without TCP_NODELAY the message then waits for the delayed ACK "
                      "of the first, up to 40 ms.");
        if (t.factor == u"payload"_s && measured.size() >= 2 && m_groups.first().label == u"interfaces"_s) {
            const Column* smallest = measured.first();
            const Column* next = measured.at(1);
            if (smallest->groups[0].mean > next->groups[0].mean)
                out << tr("The smallest payload (%1) is slower through the interfaces than %2 (%3 against %4 "
                          "ms): small messages wait for delayed ACKs where Nagle's algorithm holds them.")
                           .arg(smallest->level, next->level, formatMs(smallest->groups[0].mean),
                                formatMs(next->groups[0].mean));
        }
    }
    return out;
}

QString ExperimentReport::rosText() const
{
    return m_plan.ros == 2 ? tr("ROS 2 (DDS, a private domain)") : tr("ROS 1");
}

QByteArray ExperimentReport::exportTo(const QString& path, ReportFormats::Format format,
                                      const QList<Statistic>& statistics, QString* error) const
{
    // Written to a file, the Markdown links each factor's ECDF, written beside it as SVG.
    QString prefix;
    if (format == ReportFormats::Format::Markdown && !path.isEmpty()) {
        prefix = figurePrefixOf(path);
        if (!writeFigures(prefix, error))
            return {};
    }
    const QByteArray bytes = render(format, statistics, prefix);
    if (!path.isEmpty() && !AtomicFile::write(path, bytes, error, false))
        return {};
    return bytes;
}

bool ExperimentReport::writeFigures(const QString& figurePrefix, QString* error) const
{
    for (int t = 0; t < int(m_tables.size()); ++t)
        if (const QByteArray svg = ecdfSvg(t); !svg.isEmpty()
            && !AtomicFile::write(figurePath(figurePrefix, m_tables[t].factor), svg, error, false))
            return false;
    return true;
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
