// SPDX-License-Identifier: MIT
#include "experimentreport.h"

#include "base/atomicfile.h"
#include "latency/latencyengine.h"
#include "latency/latencyseries.h"
#include "latency/palette.h"
#include "record/runfile.h"
#include "report/ecdfsvg.h"
#include "report/reportpdf.h"

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

QString number(double v)
{
    if (!std::isfinite(v))
        return u"–"_s;
    return QString::number(v, 'f', std::abs(v) < 1 ? 2 : 1);
}

QString levelsText(const ExperimentCell& c)
{
    QStringList parts;
    for (const auto& [factor, level] : c.levels)
        parts << factor + u'=' + level;
    return parts.join(u", "_s);
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

QString texEscaped(QString s)
{
    s.replace(u"\\"_s, u"\\textbackslash{}"_s);
    for (const QString& c : {u"_"_s, u"%"_s, u"&"_s, u"#"_s, u"$"_s, u"{"_s, u"}"_s})
        s.replace(c, u"\\"_s + c);
    s.replace(u"↔"_s, u"$\\leftrightarrow$"_s);
    return s;
}
/// The paper's Table I: every stage a row, every complete cell a column, means; the total last.
struct MethodTable
{
    QStringList columns; ///< the cells' labels
    QList<std::pair<QString, QStringList>> rows; ///< (stage, mean per column); the last is the total
};

MethodTable methodTable(const ExperimentReport& r)
{
    MethodTable t;
    QList<const ExperimentReport::Cell*> cells;
    for (const ExperimentReport::Cell& c : r.cells())
        if (c.stages.size() == r.stageLabels().size() && !c.groups.isEmpty()) {
            cells << &c;
            t.columns << c.cell.label();
        }
    for (qsizetype s = 0; s < r.stageLabels().size(); ++s) {
        QStringList values;
        for (const ExperimentReport::Cell* c : cells)
            values << number(c->stages[s].mean);
        t.rows.append({r.stageLabels()[s], values});
    }
    QStringList totals;
    for (const ExperimentReport::Cell* c : cells)
        totals << number(c->groups.last().mean);
    t.rows.append({ExperimentReport::tr("total"), totals});
    return t;
}

QString fileSafe(const QString& s)
{
    QString out;
    for (const QChar c : s)
        out += c.isLetterOrNumber() || c == u'-' || c == u'_' ? c : u'_';
    return out;
}
} // namespace

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
    return QFileInfo(path).isDir() && QFile::exists(QDir(path).filePath(ExperimentRunner::stateFileName()));
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
    QString why;
    std::optional<ExperimentPlan> plan
        = ExperimentPlan::load(dir.filePath(ExperimentRunner::planFileName()), &why);
    if (!plan)
        return fail(why);
    const std::optional<QList<CellStatus>> statuses = ExperimentRunner::readState(directory, *plan, &why);
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
            const std::optional<RunData> run = RunFile::read(dir.filePath(cell.status.run), &why, part);
            if (!run && progress && !progress(int(100 * i / plan->cells.size())))
                return fail(tr("cancelled"));
            if (!run) {
                cell.problem = why;
            } else if (pipeline && run->info.pipeline.topics() != pipeline->topics()) {
                cell.problem = tr("its pipeline differs from the first cell's");
            } else {
                if (!pipeline) {
                    pipeline = run->info.pipeline;
                    r.m_groups = groupsOf(*pipeline);
                    for (int s = 0; s < pipeline->stageCount(); ++s)
                        r.m_stageLabels << pipeline->stageLabel(s);
                }
                std::vector<LatencySeries> series(std::size_t(r.m_groups.size()));
                std::vector<LatencySeries> stages(std::size_t(pipeline->stageCount()));
                for (LatencySeries& s : series)
                    s.setWindow(0); // every sample of the run, not the last 600
                for (LatencySeries& s : stages)
                    s.setWindow(0);
                LatencyEngine engine(run->info.pipeline);
                engine.setWindow(0);
                if (run->info.timeoutNs > 0)
                    engine.setTimeoutNs(run->info.timeoutNs);
                const QList<Group>& groups = r.m_groups;
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
                run->replay(engine);
                for (const LatencySeries& s : series)
                    cell.groups << s.stats();
                for (const LatencySeries& s : stages)
                    cell.stages << s.stats();
                cell.total = std::make_shared<const LatencySeries>(series.back()); // the total is last
                values[std::size_t(i)] = std::move(series);
            }
        }
        r.m_cells << cell;
    }

    // A table per factor: its levels in the order the cells have them, each pooling its cells.
    for (const QString& factor : std::as_const(r.m_plan.factors)) {
        FactorTable table {factor, {}};
        for (qsizetype i = 0; i < r.m_cells.size(); ++i) {
            QString level;
            for (const auto& [f, l] : r.m_cells[i].cell.levels)
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
            if (!r.m_cells[i].groups.isEmpty())
                column->cells << int(i);
        }
        for (Column& column : table.columns) {
            for (qsizetype g = 0; g < r.m_groups.size(); ++g) {
                LatencySeries pooled;
                pooled.setWindow(0);
                for (int i : std::as_const(column.cells))
                    for (qint64 v : values[std::size_t(i)][std::size_t(g)].values())
                        pooled.append(v);
                column.groups << pooled.stats();
                if (r.m_groups[g].total && !column.cells.isEmpty())
                    column.total = std::make_shared<const LatencySeries>(std::move(pooled));
            }
        }
        r.m_tables << table;
    }
    r.m_throughput = ExperimentRunner::readThroughput(directory);
    return r;
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
                              .arg(number(t.megabytesPerSecond()))
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
        QString line
            = tr("%1: the total mean is lowest at %2 (%3 ms) and highest at %4 (%5 ms), %6 ms more (%7 %)")
                  .arg(t.factor, (*low)->level, number(lo), (*high)->level, number(hi), number(hi - lo))
                  .arg(lo > 0 ? QString::number(qRound(100 * (hi - lo) / lo)) : u"–"_s);
        if (most >= 0)
            line += tr("; most of it in %1 (%2 ms).").arg(m_groups[most].label, number(moved));
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
                           .arg(smallest->level, next->level, number(smallest->groups[0].mean),
                                number(next->groups[0].mean));
        }
    }
    return out;
}

