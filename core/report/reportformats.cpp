// SPDX-License-Identifier: MIT
#include "reportformats.h"

#include "latency/clocktext.h"
#include "latency/latencyreport.h"
#include "latency/palette.h"
#include "latency/seriesid.h"
#include "models/latencystatsmodel.h"
#include "record/suitecsv.h"
#include "report/ecdfsvg.h"
#include "report/report.h"
#include "report/reportpdf.h"
#include "report/reporttable.h"
#include "text/nameelider.h"

#include <algorithm>
#include <cmath>
#include <QDateTime>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QSet>

using namespace Qt::StringLiterals;

namespace {
QString ms(double v)
{
    return std::isfinite(v) ? QString::number(v, 'f', 2) : u"–"_s;
}

QString when(qint64 ns)
{
    if (ns <= 0)
        return QCoreApplication::translate("ReportFormats", "unknown");
    return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000).toString(u"yyyy-MM-dd HH:mm:ss"_s);
}

/// Free text (notes, an event's detail) laid out at most this long; names at NameElider::MaxShown.
constexpr qsizetype kMaxShownText = 1000;

/// A text from a run as a report lays it out (ReportTable::shown), names at NameElider::MaxShown.
QString shown(const QString& text, qsizetype max = NameElider::MaxShown)
{
    return ReportTable::shown(text, max);
}

QString mdEscape(const QString& s)
{
    return ReportTable::mdEscape(s);
}

/// The report's title as laid out (its names are cut already, Report::title()).
QString titleOf(const Report& report)
{
    return shown(report.title(), kMaxShownText);
}

/// The tables, as every text format renders them.
using Table = ReportTable;
using Cells = ReportTable::Row;

/// `t` with every text as shown(): names cut at NameElider::MaxShown, the last column (an event's
/// why) at kMaxShownText when `freeTextLast`.
Table shownTable(Table t, bool freeTextLast = false)
{
    for (QString& h : t.header)
        h = shown(h);
    for (Cells& c : t.rows) {
        c.label = shown(c.label);
        for (qsizetype i = 0; i < c.values.size(); ++i)
            c.values[i] = shown(c.values[i], freeTextLast && i + 1 == c.values.size() ? kMaxShownText
                                                                                       : NameElider::MaxShown);
    }
    return t;
}

Table stageTable(const Report& report)
{
    Table t;
    const QList<Report::Row> rows = report.rows();
    if (!report.isComparison()) {
        t.header = QStringList {QCoreApplication::translate("ReportFormats", "Stage"),
                                QCoreApplication::translate("ReportFormats", "Mean [ms]"),
                                QCoreApplication::translate("ReportFormats", "Median"),
                                QCoreApplication::translate("ReportFormats", "Std"),
                                QCoreApplication::translate("ReportFormats", "Min"),
                                QCoreApplication::translate("ReportFormats", "Max"),
                                QCoreApplication::translate("ReportFormats", "p99"),
                                QCoreApplication::translate("ReportFormats", "Count")};
        const ReportRun& run = *report.runs().front();
        for (const Report::Row& r : rows) {
            const std::optional<LatencyStats> s = report.stats(run, r);
            if (!s)
                continue;
            // Corrected by measured clocks: the interval beside the name, and a figure within it
            // of zero marked as such.
            const std::optional<double> u = report.uncertaintyMs(run, r);
            const auto fig = [&u](double v) { return LatencyStatsModel::figureText(v, u); };
            t.rows.append({u ? r.label + u' ' + LatencyStatsModel::uncertaintyText(u) : r.label,
                           {fig(s->mean), fig(s->median), ms(s->std), fig(s->min), fig(s->max), fig(s->p99),
                            QString::number(s->count)},
                           r.crossing,
                           r.emphasized,
                           r.derived});
        }
        return shownTable(std::move(t));
    }
    t.header << QCoreApplication::translate("ReportFormats", "Mean latency [ms]");
    for (const auto& run : report.runs())
        t.header << run->name;
    for (const Report::Row& r : rows) {
        Cells c {r.label, {}, r.crossing, r.emphasized, r.derived};
        for (const auto& run : report.runs()) {
            const std::optional<LatencyStats> s = report.stats(*run, r);
            const std::optional<double> u = report.uncertaintyMs(*run, r);
            c.values << (!s      ? QString()
                             : u ? LatencyStatsModel::figureText(s->mean, u) + u' '
                                 + LatencyStatsModel::uncertaintyText(u)
                                 : ms(s->mean));
        }
        t.rows.append(c);
    }
    return shownTable(std::move(t));
}

