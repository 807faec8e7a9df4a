// SPDX-License-Identifier: MIT
// Every report format, checked for content: the suite CSV round trip byte for byte, Markdown and
// LaTeX tables (three runs, three columns), HTML that parses and holds the SVG figure, a PDF whose
// pages and text poppler reads.
#include "fixtures.h"
#include "latency/latencyseries.h"
#include "latency/seriesid.h"
#include "record/suitecsv.h"
#include "report/ecdfsvg.h"
#include "report/report.h"
#include "report/reportformats.h"
#include "report/reportpdf.h"
#include "resulttext.h"
#include "syntheticrun.h"

#include <algorithm>
#include <limits>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using namespace Qt::StringLiterals;

namespace {
QString writeCsv(const QTemporaryDir& dir, const QString& name, const SyntheticRun& run)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(SuiteCsv::write(run.topics, run.samples));
    return path;
}

Pipeline paperWithHosts()
{
    const SyntheticRun paper = SyntheticRun::paper(1, 0, 1);
    Pipeline p(paper.topics, 0);
    for (int i = 0; i < paper.topics.size(); ++i)
        p.setHost(paper.topics[i], paper.hosts()[i]);
    return p;
}

QString run(const QString& program, const QStringList& args)
{
    QProcess p;
    p.start(program, args);
    p.waitForFinished(60000);
    return QString::fromUtf8(p.readAllStandardOutput());
}
} // namespace

class TestReportFormats : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QStringList m_inputs; ///< three runs: mqtt_client-like, slower, faster

    /// The report as a PDF file in the test's folder; its path.
    QString writePdf(const Report& report, const QString& name)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(ReportPdf::render(report));
        return path;
    }