QString ExperimentReport::rosText() const
{
    return m_plan.ros == 2 ? tr("ROS 2 (DDS, a private domain)") : tr("ROS 1");
}

QString ExperimentReport::toMarkdown(const QList<Statistic>& statistics, const QString& figurePrefix) const
{
    int complete = 0;
    int failed = 0;
    for (const Cell& c : m_cells) {
        complete += c.status.state == CellStatus::Complete;
        failed += c.status.state == CellStatus::Failed;
    }
    QString md = u"# "_s + tr("Experiment report: %1").arg(m_plan.name) + u"\n\n"_s;
    md += tr("%1 cells: %2 complete, %3 failed; %4 samples a cell after %5 of warm-up. Latencies in ms; a "
             "group's value is the sum of its stages in each sample, a level pools the samples of its cells.")
              .arg(m_cells.size())
              .arg(complete)
              .arg(failed)
              .arg(m_plan.samples)
              .arg(m_plan.warmup)
        + u"\n\n"_s;
    for (const FactorTable& t : m_tables) {
        for (Statistic st : statistics) {
            md += u"## %1 (%2)\n\n"_s.arg(t.factor, statisticName(st));
            md += u"| "_s + tr("stage group");
            for (const Column& c : t.columns)
                md += u" | "_s + c.level;
            md += u" |\n| ---"_s + QString(u" | ---:"_s).repeated(t.columns.size()) + u" |\n"_s;
            for (qsizetype g = 0; g < m_groups.size(); ++g) {
                const bool total = m_groups[g].total;
                md += u"| "_s + (total ? u"**"_s + m_groups[g].label + u"**"_s : m_groups[g].label);
                for (const Column& c : t.columns) {
                    const QString v = c.cells.isEmpty() ? u"–"_s : number(value(c.groups[g], st));
                    md += u" | "_s + (total ? u"**"_s + v + u"**"_s : v);
                }
                md += u" |\n"_s;
            }
            md += u"\n"_s;
        }
        QStringList sources;
        for (const Column& c : t.columns) {
            QStringList ids;
            for (int i : c.cells)
                ids << m_cells[i].cell.id();
            sources << u"%1: %2"_s.arg(c.level, ids.isEmpty() ? tr("no complete cell") : ids.join(u", "_s));
        }
        md += tr("Cells: %1.").arg(sources.join(u"; "_s)) + u"\n\n"_s;
        if (!figurePrefix.isEmpty() && !ecdfSvg(int(&t - m_tables.data())).isEmpty())
            md += u"![%1](%2)\n\n"_s.arg(tr("Total latency by %1").arg(t.factor),
                                         QFileInfo(figurePath(figurePrefix, t.factor)).fileName());
    }
    if (hasMethodTable()) {
        const MethodTable m = methodTable(*this);
        md += u"## "_s + tr("Per stage (Table I layout, mean, ms)") + u"\n\n| "_s + tr("stage") + u" | "_s
            + m.columns.join(u" | "_s) + u" |\n| ---"_s + QString(u" | ---:"_s).repeated(m.columns.size())
            + u" |\n"_s;
        for (qsizetype i = 0; i < m.rows.size(); ++i) {
            const bool total = i + 1 == m.rows.size();
            QStringList values = m.rows[i].second;
            if (total)
                for (QString& v : values)
                    v = u"**"_s + v + u"**"_s;
            md += u"| "_s + (total ? u"**"_s + m.rows[i].first + u"**"_s : m.rows[i].first) + u" | "_s
                + values.join(u" | "_s) + u" |\n"_s;
        }
        md += u"\n"_s;
    }
    if (!m_throughput.isEmpty()) {
        md += u"## "_s + tr("Throughput") + u"\n\n"_s
            + tr("The highest publishing rate sustained (every sample through in its window, none dropped, "
                 "the total's median within twice the lowest rate's plus 5 ms), and the payload it carries.")
            + u"\n\n| "_s + tr("payload") + u" | "_s + tr("bytes") + u" | "_s + tr("highest rate (Hz)")
            + u" | MB/s | "_s + tr("rates tried (samples/expected, median total ms)")
            + u" |\n| --- | ---: | ---: | ---: | --- |\n"_s;
        for (const ThroughputResult& t : m_throughput) {
            QStringList tried;
            for (const ThroughputPoint& p : t.points)
                tried << u"%1 Hz: %2/%3, %4%5"_s.arg(p.rateHz)
                             .arg(p.samples)
                             .arg(p.expected)
                             .arg(number(p.p50Ms))
                             .arg(p.sustainable ? QString() : u" ✗"_s);
            md += u"| %1 | %2 | %3 | %4 | %5 |\n"_s.arg(t.level)
                      .arg(t.payloadBytes)
                      .arg(t.maxSustainableHz() > 0 ? QString::number(t.maxSustainableHz()) : u"–"_s)
                      .arg(number(t.megabytesPerSecond()))
                      .arg(tried.join(u"; "_s) + (t.complete ? QString() : u" …"_s));
        }
        md += u"\n"_s;
    }
    md += u"## "_s + tr("Cells") + u"\n\n| "_s + tr("cell") + u" | "_s + tr("levels") + u" | "_s + tr("ROS")
        + u" | "_s + tr("state") + u" | "_s + tr("samples") + u" | "_s + tr("total mean") + u" | "_s + tr("run")
        + u" |\n"_s + u"| --- | --- | --- | --- | ---: | ---: | --- |\n"_s;
    for (const Cell& c : m_cells)
        md += u"| %1 | %2 | %3 | %4 | %5 | %6 | %7 |\n"_s.arg(
            c.cell.id(), levelsText(c.cell), rosText(), CellStatus::stateName(c.status.state),
            c.groups.isEmpty() ? u"–"_s : QString::number(c.groups.last().count),
            c.groups.isEmpty() ? u"–"_s : number(c.groups.last().mean),
            c.status.state == CellStatus::Complete ? u"`"_s + c.status.run + u"`"_s : u"–"_s);
    const QStringList f = findings();
    if (!f.isEmpty()) {
        md += u"\n## "_s + tr("Findings") + u"\n\n"_s;
        for (const QString& line : f)
            md += u"- "_s + line + u'\n';
    }
    return md;
}