/// Every run's total: the paper's summary under its Table I.
Table totalsTable(const Report& report)
{
    Table t;
    t.header = QStringList {QCoreApplication::translate("ReportFormats", "Run"),
                            QCoreApplication::translate("ReportFormats", "Samples"),
                            QCoreApplication::translate("ReportFormats", "Dropped"),
                            QCoreApplication::translate("ReportFormats", "Mean [ms]"),
                            QCoreApplication::translate("ReportFormats", "Median"),
                            QCoreApplication::translate("ReportFormats", "Std"),
                            QCoreApplication::translate("ReportFormats", "Min"),
                            QCoreApplication::translate("ReportFormats", "Max"),
                            QCoreApplication::translate("ReportFormats", "p99")};
    for (const auto& run : report.runs()) {
        const LatencyEngine& e = *run->engine;
        const LatencyStats s = e.totalSeries() >= 0 ? e.series(e.totalSeries()).stats() : LatencyStats();
        t.rows.append({run->name,
                       {QString::number(e.samples()), QString::number(run->dropped()), ms(s.mean),
                        ms(s.median), ms(s.std), ms(s.min), ms(s.max), ms(s.p99)},
                       false,
                       false,
                       false});
    }
    return shownTable(std::move(t));
}

/// Title-block lines: what was measured, where, when, how much.
/// How the run's clocks were read: one clock (each way its own latency), or an offset estimated
/// with how far it may be off; empty without an outbound and a return crossing.
QString clocksText(const LatencyEngine& e)
{
    if (const QString measured = ClockText::measured(e.pipelineSeries(), e.pipeline()); !measured.isEmpty())
        return QCoreApplication::translate("ReportFormats", "clocks measured: %1").arg(measured);
    if (e.pipelineSeries().thereSeries() >= 0)
        return QCoreApplication::translate("ReportFormats",
                                           "one clock: each direction's own one-way latency, no offset");
    if (e.pipelineSeries().clockOffsetSeries() < 0)
        return {};
    // Short: a comparison lists it once per run, side by side; what it cannot tell apart is said
    // once, in the note under the tables.
    const auto bounds = e.pipelineSeries().clockOffsetBoundsMs();
    const QString median
        = LatencyStatsModel::msText(e.series(e.pipelineSeries().clockOffsetSeries()).stats().median);
    if (!bounds)
        return QCoreApplication::translate("ReportFormats", "two clocks: offset %1 ms").arg(median);
    return QCoreApplication::translate("ReportFormats", "two clocks: offset %1 ms %2, between %3 and %4 ms")
        .arg(median, LatencyStatsModel::offsetUncertaintyText(bounds), LatencyStatsModel::msText(bounds->first),
             LatencyStatsModel::msText(bounds->second));
}