private slots:
    void initTestCase()
    {
        m_inputs << writeCsv(m_dir, u"client.csv"_s, SyntheticRun::paper(600, 250'000'000, 1));
        SyntheticRun slower = SyntheticRun::paper(500, -20'000'000, 2);
        for (auto& s : slower.samples)
            for (std::size_t i = 1; i < s.size(); ++i)
                s[i] += qint64(i) * 2'000'000;
        m_inputs << writeCsv(m_dir, u"bridge.csv"_s, slower);
        m_inputs << writeCsv(m_dir, u"overlay.csv"_s, SyntheticRun::paper(400, 0, 3));
    }

    // One row a format (issue 42): every Format has exactly one, its name reads back, and render()
    // gives what the row's own function gives.
    void everyFormatIsOneRow()
    {
        using F = ReportFormats::Format;
        QSet<QString> names;
        QSet<int> formats;
        for (const ReportFormats::Entry& e : ReportFormats::formats()) {
            QVERIFY2(!names.contains(e.name) && !formats.contains(int(e.format)), qPrintable(e.name));
            names.insert(e.name);
            formats.insert(int(e.format));
            QVERIFY(!e.title.isEmpty() && e.render);
            F back = F::Json;
            QVERIFY(ReportFormats::parse(e.name.toUpper(), &back));
            QCOMPARE(back, e.format);
            QCOMPARE(ReportFormats::suffix(e.format), e.name);
        }
        QCOMPARE(formats.size(), int(F::Pdf) + 1);
        F f = F::Json;
        QVERIFY(!ReportFormats::parse(u"docx"_s, &f));
        QString error;
        const std::optional<Report> one = noted(Report::build({m_inputs.first()}, std::nullopt, {}), &error);
        QVERIFY2(one, qPrintable(error));
        QCOMPARE(*ReportFormats::render(*one, F::Markdown, false), ReportFormats::markdown(*one));
        QCOMPARE(*ReportFormats::render(*one, F::Csv, true), *ReportFormats::csv(*one, true));
        const std::optional<Report> three = noted(Report::build(m_inputs, std::nullopt, {}), &error);
        QVERIFY2(three, qPrintable(error));
        QVERIFY(!noted(ReportFormats::render(*three, F::Csv, false), &error));
        QVERIFY(error.contains(u"--join"_s));
    }

    void suiteCsvRoundTripIsByteIdentical()
    {
        QFile original(m_inputs.first());
        QVERIFY(original.open(QIODevice::ReadOnly));
        QString error;
        const std::optional<Report> report
            = noted(Report::build({m_inputs.first()}, std::nullopt, {}), &error);
        QVERIFY2(report, qPrintable(error));
        QCOMPARE(*ReportFormats::csv(*report, false), original.readAll());
        // Per sample in ms: the stages of the first sample.
        const QList<QByteArray> lines = ReportFormats::csv(*report, true)->split('\n');
        QCOMPARE(lines.size(), 602); // header, 600 rows, the empty rest
        const SyntheticRun again = SyntheticRun::paper(600, 250'000'000, 1);
        const QList<QByteArray> first = lines[1].trimmed().split(',');
        QCOMPARE(first.size(), 12);
        QCOMPARE(first[0].toDouble(), double(again.samples[0][1] - again.samples[0][0]) / 1e6);
        QCOMPARE(first.last().toDouble(), double(again.samples[0].back() - again.samples[0].front()) / 1e6);
        // CSV holds one run: a comparison is refused.
        const std::optional<Report> three = noted(Report::build(m_inputs, std::nullopt, {}), &error);
        QVERIFY(!noted(ReportFormats::csv(*three, false), &error));
        QVERIFY(error.contains(u"--join"_s));
    }

    void markdownAndLatexTablesOfOneAndThreeRuns()
    {
        QString error;
        const std::optional<Report> one
            = noted(Report::build({m_inputs.first()}, paperWithHosts(), {}), &error);
        QVERIFY2(one, qPrintable(error));
        const QString md = QString::fromUtf8(ReportFormats::markdown(*one));
        QVERIFY(md.contains(u"| Stage | Mean [ms] | Median | Std | Min | Max | p99 | Count |"_s));
        QVERIFY(md.contains(u"| **total** | **"_s));
        QVERIFY(md.contains(u"| *communication, one way (half the round trip)* |"_s));
        // The 250 ms the run was made with, within the jitter of the two crossings.
        const QRegularExpressionMatch offset
            = QRegularExpression(u"\\| \\*clock offset\\* \\| ([-0-9.]+) \\|"_s).match(md);
        QVERIFY2(offset.hasMatch(), qPrintable(md));
        QVERIFY2(std::abs(offset.captured(1).toDouble() - 250.0) < 1.0, qPrintable(offset.captured(1)));

        const std::optional<Report> three = noted(Report::build(m_inputs, paperWithHosts(), {}), &error);
        QVERIFY2(three, qPrintable(error));
        const QString md3 = QString::fromUtf8(ReportFormats::markdown(*three));
        QVERIFY2(md3.contains(u"| Mean latency [ms] | client | bridge | overlay |"_s), qPrintable(md3));
        const QString tex = QString::fromUtf8(ReportFormats::latex(*three));
        QCOMPARE(tex.count(u"\\begin{tabular}"_s), 2);
        QCOMPARE(tex.count(u"\\end{tabular}"_s), 2);
        QCOMPARE(tex.count(u"\\toprule"_s), 2);
        QCOMPARE(tex.count(u"\\bottomrule"_s), 2);
        QVERIFY(tex.contains(u"\\begin{tabular}{lrrr}"_s)); // a label column and three runs
        // Every row of the stage table has four cells.
        const QString first = tex.section(u"\\end{tabular}"_s, 0, 0);
        for (const QString& line : first.split(u'\n')) {
            if (line.endsWith(u"\\\\"_s))
                QCOMPARE(line.count(u" & "_s), 3);
        }
        QVERIFY(tex.contains(u"\\textbf{total}"_s));
        QVERIFY(tex.contains(u"mqtt\\_interface\\_vehicle $\\rightarrow$ mqtt\\_interface\\_cloud"_s));
        // With a TeX engine at hand, the tables must compile.
        const QString pdflatex = QStandardPaths::findExecutable(u"pdflatex"_s);
        if (pdflatex.isEmpty())
            return;
        QFile doc(m_dir.filePath(u"t.tex"_s));
        QVERIFY(doc.open(QIODevice::WriteOnly));
        doc.write(
            "\\documentclass{article}\\usepackage{booktabs}\\usepackage[utf8]{inputenc}\\begin{document}\n"
            + tex.toUtf8() + "\n\\end{document}\n");
        doc.close();
        QProcess p;
        p.setWorkingDirectory(m_dir.path());
        p.start(pdflatex, {u"-interaction=nonstopmode"_s, u"t.tex"_s});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 0);
    }

    void htmlParsesAndHoldsTheFigure()
    {
        QString error;
        const std::optional<Report> three = noted(Report::build(m_inputs, paperWithHosts(), {}), &error);
        QVERIFY2(three, qPrintable(error));
        const QByteArray html = ReportFormats::html(*three);
        QXmlStreamReader xml(html);
        int svgs = 0;
        int polylines = 0;
        int tables = 0;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement()) {
                svgs += xml.name() == u"svg"_s;
                polylines += xml.name() == u"polyline"_s;
                tables += xml.name() == u"table"_s;
            }
        }
        QVERIFY2(!xml.hasError(),
                 qPrintable(xml.errorString() + u" at line "_s + QString::number(xml.lineNumber())));
        QCOMPARE(svgs, 1);
        QCOMPARE(polylines, 3); // the three totals in one figure, as the paper's Fig. 5
        QVERIFY(tables >= 5); // three runs' facts, the stage table, the totals
        QVERIFY(html.contains("stroke-dasharray=\"6,4\"")); // means
    }

    // Issue 43: a run with measured clocks reports each crossing corrected, with its interval, the
    // asymmetry beside the paper's one way, and the clocks themselves, in every format.
    void measuredClocksAreReportedWithTheirIntervals()
    {
        RunData run = RunData::fromSamples(paperWithHosts(), SyntheticRun::paper(200, 35'000'000, 5).samples);
        run.info.name = u"two hosts"_s;
        for (const auto& [host, offsetNs, uncertaintyNs] :
             {std::tuple {u"vehicle"_s, qint64(0), qint64(100'000)},
              std::tuple {u"cloud"_s, qint64(35'000'000), qint64(300'000)}}) {
            ClockEstimate c;
            c.host = host;
            c.offsetNs = offsetNs;
            c.uncertaintyNs = uncertaintyNs;
            run.clocks.push_back({c, 0});
        }
        const Report one = Report::fromRuns({run}, std::nullopt, {});
        const QString md = QString::fromUtf8(ReportFormats::markdown(one));
        QVERIFY2(md.contains(u"clocks measured: cloud +35.00 ms ± 0.40 ms against vehicle"_s),
                 qPrintable(md));
        QVERIFY2(md.contains(u"| *communication, vehicle → cloud, clocks measured ± 0.40 ms* |"_s), qPrintable(md));
        QVERIFY2(md.contains(u"path asymmetry (there − half the round trip) ± 0.40 ms"_s), qPrintable(md));
        const QJsonObject doc = QJsonDocument::fromJson(ReportFormats::json(one)).object();
        const QJsonArray stages = doc.value(u"stages"_s).toArray();
        int corrected = 0;
        for (const QJsonValue& stage : stages)
            if (const QJsonObject c = stage.toObject().value(u"corrected"_s).toObject(); !c.isEmpty()) {
                ++corrected;
                // The crossings take about 19 ms each way in the synthetic run, whatever the offset.
                QVERIFY2(qAbs(c.value(u"mean_ms"_s).toDouble() - 19) < 2,
                         qPrintable(QString::number(c.value(u"mean_ms"_s).toDouble())));
                QCOMPARE(c.value(u"uncertainty_ms"_s).toDouble(), 0.4);
            }
        QCOMPARE(corrected, 2);
        const QString tex = QString::fromUtf8(ReportFormats::latex(one));
        QVERIFY2(tex.contains(u"clocks measured"_s), qPrintable(tex));

        // Without the clocks: as before, no corrected row, the offset estimated from the round trip.
        run.clocks.clear();
        const QString plain
            = QString::fromUtf8(ReportFormats::markdown(Report::fromRuns({run}, std::nullopt, {})));
        QVERIFY(!plain.contains(u"clocks measured"_s));
        QVERIFY(plain.contains(u"two clocks: offset"_s));
    }

    // Issue 13: the events recorded with a run are listed in every format; a run of `watch`
    // (events, no pipeline) has no latency tables or figure.
    void eventsAreListed()
    {
        RunData measured = RunData::fromSamples(paperWithHosts(), SyntheticRun::paper(50, 0, 7).samples);
        measured.info.name = u"measured"_s;
        const qint64 t0 = 1'700'000'000'000'000'000LL;
        measured.events.push_back({u"lab|ros2mqtt|/w/plain|w/plain"_s,
                                   u"alert"_s,
                                   {u"stall"_s},
                                   u"no message at the destination for 1.2 s"_s,
                                   t0,
                                   t0 + 3'000'000'000LL,
                                   R"({"figures":{"lost":7}})"});
        measured.events.push_back({u"bridge:cloud_bridge"_s,
                                   u"warning"_s,
                                   {u"bridge_down"_s},
                                   u"<down & out>"_s,
                                   t0 + 1'000'000'000LL,
                                   0,
                                   "not json"});
        RunData watched;
        watched.info.name = u"watched"_s;
        watched.events.push_back(measured.events.front());

        const Report one = Report::fromRuns({measured}, std::nullopt, {});
        const QString md = QString::fromUtf8(ReportFormats::markdown(one));
        QVERIFY2(md.contains(u"## Events"_s), qPrintable(md));
        QVERIFY2(md.contains(u" | 3.0 s | lab: /w/plain → w/plain | alert | no message at the destination"_s),
                 qPrintable(md));
        QVERIFY(md.contains(u"| open | bridge cloud_bridge | warning | \\<down & out\\> |"_s));
        QVERIFY(md.contains(u"**Events:** 2 (1 alerts)"_s));
        QVERIFY(md.indexOf(u"Latency per stage"_s) < md.indexOf(u"## Events"_s));

        const QJsonArray events
            = QJsonDocument::fromJson(ReportFormats::json(one)).object().value(u"events"_s).toArray();
        QCOMPARE(events.size(), 2);
        QCOMPARE(events[0].toObject().value(u"figures"_s).toObject().value(u"lost"_s).toInt(), 7);
        QCOMPARE(events[0].toObject().value(u"end_ns"_s).toString(), QString::number(t0 + 3'000'000'000LL));
        QVERIFY(events[1].toObject().value(u"end_ns"_s).isNull());

        const Report both = Report::fromRuns({measured, watched}, std::nullopt, {});
        QXmlStreamReader xml(ReportFormats::html(both));
        while (!xml.atEnd())
            xml.readNext();
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(ReportFormats::htmlBody(both, true).contains(u"&lt;down &amp; out&gt;"_s));
        const QString tex = QString::fromUtf8(ReportFormats::latex(both));
        QCOMPARE(tex.count(u"\\begin{tabular}"_s), 3); // stages, totals, events
        QVERIFY(tex.contains(u"watched & "_s));

        const Report onlyEvents = Report::fromRuns({watched}, std::nullopt, {});
        const QString mdEvents = QString::fromUtf8(ReportFormats::markdown(onlyEvents));
        QVERIFY(!mdEvents.contains(u"Latency per stage"_s));
        QVERIFY(!mdEvents.contains(u"Pipeline"_s));
        QVERIFY(mdEvents.contains(u"## Events"_s));
        QVERIFY(!ReportFormats::html(onlyEvents).contains("<svg"));
    }

    // Issue 45: a watch's run holds the observed hop latencies of its links (single-stage series,
    // no pipeline): a report has their rows, says what they are, and draws no pipeline's figure; a
    // measured run has them below its stages.
    void observedHopsAreReported()
    {
        const QString name = SeriesId::observedName(u"/w/plain"_s, u"w/plain"_s);
        QCOMPARE(name, u"observed /w/plain \u2192 w/plain"_s);
        QVERIFY(SeriesId::isObserved(name));
        QVERIFY(!SeriesId::isObserved(u"/bridge/latencies"_s));
        RunData watched;
        watched.info.name = u"watched"_s;
        watched.series = {name, u"/bridge/latencies"_s};
        const qint64 t0 = 1'700'000'000'000'000'000LL;
        for (int i = 0; i < 100; ++i) { // 1.00 to 1.99 ms, and the bridge's own 5 ms
            watched.latencies.push_back(
                {0, 1'000'000LL + i * 10'000LL, t0 + i * 1'000'000LL, t0 + i * 1'000'000LL});
            watched.latencies.push_back({1, 5'000'000LL, t0 + i * 1'000'000LL, t0 + i * 1'000'000LL});
        }
        const Report onlyObserved = Report::fromRuns({watched}, std::nullopt, {});
        QVERIFY(onlyObserved.hasLatency());
        QVERIFY(!onlyObserved.hasPipeline());
        const QString md = QString::fromUtf8(ReportFormats::markdown(onlyObserved));
        QVERIFY2(md.contains(u"| observed /w/plain → w/plain | 1.49 | 1.50 |"_s), qPrintable(md));
        QVERIFY2(md.contains(u"| /bridge/latencies | 5.00 | 5.00 |"_s), qPrintable(md));
        QVERIFY2(md.contains(u"Rows named \"observed\""_s), qPrintable(md));
        QVERIFY2(!md.contains(u"| total"_s), qPrintable(md)); // no pipeline, no total
        QVERIFY(!ReportFormats::html(onlyObserved).contains("<svg"));
        const QJsonArray single = QJsonDocument::fromJson(ReportFormats::json(onlyObserved))
                                      .object()
                                      .value(u"single_stage"_s)
                                      .toArray();
        QCOMPARE(single.size(), 2);
        // in the order their first values came
        QCOMPARE(single[0].toObject().value(u"name"_s).toString(), name);
        QVERIFY(single[0].toObject().value(u"observed"_s).toBool());
        QCOMPARE(single[0].toObject().value(u"stats"_s).toObject().value(u"count"_s).toInt(), 100);
        QCOMPARE(single[1].toObject().value(u"name"_s).toString(), u"/bridge/latencies"_s);
        QVERIFY(!single[1].toObject().value(u"observed"_s).toBool());

        // Beside a measured run's stages, after its total; a run without them has no figure there.
        RunData measured = RunData::fromSamples(paperWithHosts(), SyntheticRun::paper(50, 0, 7).samples);
        measured.info.name = u"measured"_s;
        const Report one = Report::fromRuns({measured}, std::nullopt, {});
        QVERIFY(!QString::fromUtf8(ReportFormats::markdown(one)).contains(u"observed"_s));
        const Report both = Report::fromRuns({measured, watched}, std::nullopt, {});
        const QList<Report::Row> rows = both.rows();
        QCOMPARE(rows.back().label, name);
        const auto total
            = std::find_if(rows.cbegin(), rows.cend(), [](const Report::Row& r) { return r.emphasized; });
        QVERIFY(total != rows.cend() && total < rows.cend() - 2);
        QVERIFY(!both.stats(*both.runs().front(), rows.back()));
        QCOMPARE(both.stats(*both.runs().back(), rows.back())->count, 100);
    }

    // Issue 40: editing a config raised events that went into a run's Events table with no word of
    // where they came from. Each row says the config file and the bridge (older runs: the config's
    // name), in every format; the JSON report keeps config_file.
    void eventsSayWhereTheyCameFrom()
    {
        RunData watched;
        watched.info.name = u"watched"_s;
        const qint64 t0 = 1'700'000'000'000'000'000LL;
        watched.events.push_back(
            {u"lab|ros2mqtt|/w/plain|w/plain"_s,
             u"alert"_s,
             {u"stall"_s},
             u"stalled"_s,
             t0,
             t0 + 1'000'000'000LL,
             R"({"config":"lab","config_file":"/labs/vehicle/lab.yaml","client":"lab_bridge"})"});
        watched.events.push_back(
            {u"bridge:old"_s, u"alert"_s, {u"bridge_down"_s}, u"down"_s, t0 + 1, 0, R"({"config":"old"})"});
        watched.events.push_back({u"discovered|ros2mqtt||d/x"_s,
                                  u"warning"_s,
                                  {u"rate"_s},
                                  u"slow"_s,
                                  t0 + 2,
                                  0,
                                  R"({"config":"discovered"})"});
        const Report report = Report::fromRuns({watched}, std::nullopt, {});
        const QString md = QString::fromUtf8(ReportFormats::markdown(report));
        QVERIFY2(md.contains(u"| Start | From | Duration | Link | Level | Why |"_s), qPrintable(md));
        QVERIFY2(md.contains(u"| lab.yaml, bridge lab_bridge | 1.0 s | lab: /w/plain → w/plain | alert |"_s),
                 qPrintable(md));
        QVERIFY2(md.contains(u"| old | open | bridge old | alert |"_s), qPrintable(md));
        QVERIFY2(md.contains(u"| announced on the broker | open |"_s), qPrintable(md));
        const QString tex = QString::fromUtf8(ReportFormats::latex(report));
        QVERIFY2(tex.contains(u"lab.yaml, bridge lab\\_bridge"_s), qPrintable(tex));
        const QJsonArray events
            = QJsonDocument::fromJson(ReportFormats::json(report)).object().value(u"events"_s).toArray();
        QCOMPARE(events[0].toObject().value(u"config_file"_s).toString(), u"/labs/vehicle/lab.yaml"_s);
    }

    // Issue 31: an event's texts are input. `|` and newlines broke the Markdown table, NUL bytes
    // reached Markdown and HTML, and INT64_MIN to INT64_MAX lasted "-0.0 s" (an overflow).
    void hostileEventTextsStayInTheirCells()
    {
        RunData watched;
        watched.info.name = u"hostile|name\nwith `ticks`"_s;
        const QString nul = QString(QChar(u'\0'));
        watched.events.push_back({u"bridge:a|b"_s,
                                  u"alert"_s,
                                  {u"bridge_down"_s},
                                  u"first|second\nthird\r\nfourth `code` [link](x) <b>"_s + nul + u"\x1b[31m"_s,
                                  std::numeric_limits<qint64>::min(),
                                  std::numeric_limits<qint64>::max(),
                                  {}});
        watched.events.push_back({u"bridge:b"_s, u"warning"_s, {u"x"_s}, u"ok"_s, 1'000'000'000'000'000'000LL,
                                  1'000'000'000'000'000'000LL + 2'500'000'000LL, {}});
        const Report report = Report::fromRuns({watched}, std::nullopt, {});
        const QString md = QString::fromUtf8(ReportFormats::markdown(report));
        QVERIFY(!md.contains(QChar(u'\0')) && !md.contains(QChar(0x1b)));
        // Every row of the events table has as many cell borders as its header (`\|` is no border).
        static const QRegularExpression border(u"(?<!\\\\)\\|"_s);
        const QString table = md.section(u"## Events\n\n"_s, 1).section(u"\n\n"_s, 0, 0);
        const QStringList rows = table.split(u'\n');
        QCOMPARE(rows.size(), 4); // header, rule, two events
        for (const QString& row : rows)
            QVERIFY2(row.count(border) == 7, qPrintable(row)); // six columns since From (issue 40)
        QVERIFY2(rows[2].contains(u"first\\|second third  fourth \\`code\\` [link\\](x) \\<b\\>"_s),
                 qPrintable(rows[2]));
        // A duration without overflow: 2^64 ns are 213,504 days; the other one is 2.5 s.
        QVERIFY2(rows[2].contains(u"| 213504 d |"_s), qPrintable(rows[2]));
        QVERIFY2(rows[3].contains(u"| 2.5 s |"_s), qPrintable(rows[3]));
        QVERIFY(!md.contains(u"-0.0"_s));
        QCOMPARE(ReportFormats::json(report).count("\"duration_s\": -"), 0);
        // The title is one line.
        QVERIFY2(md.startsWith(u"# Watch report: hostile\\|name with \\`ticks\\`\n"_s), qPrintable(md.left(200)));

        const QString html = ReportFormats::htmlBody(report, false);
        QVERIFY(!html.contains(QChar(u'\0')) && !html.contains(QChar(0x1b)));
        QVERIFY(html.contains(u"first|second third  fourth `code` [link](x) &lt;b&gt;"_s));
        const QString tex = QString::fromUtf8(ReportFormats::latex(report));
        QVERIFY(!tex.contains(QChar(u'\0')) && !tex.contains(QChar(0x1b)));
        // The title's comment line cannot end early and put the rest of the name into TeX.
        QVERIFY2(tex.startsWith(u"% Watch report: hostile|name with `ticks`\n"_s), qPrintable(tex.left(200)));
    }

    // Issue 31: a PDF of a run with a 5-million-character name never finished (laying it out grew
    // with the square). Names are cut where they are laid out, keeping their tail.
    void aHugeNameIsCutWhereItIsLaidOut()
    {
        RunData watched;
        watched.info.name = QString(5'000'000, u'n') + u"-tail"_s;
        watched.info.notes = QString(5'000'000, u'o');
        watched.events.push_back({QString(5'000'000, u's'), u"alert"_s, {u"x"_s}, QString(4096, u'd'), 1, 2, {}});
        const Report report = Report::fromRuns({watched}, std::nullopt, {});
        QElapsedTimer clock;
        clock.start();
        const QByteArray pdf = ReportPdf::render(report);
        QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY(pdf.startsWith("%PDF"));
        const QString md = QString::fromUtf8(ReportFormats::markdown(report));
        QVERIFY2(md.size() < 20000, qPrintable(QString::number(md.size())));
        QVERIFY(md.contains(u"…"_s + QString(194, u'n') + u"-tail"_s));
        QVERIFY(!md.contains(QString(201, u'n')));
        const QString html = ReportFormats::htmlBody(report, true);
        QVERIFY2(html.size() < 20000, qPrintable(QString::number(html.size())));
        QVERIFY(QString::fromUtf8(ReportFormats::latex(report)).size() < 20000);
    }

    void pdfHasPagesAndText()
    {
        if (QStandardPaths::findExecutable(u"pdfinfo"_s).isEmpty())
            QSKIP("poppler-utils (pdfinfo) is not installed; scripts/setup.sh installs it");
        QString error;
        Report::Options options;
        options.title = u"Bridgescope PDF test"_s;
        const std::optional<Report> three = noted(Report::build(m_inputs, paperWithHosts(), options), &error);
        QVERIFY2(three, qPrintable(error));
        const QString path = writePdf(*three, u"three.pdf"_s);
        const QString info = run(u"pdfinfo"_s, {path});
        const QRegularExpressionMatch pages = QRegularExpression(u"Pages:\\s+(\\d+)"_s).match(info);
        QVERIFY2(pages.hasMatch(), qPrintable(info));
        QVERIFY(pages.captured(1).toInt() >= 1);
        QVERIFY(info.contains(u"A4"_s) || info.contains(u"595."));
        QVERIFY(info.contains(u"Bridgescope PDF test"_s)); // the document title
        const QString text = run(u"pdftotext"_s, {path, u"-"_s});
        QVERIFY(text.contains(u"Bridgescope PDF test"_s));
        QVERIFY(text.contains(u"overlay"_s));
        QVERIFY(text.contains(u"Total latency per run"_s));
    }

    // Issue 33, point 6: in the PDF's facts, "ROS master" ran into its value.
    void pdfFactLabelsKeepApartFromTheirValues()
    {
        if (QStandardPaths::findExecutable(u"pdftotext"_s).isEmpty())
            QSKIP("poppler-utils (pdftotext) is not installed; scripts/setup.sh installs it");
        RunData watched;
        watched.info.name = u"lab"_s;
        watched.info.broker = u"tcp://127.0.0.1:1883"_s;
        watched.info.rosMaster = u"http://127.0.0.1:11311/"_s;
        watched.events.push_back({u"bridge:x"_s, u"alert"_s, {u"x"_s}, u"down"_s, 1, 2, {}});
        const QString path = writePdf(Report::fromRuns({watched}, std::nullopt, {}), u"facts.pdf"_s);
        // Words with their boxes: the label's last word ends well before its value begins.
        const QString xhtml = run(u"pdftotext"_s, {u"-bbox"_s, path, u"-"_s});
        const QRegularExpression word(u"<word xMin=\"([\\d.]+)\" yMin=\"([\\d.]+)\" xMax=\"([\\d.]+)\" "
                                      "yMax=\"[\\d.]+\">([^<]*)</word>"_s);
        struct Word
        {
            double xMin, yMin, xMax;
            QString text;
        };
        QList<Word> words;
        for (const QRegularExpressionMatch& m : word.globalMatch(xhtml))
            words.append({m.captured(1).toDouble(), m.captured(2).toDouble(), m.captured(3).toDouble(), m.captured(4)});
        int checked = 0;
        for (qsizetype i = 0; i + 1 < words.size(); ++i) {
            const bool label = (words[i].text == u"master"_s && i > 0 && words[i - 1].text == u"ROS"_s)
                || words[i].text == u"Broker"_s;
            if (!label)
                continue;
            const Word& value = words[i + 1];
            QVERIFY2(std::abs(value.yMin - words[i].yMin) < 3, qPrintable(value.text));
            QVERIFY2(value.xMin - words[i].xMax >= 6,
                     qPrintable(u"%1 ends at %2, %3 begins at %4"_s.arg(words[i].text).arg(words[i].xMax)
                                    .arg(value.text).arg(value.xMin)));
            ++checked;
        }
        QCOMPARE(checked, 2);
    }

    // Issue 33, point 6: a comparison PDF's last page was two-thirds blank, its figure alone on it.
    void aFigureFillsThePageItEndsOn()
    {
        const QSizeF page(2000, 3000);
        const QSizeF natural(720, 400); // 2000 x 1111 at full width
        bool newPage = false;
        QCOMPARE(ReportPdf::placeFigure(1000, page, natural, &newPage), QRectF(0, 1000, 2000, 2000.0 * 400 / 720));
        QVERIFY(!newPage);
        // A few lines short: shrunk into the room left, centred, on the same page.
        const QRectF shrunk = ReportPdf::placeFigure(2100, page, natural, &newPage);
        QVERIFY(!newPage);
        QCOMPARE(shrunk.top(), 2100.0);
        QCOMPARE(shrunk.bottom(), 3000.0);
        QVERIFY(std::abs(shrunk.width() / shrunk.height() - 720.0 / 400.0) < 1e-9);
        QVERIFY(std::abs(shrunk.center().x() - 1000) < 1e-9);
        // Far too little room: a new page, full width.
        QCOMPARE(ReportPdf::placeFigure(2700, page, natural, &newPage), QRectF(0, 0, 2000, 2000.0 * 400 / 720));
        QVERIFY(newPage);
    }

    void aComparisonPdfHasNoBlankPage()
    {
        if (QStandardPaths::findExecutable(u"pdftoppm"_s).isEmpty())
            QSKIP("poppler-utils (pdftoppm) is not installed; scripts/setup.sh installs it");
        QString error;
        const std::optional<Report> three = noted(Report::build(m_inputs, paperWithHosts(), {}), &error);
        QVERIFY2(three, qPrintable(error));
        const QString path = writePdf(*three, u"compared.pdf"_s);
        // Per page, where its lowest ink is (the figure is drawn as paths, no text to find): every
        // page is filled at least half.
        const QString prefix = m_dir.filePath(u"compared-page"_s);
        run(u"pdftoppm"_s, {u"-r"_s, u"30"_s, u"-gray"_s, u"-png"_s, path, prefix});
        const QStringList pages = QDir(m_dir.path()).entryList({u"compared-page*.png"_s}, QDir::Files, QDir::Name);
        QVERIFY(!pages.isEmpty());
        for (qsizetype i = 0; i < pages.size(); ++i) {
            const QImage page(m_dir.filePath(pages[i]));
            QVERIFY(!page.isNull());
            int lowest = 0;
            for (int y = 0; y < page.height(); ++y)
                for (int x = 0; x < page.width(); ++x)
                    if (qGray(page.pixel(x, y)) < 200) {
                        lowest = y;
                        break;
                    }
            QVERIFY2(lowest > page.height() / 2,
                     qPrintable(u"page %1 of %2 ends at %3 of %4"_s.arg(i + 1).arg(pages.size()).arg(lowest).arg(page.height())));
        }
    }

    // Issue 33, point 2: one outlier among 10-30 ms does not stretch the report's ECDF axis; it
    // is marked at the axis' end and counted.
    void svgAxisEndsAtAHighQuantile()
    {
        LatencySeries series;
        series.setWindow(0);
        for (int i = 0; i < 200; ++i)
            series.append(10'000'000 + qint64(i) * 100'000); // 10 to 29.9 ms
        series.append(328'000'000);
        const QString svg = QString::fromUtf8(EcdfSvg::render({{u"total"_s, u"#1f77b4"_s, &series}}));
        double highest = 0;
        const QRegularExpression tick(u"<text x=\"[\\d.]+\" y=\"[\\d.]+\" text-anchor=\"middle\">([\\d.]+)</text>"_s);
        for (const QRegularExpressionMatch& m : tick.globalMatch(svg))
            highest = std::max(highest, m.captured(1).toDouble());
        QVERIFY2(highest >= 30 && highest <= 40, qPrintable(QString::number(highest)));
        QVERIFY2(svg.contains(u"total: 1 beyond %1 ms"_s.arg(highest)), qPrintable(svg.right(800)));
        QVERIFY(svg.contains(u"<circle"_s));
        // Without an outlier nothing is marked.
        LatencySeries plain;
        for (int i = 0; i < 200; ++i)
            plain.append(10'000'000 + qint64(i) * 100'000);
        const QString clean = QString::fromUtf8(EcdfSvg::render({{u"total"_s, u"#1f77b4"_s, &plain}}));
        QVERIFY(!clean.contains(u"beyond"_s) && !clean.contains(u"<circle"_s));
    }

    void svgTicksAreRound_data()
    {
        QTest::addColumn<double>("lo");
        QTest::addColumn<double>("hi");
        QTest::addColumn<QList<double>>("ticks");
        QTest::newRow("0..100") << 0.0 << 100.0 << QList<double> {0, 20, 40, 60, 80, 100};
        QTest::newRow("70..136") << 70.0 << 136.0 << QList<double> {80, 100, 120};
        QTest::newRow("negative") << -3.0 << 2.0 << QList<double> {-3, -2, -1, 0, 1, 2};
    }

    void svgTicksAreRound()
    {
        QFETCH(double, lo);
        QFETCH(double, hi);
        QFETCH(QList<double>, ticks);
        QCOMPARE(EcdfSvg::ticks(lo, hi), ticks);
    }
};

QTEST_MAIN(TestReportFormats)
#include "tst_reportformats.moc"