QString ExperimentReport::toTex(const QList<Statistic>& statistics) const
{
    QString tex = u"%% "_s + tr("Experiment report: %1").arg(m_plan.name) + u" (booktabs)\n"_s;
    for (const FactorTable& t : m_tables) {
        for (Statistic st : statistics) {
            tex += u"\\begin{table}\n\\centering\n\\caption{%1: %2 latencies [ms]}\n\\begin{tabular}{l%3}\n\\toprule\n"_s
                       .arg(texEscaped(t.factor), statisticName(st),
                            QString(u"r"_s).repeated(t.columns.size()));
            tex += tr("stage group");
            for (const Column& c : t.columns)
                tex += u" & "_s + texEscaped(c.level);
            tex += u" \\\\\n\\midrule\n"_s;
            for (qsizetype g = 0; g < m_groups.size(); ++g) {
                const bool total = m_groups[g].total;
                if (total)
                    tex += u"\\midrule\n"_s;
                tex += total ? u"\\textbf{%1}"_s.arg(texEscaped(m_groups[g].label))
                             : texEscaped(m_groups[g].label);
                for (const Column& c : t.columns) {
                    const QString v = c.cells.isEmpty() ? u"--"_s : number(value(c.groups[g], st));
                    tex += u" & "_s + (total ? u"\\textbf{%1}"_s.arg(v) : v);
                }
                tex += u" \\\\\n"_s;
            }
            tex += u"\\bottomrule\n\\end{tabular}\n\\end{table}\n\n"_s;
        }
    }
    if (hasMethodTable()) {
        const MethodTable m = methodTable(*this);
        tex += u"\\begin{table}\n\\centering\n\\caption{%1}\n\\begin{tabular}{l%2}\n\\toprule\n"_s.arg(
            texEscaped(tr("Mean latencies [ms] by method")), QString(u"r"_s).repeated(m.columns.size()));
        tex += tr("stage");
        for (const QString& c : m.columns)
            tex += u" & "_s + texEscaped(c);
        tex += u" \\\\\n\\midrule\n"_s;
        for (qsizetype i = 0; i < m.rows.size(); ++i) {
            const bool total = i + 1 == m.rows.size();
            if (total)
                tex += u"\\midrule\n"_s;
            tex += total ? u"\\textbf{%1}"_s.arg(texEscaped(m.rows[i].first)) : texEscaped(m.rows[i].first);
            for (const QString& v : m.rows[i].second)
                tex += u" & "_s + (total ? u"\\textbf{%1}"_s.arg(v) : v);
            tex += u" \\\\\n"_s;
        }
        tex += u"\\bottomrule\n\\end{tabular}\n\\end{table}\n\n"_s;
    }
    return tex;
}