QList<std::pair<QString, QString>> facts(const ReportRun& run)
{
    const LatencyEngine& e = *run.engine;
    const Pipeline& p = e.pipeline();
    QList<std::pair<QString, QString>> out;
    const auto add = [&out](const char* key, const QString& value) {
        if (!value.isEmpty())
            out.append({QCoreApplication::translate("ReportFormats", key), shown(value, kMaxShownText)});
    };
    add(QT_TRANSLATE_NOOP("ReportFormats", "Run"), NameElider::elideTail(run.name));
    add(QT_TRANSLATE_NOOP("ReportFormats", "Source"),
        run.path.isEmpty() ? QString() : run.path + u" ("_s + run.kind + u')');
    add(QT_TRANSLATE_NOOP("ReportFormats", "Recorded"),
        run.info.startedNs > 0 ? when(run.info.startedNs) + u" – "_s
                + (run.info.stoppedNs > 0 ? when(run.info.stoppedNs)
                                          : QCoreApplication::translate("ReportFormats", "not stopped"))
                               : QString());
    QString pipeline = QCoreApplication::translate("ReportFormats", "%1 stamps, %2 stages")
                           .arg(p.topicCount())
                           .arg(p.stageCount());
    if (p.hasHosts()) {
        QStringList hosts;
        QSet<QString> seen; // a list's contains() was quadratic in the hosts of a hostile pipeline
        for (int i = 0; i < p.topicCount(); ++i) {
            const QString h = p.host(i);
            if (!h.isEmpty() && !seen.contains(h)) {
                seen.insert(h);
                hosts << h;
            }
        }
        pipeline += QCoreApplication::translate("ReportFormats", "; hosts %1; %2 crossings")
                        .arg(hosts.join(u", "_s))
                        .arg(p.crossings().size());
    }
    const bool measured = p.topicCount() > 0; // a run of `watch` may hold events only
    add(QT_TRANSLATE_NOOP("ReportFormats", "Pipeline"), measured ? pipeline : QString());
    add(QT_TRANSLATE_NOOP("ReportFormats", "Clocks"), clocksText(e));
    if (const QList<LatencyWarning> warnings = LatencyWarnings::of(e); !warnings.isEmpty())
        add(QT_TRANSLATE_NOOP("ReportFormats", "Not a measurement"),
            LatencyWarnings::lines(warnings).join(u"; "_s) + u". "_s + LatencyWarnings::fixOnCommandLine());
    add(QT_TRANSLATE_NOOP("ReportFormats", "Broker"), run.info.broker);
    add(QT_TRANSLATE_NOOP("ReportFormats", "ROS master"), run.info.rosMaster);
    add(QT_TRANSLATE_NOOP("ReportFormats", "ROS 2"), run.info.ros2Domain);
    if (measured) {
        add(QT_TRANSLATE_NOOP("ReportFormats", "Samples"),
            QCoreApplication::translate("ReportFormats", "%1 complete, %2 dropped, %3 duplicate stamps")
                .arg(e.samples())
                .arg(run.dropped())
                .arg(e.counters().duplicates));
        add(QT_TRANSLATE_NOOP("ReportFormats", "Window"),
            e.window() > 0
                ? QCoreApplication::translate("ReportFormats", "the last %1 samples").arg(e.window())
                : QCoreApplication::translate("ReportFormats", "the whole run"));
    }
    if (!run.events.empty()) {
        const auto alerts = std::count_if(run.events.cbegin(), run.events.cend(),
                                          [](const RecordedEvent& e) { return e.level == u"alert"_s; });
        add(QT_TRANSLATE_NOOP("ReportFormats", "Events"),
            QCoreApplication::translate("ReportFormats", "%1 (%2 alerts)")
                .arg(run.events.size())
                .arg(alerts));
    }
    add(QT_TRANSLATE_NOOP("ReportFormats", "Host"), run.info.host);
    add(QT_TRANSLATE_NOOP("ReportFormats", "Notes"), run.info.notes);
    return out;
}

/// The facts of compared runs as one table, a column per run (`th` opens a label cell): a fact
/// that differs between runs is read across, and the page keeps room for the figure.
QString comparedFacts(const Report& report, const QString& th)
{
    QStringList keys;
    std::vector<QHash<QString, QString>> values;
    for (const auto& run : report.runs()) {
        values.emplace_back();
        for (const auto& [key, value] : facts(*run)) {
            if (!keys.contains(key))
                keys << key;
            values.back().insert(key, value);
        }
    }
    QString out = u"<table class=\"facts\" cellspacing=\"0\" cellpadding=\"3\">\n<tr><td></td>"_s;
    for (const auto& run : report.runs())
        out += u"<th align=\"left\">"_s + shown(run->name).toHtmlEscaped() + u"</th>"_s;
    out += u"</tr>\n"_s;
    for (const QString& key : std::as_const(keys)) {
        out += u"<tr>"_s + th + key.toHtmlEscaped() + u"</th>"_s;
        for (const auto& v : values)
            out += u"<td>"_s + v.value(key).toHtmlEscaped() + u"</td>"_s;
        out += u"</tr>\n"_s;
    }
    return out + u"</table>\n"_s;
}

/// Events listed in a report's table; the JSON report has them all.
constexpr int kMaxEventRows = 1000;

