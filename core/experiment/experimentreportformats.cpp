// SPDX-License-Identifier: MIT
// ExperimentReport in the text formats (Markdown, LaTeX, HTML) and PDF: every table is a
// ReportTable, so that each format has the one escaper the run reports use.
#include "experiment/experimentreport.h"

#include "report/reportpdf.h"
#include "report/reporttable.h"

#include <QFileInfo>

using namespace Qt::StringLiterals;

namespace {
using Statistic = ExperimentReport::Statistic;

/// The longest a free text (the plan's name, a finding) is laid out.
constexpr qsizetype kMaxShownText = 1000;

QString shownText(const QString& text)
{
    return ReportTable::shown(text, kMaxShownText);
}

QString md(const QString& text)
{
    return ReportTable::mdEscape(shownText(text));
}

QString tex(const QString& text)
{
    return ReportTable::latexEscape(shownText(text));
}

QString html(const QString& text)
{
    return shownText(text).toHtmlEscaped();
}

/// A factor's table: a level per column, a stage group per row, the total last and bold.
ReportTable factorTable(const ExperimentReport& r, const ExperimentReport::FactorTable& t, Statistic st)
{
    ReportTable table;
    table.header << ExperimentReport::tr("stage group");
    for (const ExperimentReport::Column& c : t.columns)
        table.header << c.level;
    for (qsizetype g = 0; g < r.groups().size(); ++g) {
        ReportTable::Row row {r.groups()[g].label, {}, false, r.groups()[g].total, false};
        for (const ExperimentReport::Column& c : t.columns)
            row.values << (c.cells.isEmpty() ? u"–"_s
                                             : ExperimentReport::formatMs(ExperimentReport::value(c.groups[g], st)));
        table.rows << row;
    }
    return table;
}

/// The paper's Table I: every stage a row, every complete cell a column, means; the total last.
ReportTable methodTable(const ExperimentReport& r)
{
    ReportTable t;
    t.header << ExperimentReport::tr("stage");
    QList<const ExperimentReport::Cell*> cells;
    for (const ExperimentReport::Cell& c : r.cells())
        if (c.stages.size() == r.stageLabels().size() && !c.groups.isEmpty()) {
            cells << &c;
            t.header << c.cell.label();
        }
    for (qsizetype s = 0; s < r.stageLabels().size(); ++s) {
        ReportTable::Row row {r.stageLabels()[s], {}};
        for (const ExperimentReport::Cell* c : cells)
            row.values << ExperimentReport::formatMs(c->stages[s].mean);
        t.rows << row;
    }
    ReportTable::Row total {ExperimentReport::tr("total"), {}, false, true, false};
    for (const ExperimentReport::Cell* c : cells)
        total.values << ExperimentReport::formatMs(c->groups.last().mean);
    t.rows << total;
    return t;
}

/// The throughput step: per payload, the highest rate sustained; with `tried`, every rate tried.
ReportTable throughputTable(const ExperimentReport& r, bool tried)
{
    ReportTable t;
    t.header << ExperimentReport::tr("payload") << ExperimentReport::tr("bytes")
             << ExperimentReport::tr("highest rate (Hz)") << u"MB/s"_s;
    t.numeric = {false, true, true, true};
    if (tried) {
        t.header << ExperimentReport::tr("rates tried (samples/expected, median total ms)");
        t.numeric << false;
    }
    for (const ThroughputResult& result : r.throughput()) {
        ReportTable::Row row {result.level,
                              {QString::number(result.payloadBytes),
                               result.maxSustainableHz() > 0 ? QString::number(result.maxSustainableHz()) : u"–"_s,
                               ExperimentReport::formatMs(result.megabytesPerSecond())}};
        if (tried) {
            QStringList rates;
            for (const ThroughputPoint& p : result.points)
                rates << u"%1 Hz: %2/%3, %4%5"_s.arg(p.rateHz)
                             .arg(p.samples)
                             .arg(p.expected)
                             .arg(ExperimentReport::formatMs(p.p50Ms))
                             .arg(p.sustainable ? QString() : u" ✗"_s);
            row.values << rates.join(u"; "_s) + (result.complete ? QString() : u" …"_s);
        }
        t.rows << row;
    }
    return t;
}

/// Every cell: its levels, ROS, state and samples, with `mean` its total's mean, and its run.
ReportTable cellsTable(const ExperimentReport& r, bool mean)
{
    ReportTable t;
    t.header << ExperimentReport::tr("cell") << ExperimentReport::tr("levels") << ExperimentReport::tr("ROS")
             << ExperimentReport::tr("state") << ExperimentReport::tr("samples");
    t.numeric = {false, false, false, false, true};
    if (mean) {
        t.header << ExperimentReport::tr("total mean");
        t.numeric << true;
    }
    t.header << ExperimentReport::tr("run");
    t.numeric << false;
    for (const ExperimentReport::Cell& c : r.cells()) {
        ReportTable::Row row {c.cell.id(),
                              {ExperimentReport::levelsText(c.cell), r.rosText(), CellStatus::stateName(c.status.state),
                               c.groups.isEmpty() ? u"–"_s : QString::number(c.groups.last().count)}};
        if (mean)
            row.values << (c.groups.isEmpty() ? u"–"_s : ExperimentReport::formatMs(c.groups.last().mean));
        row.values << (mean && c.status.state != CellStatus::Complete ? u"–"_s : c.status.run);
        t.rows << row;
    }
    return t;
}

/// How many cells are complete and failed.
std::pair<int, int> doneCounts(const ExperimentReport& r)
{
    int complete = 0;
    int failed = 0;
    for (const ExperimentReport::Cell& c : r.cells()) {
        complete += c.status.state == CellStatus::Complete;
        failed += c.status.state == CellStatus::Failed;
    }
    return {complete, failed};
}
} // namespace