QString ExperimentReport::toHtml(const QList<Statistic>& statistics, bool figures) const
{
    // The Markdown's tables as HTML: one page, no scripts, every text escaped.
    QString html
        = u"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%1</title>"
          u"<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}"
          u"table{border-collapse:collapse;margin:1em 0}td,th{padding:.2em .8em;border-bottom:1px solid #ccc}"
          u"td.n{text-align:right}</style></head><body>\n"_s.arg(
              tr("Experiment report: %1").arg(m_plan.name).toHtmlEscaped());
    html += u"<h1>%1</h1>\n"_s.arg(tr("Experiment report: %1").arg(m_plan.name).toHtmlEscaped());
    for (const FactorTable& t : m_tables) {
        for (Statistic st : statistics) {
            html += u"<h2>%1 (%2, ms)</h2>\n<table cellpadding=\"3\" cellspacing=\"0\"><tr><th>%3</th>"_s.arg(
                t.factor.toHtmlEscaped(), statisticName(st), tr("stage group"));
            for (const Column& c : t.columns)
                html += u"<th>%1</th>"_s.arg(c.level.toHtmlEscaped());
            html += u"</tr>\n"_s;
            for (qsizetype g = 0; g < m_groups.size(); ++g) {
                const bool total = m_groups[g].total;
                html += u"<tr><td>%1</td>"_s.arg(total ? u"<b>%1</b>"_s.arg(m_groups[g].label.toHtmlEscaped())
                                                       : m_groups[g].label.toHtmlEscaped());
                for (const Column& c : t.columns) {
                    const QString v = c.cells.isEmpty() ? u"–"_s : number(value(c.groups[g], st));
                    html += u"<td class=\"n\" align=\"right\">%1</td>"_s.arg(total ? u"<b>%1</b>"_s.arg(v)
                                                                                   : v);
                }
                html += u"</tr>\n"_s;
            }
            html += u"</table>\n"_s;
        }
        if (figures)
            html += u"<figure>%1</figure>\n"_s.arg(QString::fromUtf8(ecdfSvg(int(&t - m_tables.data()))));
    }
    if (hasMethodTable()) {
        const MethodTable m = methodTable(*this);
        html += u"<h2>%1</h2>\n<table cellpadding=\"3\" cellspacing=\"0\"><tr><th>%2</th>"_s.arg(
            tr("Per stage (Table I layout, mean, ms)").toHtmlEscaped(), tr("stage").toHtmlEscaped());
        for (const QString& c : m.columns)
            html += u"<th>%1</th>"_s.arg(c.toHtmlEscaped());
        html += u"</tr>\n"_s;
        for (qsizetype i = 0; i < m.rows.size(); ++i) {
            const bool total = i + 1 == m.rows.size();
            const auto bold = [total](const QString& v) { return total ? u"<b>%1</b>"_s.arg(v) : v; };
            html += u"<tr><td>%1</td>"_s.arg(bold(m.rows[i].first.toHtmlEscaped()));
            for (const QString& v : m.rows[i].second)
                html += u"<td class=\"n\" align=\"right\">%1</td>"_s.arg(bold(v));
            html += u"</tr>\n"_s;
        }
        html += u"</table>\n"_s;
    }
    if (!m_throughput.isEmpty()) {
        html
            += u"<h2>%1</h2>\n<table cellpadding=\"3\" cellspacing=\"0\"><tr><th>%2</th><th>%3</th><th>%4</th><th>MB/s</th></tr>\n"_s
                   .arg(tr("Throughput"), tr("payload"), tr("bytes"), tr("highest rate (Hz)"));
        for (const ThroughputResult& t : m_throughput)
            html
                += u"<tr><td>%1</td><td class=\"n\" align=\"right\">%2</td><td class=\"n\" align=\"right\">%3</td><td class=\"n\" align=\"right\">%4</td></tr>\n"_s
                       .arg(t.level.toHtmlEscaped())
                       .arg(t.payloadBytes)
                       .arg(t.maxSustainableHz() > 0 ? QString::number(t.maxSustainableHz()) : u"–"_s)
                       .arg(number(t.megabytesPerSecond()));
        html += u"</table>\n"_s;
    }
    html
        += u"<h2>%1</h2>\n<table cellpadding=\"3\" cellspacing=\"0\"><tr><th>%2</th><th>%3</th><th>%4</th><th>%5</th><th>%6</th><th>%7</th></tr>\n"_s
               .arg(tr("Cells"), tr("cell"), tr("levels"), tr("ROS"), tr("state"), tr("samples"), tr("run"));
    for (const Cell& c : m_cells)
        html
            += u"<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td class=\"n\" align=\"right\">%5</td><td>%6</td></tr>\n"_s
                   .arg(c.cell.id().toHtmlEscaped(), levelsText(c.cell).toHtmlEscaped(), rosText(),
                        CellStatus::stateName(c.status.state),
                        c.groups.isEmpty() ? u"–"_s : QString::number(c.groups.last().count),
                        c.status.run.toHtmlEscaped());
    html += u"</table>\n"_s;
    const QStringList f = findings();
    if (!f.isEmpty()) {
        html += u"<h2>%1</h2>\n<ul>\n"_s.arg(tr("Findings"));
        for (const QString& line : f)
            html += u"<li>%1</li>\n"_s.arg(line.toHtmlEscaped());
        html += u"</ul>\n"_s;
    }
    return html + u"</body></html>\n"_s;
}

QByteArray ExperimentReport::toPdf(const QList<Statistic>& statistics) const
{
    QList<QByteArray> figures;
    for (int t = 0; t < int(m_tables.size()); ++t)
        if (const QByteArray svg = ecdfSvg(t); !svg.isEmpty())
            figures << svg;
    QString body = toHtml(statistics, false);
    // The rich-text subset: the body's content only (QTextDocument ignores the style sheet).
    body = body.mid(body.indexOf(u"<body>"_s));
    return ReportPdf::render(tr("Experiment report: %1").arg(m_plan.name), body, figures);
}

QByteArray ExperimentReport::render(ReportFormats::Format format, const QList<Statistic>& statistics,
                                    const QString& figurePrefix) const
{
    switch (format) {
    case ReportFormats::Format::Markdown:
        return toMarkdown(statistics, figurePrefix).toUtf8();
    case ReportFormats::Format::Latex:
        return toTex(statistics).toUtf8();
    case ReportFormats::Format::Html:
        return toHtml(statistics).toUtf8();
    case ReportFormats::Format::Pdf:
        return toPdf(statistics);
    case ReportFormats::Format::Csv:
        return toCsv().toUtf8();
    case ReportFormats::Format::Json:
        return toJson();
    }
    return {};
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