/// A link id ("config|ros2mqtt|/ros/topic|mqtt/topic") or "bridge:NAME" as people read it.
QString eventSubject(const QString& subject)
{
    if (subject.startsWith(u"bridge:"_s))
        return QCoreApplication::translate("ReportFormats", "bridge %1").arg(subject.mid(7));
    const QStringList parts = subject.split(u'|');
    if (parts.size() != 4)
        return subject;
    const bool toMqtt = parts[1] == u"ros2mqtt"_s;
    return u"%1: %2 → %3"_s.arg(parts[0], toMqtt ? parts[2] : parts[3], toMqtt ? parts[3] : parts[2]);
}

/// Where an event came from: the watched config's file (its name) and its bridge, as the event's
/// JSON says them (a run recorded before they were kept says its config's name, or nothing).
QString eventOrigin(const RecordedEvent& e)
{
    const QJsonObject o = QJsonDocument::fromJson(e.json).object();
    const QString config = o.value(u"config"_s).toString();
    if (config == u"discovered"_s && o.value(u"config_file"_s).toString().isEmpty())
        return QCoreApplication::translate("ReportFormats", "announced on the broker");
    const QString file = o.value(u"config_file"_s).toString();
    const QString where = file.isEmpty() ? config : QFileInfo(file).fileName();
    const QString client = o.value(u"client"_s).toString();
    if (client.isEmpty())
        return where.isEmpty() ? u"–"_s : where;
    return where.isEmpty() ? QCoreApplication::translate("ReportFormats", "bridge %1").arg(client)
                           : QCoreApplication::translate("ReportFormats", "%1, bridge %2").arg(where, client);
}

QString duration(const RecordedEvent& e)
{
    if (e.endNs <= 0)
        return QCoreApplication::translate("ReportFormats", "open");
    if (e.endNs < e.startNs)
        return u"–"_s; // ends before it starts: no duration to show
    const double s = e.durationSeconds(); // computed without overflow, whatever the times
    if (s < 120)
        return QString::number(s, 'f', 1) + u" s"_s;
    if (s < 2 * 3600)
        return QString::number(s / 60, 'f', 1) + u" min"_s;
    if (s < 2 * 86400)
        return QString::number(s / 3600, 'f', 1) + u" h"_s;
    return QString::number(s / 86400, 'f', 0) + u" d"_s;
}

/// The watch events of every run, by start (at most kMaxEventRows; `more` gets how many were left out).
Table eventsTable(const Report& report, qsizetype* more)
{
    Table t;
    if (report.isComparison())
        t.header << QCoreApplication::translate("ReportFormats", "Run");
    t.header << QCoreApplication::translate("ReportFormats", "Start")
             << QCoreApplication::translate("ReportFormats", "From")
             << QCoreApplication::translate("ReportFormats", "Duration")
             << QCoreApplication::translate("ReportFormats", "Link")
             << QCoreApplication::translate("ReportFormats", "Level")
             << QCoreApplication::translate("ReportFormats", "Why");
    *more = 0;
    for (const auto& run : report.runs())
        for (const RecordedEvent& e : run->events) {
            if (t.rows.size() >= kMaxEventRows) {
                ++*more;
                continue;
            }
            Cells c;
            QStringList cells {when(e.startNs), eventOrigin(e),
                               duration(e),     eventSubject(e.subject),
                               e.level,         e.detail.isEmpty() ? e.reasons.join(u", "_s) : e.detail};
            if (report.isComparison())
                c.label = run->name;
            else
                c.label = cells.takeFirst();
            c.values = cells;
            c.emphasized = false;
            c.crossing = e.level == u"alert"_s; // shown like a marked row
            t.rows.append(c);
        }
    return shownTable(std::move(t), true);
}

QJsonArray eventsJson(const ReportRun& run)
{
    QJsonArray out;
    for (const RecordedEvent& e : run.events) {
        QJsonObject o = QJsonDocument::fromJson(e.json).object(); // the figures, when the file has them
        o.remove(u"event"_s);
        o.insert(u"subject"_s, e.subject);
        o.insert(u"level"_s, e.level);
        o.insert(u"reasons"_s, QJsonArray::fromStringList(e.reasons));
        o.insert(u"detail"_s, e.detail);
        o.insert(u"start_ns"_s, QString::number(e.startNs));
        o.insert(u"end_ns"_s, e.endNs > 0 ? QJsonValue(QString::number(e.endNs)) : QJsonValue());
        o.insert(u"duration_s"_s, e.endNs > 0 ? QJsonValue(e.durationSeconds()) : QJsonValue());
        out.append(o);
    }
    return out;
}