QString ExperimentReport::toMarkdown(const QList<Statistic>& statistics, const QString& figurePrefix) const
{
    const auto [complete, failed] = doneCounts(*this);
    QString out = u"# "_s + md(tr("Experiment report: %1").arg(m_plan.name)) + u"\n\n"_s;
    out += tr("%1 cells: %2 complete, %3 failed; %4 samples a cell after %5 of warm-up. Latencies in ms; a "
              "group's value is the sum of its stages in each sample, a level pools the samples of its cells.")
               .arg(m_cells.size())
               .arg(complete)
               .arg(failed)
               .arg(m_plan.samples)
               .arg(m_plan.warmup)
        + u"\n\n"_s;
    for (const FactorTable& t : m_tables) {
        for (Statistic st : statistics)
            out += u"## %1 (%2)\n\n"_s.arg(md(t.factor), statisticName(st)) + factorTable(*this, t, st).markdown();
        QStringList sources;
        for (const Column& c : t.columns) {
            QStringList ids;
            for (int i : c.cells)
                ids << m_cells[i].cell.id();
            sources << u"%1: %2"_s.arg(c.level, ids.isEmpty() ? tr("no complete cell") : ids.join(u", "_s));
        }
        out += md(tr("Cells: %1.").arg(sources.join(u"; "_s))) + u"\n\n"_s;
        if (!figurePrefix.isEmpty() && !ecdfSvg(int(&t - m_tables.data())).isEmpty())
            out += u"![%1](%2)\n\n"_s.arg(md(tr("Total latency by %1").arg(t.factor)),
                                          QFileInfo(figurePath(figurePrefix, t.factor)).fileName());
    }
    if (hasMethodTable())
        out += u"## "_s + tr("Per stage (Table I layout, mean, ms)") + u"\n\n"_s + methodTable(*this).markdown();
    if (!m_throughput.isEmpty())
        out += u"## "_s + tr("Throughput") + u"\n\n"_s
            + tr("The highest publishing rate sustained (every sample through in its window, none dropped, "
                 "the total's median within twice the lowest rate's plus 5 ms), and the payload it carries.")
            + u"\n\n"_s + throughputTable(*this, true).markdown();
    out += u"## "_s + tr("Cells") + u"\n\n"_s + cellsTable(*this, true).markdown();
    const QStringList f = findings();
    if (!f.isEmpty()) {
        out += u"## "_s + tr("Findings") + u"\n\n"_s;
        for (const QString& line : f)
            out += u"- "_s + md(line) + u'\n';
    }
    return out;
}

QString ExperimentReport::toTex(const QList<Statistic>& statistics) const
{
    const auto table = [](const QString& caption, const ReportTable& t) -> QString {
        return u"\\begin{table}\n\\centering\n\\caption{%1}\n"_s.arg(caption) + t.latex() + u"\\end{table}\n\n"_s;
    };
    QString out = u"%% "_s + tex(tr("Experiment report: %1").arg(m_plan.name)) + u" (booktabs)\n"_s;
    for (const FactorTable& t : m_tables)
        for (Statistic st : statistics)
            out += table(u"%1: %2 latencies [ms]"_s.arg(tex(t.factor), statisticName(st)),
                         factorTable(*this, t, st));
    if (hasMethodTable())
        out += table(tex(tr("Mean latencies [ms] by method")), methodTable(*this));
    return out;
}

QString ExperimentReport::toHtml(const QList<Statistic>& statistics, bool figures) const
{
    // The Markdown's tables as HTML: one page, no scripts, every text escaped.
    const QString title = html(tr("Experiment report: %1").arg(m_plan.name));
    QString out = u"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%1</title>"
                  u"<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}"
                  u"table{border-collapse:collapse;margin:1em 0}td,th{padding:.2em .8em;border-bottom:1px solid #ccc}"
                  u"</style></head><body>\n<h1>%1</h1>\n"_s.arg(title);
    const QString attributes = u" cellpadding=\"3\" cellspacing=\"0\""_s;
    const auto section = [&](const QString& heading, const ReportTable& t) {
        out += u"<h2>%1</h2>\n"_s.arg(heading.toHtmlEscaped()) + t.html(attributes);
    };
    for (const FactorTable& t : m_tables) {
        for (Statistic st : statistics)
            section(u"%1 (%2, ms)"_s.arg(shownText(t.factor), statisticName(st)), factorTable(*this, t, st));
        if (figures)
            out += u"<figure>%1</figure>\n"_s.arg(QString::fromUtf8(ecdfSvg(int(&t - m_tables.data()))));
    }
    if (hasMethodTable())
        section(tr("Per stage (Table I layout, mean, ms)"), methodTable(*this));
    if (!m_throughput.isEmpty())
        section(tr("Throughput"), throughputTable(*this, false));
    section(tr("Cells"), cellsTable(*this, false));
    const QStringList f = findings();
    if (!f.isEmpty()) {
        out += u"<h2>%1</h2>\n<ul>\n"_s.arg(tr("Findings").toHtmlEscaped());
        for (const QString& line : f)
            out += u"<li>%1</li>\n"_s.arg(html(line));
        out += u"</ul>\n"_s;
    }
    return out + u"</body></html>\n"_s;
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