QString eventsNote(qsizetype more)
{
    QString out = QCoreApplication::translate("ReportFormats",
                                              "Events: every change of a watched link's or bridge's state "
                                              "while the run was recorded, from the config and bridge "
                                              "named; alerts are marked.");
    if (more > 0)
        out += u' '
            + QCoreApplication::translate("ReportFormats", "%1 more events are in the JSON report.")
                  .arg(more);
    return out;
}

QString note(const Report& report)
{
    const QList<Report::Row> rows = report.rows();
    const bool observed = std::any_of(rows.cbegin(), rows.cend(), [](const Report::Row& r) {
        const std::optional<SeriesId> id = SeriesId::parse(r.seriesId);
        return id && id->kind == SeriesKind::External && SeriesId::isObserved(id->name);
    });
    const QString more = observed
        ? u' '
            + QCoreApplication::translate(
                "ReportFormats",
                "Rows named \"observed\": a bridge's hop latency without stamps, each message Bridgescope "
                "saw going into the bridge matched by its content with the copy it saw coming out, on "
                "Bridgescope's one clock (its own delivery included).")
        : QString();
    return QCoreApplication::translate(
               "ReportFormats",
               "Statistics in ms; std is the corrected standard deviation (ddof = 1). Rows "
               "in italics cross between hosts: their raw values include the clock offset. "
               "Communication: total minus every stage on one host, one way being half of it. "
               "With two clocks, a clock offset and a difference between the two legs cannot be told apart "
               "within the offset's range (neither leg takes negative time); with one clock (one_clock: true "
               "in the pipeline, or --one-clock) each direction's own one-way latency is given instead.")
        + more;
}
} // namespace

const QList<ReportFormats::Entry>& ReportFormats::formats()
{
    // translated when first asked, after the translator is installed
    static const QList<Entry> all {
        {Format::Pdf, u"pdf"_s, tr("PDF"), true,
         [](const Report& r, bool) -> Result<QByteArray> { return ReportPdf::render(r); }},
        {Format::Html, u"html"_s, tr("HTML (tables and SVG figure)"), true,
         [](const Report& r, bool) -> Result<QByteArray> { return html(r); }},
        {Format::Markdown, u"md"_s, tr("Markdown"), false,
         [](const Report& r, bool) -> Result<QByteArray> { return markdown(r); }},
        {Format::Latex, u"tex"_s, tr("LaTeX (booktabs tabular)"), false,
         [](const Report& r, bool) -> Result<QByteArray> { return latex(r); }},
        {Format::Csv, u"csv"_s, tr("CSV"), false,
         [](const Report& r, bool perSampleMs) { return csv(r, perSampleMs); }},
        {Format::Json, u"json"_s, tr("JSON"), false,
         [](const Report& r, bool) -> Result<QByteArray> { return json(r); }},
    };
    return all;
}

const ReportFormats::Entry& ReportFormats::entry(Format format)
{
    for (const Entry& e : formats())
        if (e.format == format)
            return e;
    Q_UNREACHABLE(); // every Format has its row (tst_reportformats)
}

bool ReportFormats::parse(const QString& name, Format* format)
{
    for (const Entry& e : formats())
        if (e.name == name.toLower()) {
            *format = e.format;
            return true;
        }
    return false;
}

QByteArray ReportFormats::json(const Report& report)
{
    const auto one = [](const ReportRun& run) {
        QJsonObject o = LatencyReport::json(*run.engine, run.droppedBeforeImport);
        if (!run.events.empty())
            o.insert(u"events"_s, eventsJson(run));
        return o;
    };
    if (!report.isComparison())
        return QJsonDocument(one(*report.runs().front())).toJson(QJsonDocument::Indented);
    QJsonArray runs;
    for (const auto& run : report.runs()) {
        QJsonObject o = one(*run);
        o.insert(u"name"_s, run->name);
        o.insert(u"source"_s, run->path);
        runs.append(o);
    }
    return QJsonDocument(QJsonObject {{u"runs"_s, runs}}).toJson(QJsonDocument::Indented);
}

Result<QByteArray> ReportFormats::csv(const Report& report, bool perSampleMs)
{
    if (report.isComparison())
        return LocatedError {
            tr("a CSV file holds a single run: give one input, or join several with --join")};
    const ReportRun& run = *report.runs().front();
    const Pipeline& p = run.engine->pipeline();
    if (!perSampleMs)
        return SuiteCsv::write(p.topics(), run.samples);
    QStringList header;
    for (int s = 0; s < p.stageCount(); ++s)
        header << p.stageLabel(s) + u" [ms]"_s;
    header << tr("total [ms]");
    QByteArray out = SuiteCsv::header(header);
    const auto number
        = [](qint64 ns) { return QByteArray::number(double(ns) / 1e6, 'g', QLocale::FloatingPointShortest); };
    for (const std::vector<qint64>& t : run.samples) {
        QByteArray line;
        for (std::size_t s = 0; s + 1 < t.size(); ++s)
            line += number(t[s + 1] - t[s]) + ',';
        line += number(t.back() - t.front());
        out += line + "\r\n";
    }
    return out;
}

QByteArray ReportFormats::markdown(const Report& report)
{
    QString out = u"# "_s + mdEscape(titleOf(report)) + u"\n\n"_s;
    for (const auto& run : report.runs()) {
        if (report.isComparison())
            out += u"## "_s + mdEscape(shown(run->name)) + u"\n\n"_s;
        for (const auto& [key, value] : facts(*run))
            out += u"- **"_s + key + u":** "_s + mdEscape(value) + u'\n';
        out += u'\n';
    }
    const auto table = [&out](const Table& t) { out += t.markdown(); };
    if (report.hasLatency()) {
        out += u"## "_s + tr("Latency per stage") + u"\n\n"_s;
        table(stageTable(report));
        if (report.isComparison() && report.hasPipeline()) {
            out += u"## "_s + tr("Total latency per run") + u"\n\n"_s;
            table(totalsTable(report));
        }
        out += note(report) + u"\n"_s;
    }
    if (report.hasEvents()) {
        qsizetype more = 0;
        const Table events = eventsTable(report, &more);
        out += (report.hasLatency() ? u"\n## "_s : u"## "_s) + tr("Events") + u"\n\n"_s;
        table(events);
        out += eventsNote(more) + u'\n';
    }
    return out.toUtf8();
}

QByteArray ReportFormats::latex(const Report& report)
{
    QString out = u"% "_s + titleOf(report) + u"\n% "_s
        + tr("Written by Bridgescope; needs \\usepackage{booktabs}.") + u'\n';
    const auto table = [&out](const Table& t, const QString& caption) {
        out += u"% "_s + caption + u'\n' + t.latex() + u'\n';
    };
    if (report.hasLatency()) {
        for (const auto& run : report.runs())
            for (const QString& line : LatencyWarnings::lines(LatencyWarnings::of(*run->engine)))
                out += u"% "_s
                    + tr("Not a measurement (%1): %2").arg(shown(run->name), shown(line, kMaxShownText))
                    + u'\n';
        table(stageTable(report), tr("Latency per stage"));
        if (report.isComparison() && report.hasPipeline())
            table(totalsTable(report), tr("Total latency per run"));
        out += u"% "_s + note(report) + u'\n';
    }
    if (report.hasEvents()) {
        qsizetype more = 0;
        table(eventsTable(report, &more), tr("Events"));
        out += u"% "_s + eventsNote(more) + u'\n';
    }
    return out.toUtf8();
}

QString ReportFormats::htmlBody(const Report& report, bool forQtRichText)
{
    QString out = u"<h1>"_s + titleOf(report).toHtmlEscaped() + u"</h1>\n"_s;
    // Qt's rich text (the PDF) knows no style sheet's padding for a class: the labels get a
    // column of their own width, or the longest ("ROS master") runs into its value.
    const QString th = forQtRichText ? u"<th align=\"left\" width=\"17%\" style=\"font-weight: normal\">"_s
                                     : u"<th>"_s;
    if (forQtRichText && report.isComparison() && report.runs().size() <= 4) // more: too narrow
        out += comparedFacts(report, th); // on paper, one table: the figure fits below the tables
    else
        for (const auto& run : report.runs()) {
            if (report.isComparison())
                out += u"<h3>"_s + shown(run->name).toHtmlEscaped() + u"</h3>\n"_s;
            out += forQtRichText ? u"<table class=\"facts\" cellspacing=\"0\" cellpadding=\"3\">\n"_s
                                 : u"<table class=\"facts\">\n"_s;
            for (const auto& [key, value] : facts(*run))
                out += u"<tr>"_s + th + key.toHtmlEscaped() + u"</th><td>"_s + value.toHtmlEscaped()
                    + u"</td></tr>\n"_s;
            out += u"</table>\n"_s;
        }
    const QString border = forQtRichText ? u" border=\"1\" cellspacing=\"0\" cellpadding=\"3\""_s : QString();
    const auto table = [&](const Table& t, const QString& caption) {
        out += u"<h2>"_s + caption.toHtmlEscaped() + u"</h2>\n"_s + t.html(border);
    };
    if (report.hasLatency()) {
        table(stageTable(report), tr("Latency per stage"));
        if (report.isComparison() && report.hasPipeline())
            table(totalsTable(report), tr("Total latency per run"));
        out += u"<p class=\"note\">"_s + note(report).toHtmlEscaped() + u"</p>\n"_s;
    }
    if (report.hasEvents()) {
        qsizetype more = 0;
        table(eventsTable(report, &more), tr("Events"));
        out += u"<p class=\"note\">"_s + eventsNote(more).toHtmlEscaped() + u"</p>\n"_s;
    }
    return out;
}

QByteArray ReportFormats::ecdfSvg(const Report& report, int width, int height)
{
    QList<EcdfSvg::Curve> curves;
    int color = 0;
    for (const auto& run : report.runs()) {
        const LatencyEngine& e = *run->engine;
        if (e.totalSeries() < 0)
            continue;
        const QString total = report.isComparison() ? shown(run->name) : tr("total");
        curves.append({total, seriesColor(color++), &e.series(e.totalSeries())});
        if (!report.isComparison() && e.pipelineSeries().oneWaySeries() >= 0)
            curves.append({tr("communication, one way"), seriesColor(color++),
                           &e.series(e.pipelineSeries().oneWaySeries())});
    }
    return EcdfSvg::render(curves, width, height,
                           report.isComparison() ? tr("Total latency per run") : tr("Latency distribution"));
}

QByteArray ReportFormats::html(const Report& report)
{
    QString out = u"<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n"
                  "<meta charset=\"utf-8\"/>\n<title>"_s
        + titleOf(report).toHtmlEscaped()
        + u"</title>\n<style>\n"
          "body { font-family: 'DejaVu Sans', Helvetica, Arial, sans-serif; max-width: 60em; margin: 2em "
          "auto; "
          "color: #222; }\n"
          "table { border-collapse: collapse; margin: 0.5em 0 1.5em; }\n"
          "table.stats th, table.stats td { border-bottom: 1px solid #ccc; padding: 0.25em 0.7em; }\n"
          "table.stats th { border-bottom: 2px solid #444; text-align: right; }\n"
          "table.stats .label { text-align: left; }\n"
          "table.facts th { text-align: left; padding-right: 1em; font-weight: normal; color: #555; }\n"
          ".note { color: #555; font-size: 0.9em; }\n"
          "</style>\n</head>\n<body>\n"_s;
    out += htmlBody(report, false);
    if (report.hasPipeline())
        out += u"<h2>"_s + tr("ECDF").toHtmlEscaped() + u"</h2>\n<figure>\n"_s
            + QString::fromUtf8(ecdfSvg(report)) + u"</figure>\n"_s;
    out += u"<p class=\"note\">"_s
        + tr("Made with Bridgescope %1 on %2.")
              .arg(QStringLiteral(BRIDGESCOPE_VERSION), QDateTime::currentDateTime().toString(Qt::ISODate))
              .toHtmlEscaped()
        + u"</p>\n</body>\n</html>\n"_s;
    return out.toUtf8();
}

Result<QByteArray> ReportFormats::render(const Report& report, Format format, bool perSampleMs)
{
    return entry(format).render(report, perSampleMs);
}
