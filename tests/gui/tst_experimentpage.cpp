// SPDX-License-Identifier: MIT
// The Experiments page against real labs: a typed plan checked as it is edited, a 2-cell plan run
// by the page's child process (embedded mosquitto and rosmaster per cell), its grid coloured by
// state, the live totals equal to those in the run files, a finished cell opened on the Measure
// page, the report exported, Resume of a finished folder, and Stop with clean-up.
#include "app/gui/mainwindow.h"
#include "experiment/experimentreport.h"
#include "exportcheck.h"
#include "latency/latencyseriesset.h"
#include "resulttext.h"
#include "viewhelpers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/experiment/experimentpage.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"
#include "windowparts.h"

#include <algorithm>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTextDocumentFragment>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using namespace WindowParts;

class TestExperimentPage : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    /// What checkExports() reads: an exported report's text.
    QString exported(const QString& name) const
    {
        QFile f(m_dir.filePath(name));
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }

    /// The report exported in every format holds the two cells of the qos factor, each format as
    /// it is written; the Markdown links its figure, an SVG beside it.
    void checkExports() const
    {
        const QStringList ids {u"001-qos-0"_s, u"002-qos-1"_s};
        const QString md = exported(u"r.md"_s);
        QVERIFY2(md.startsWith(u"# "_s) && md.contains(u"## qos"_s) && md.contains(u"](r-qos-ecdf.svg)"_s)
                     && md.contains(ids[0]) && md.contains(ids[1]),
                 qPrintable(md));
        QString problem = ExportCheck::svgProblem(m_dir.filePath(u"r-qos-ecdf.svg"_s), 10, u"qos"_s);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        problem = ExportCheck::pdfProblem(m_dir.filePath(u"r.pdf"_s));
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const QString html = exported(u"r.html"_s);
        QVERIFY2(html.startsWith(u"<!DOCTYPE html>"_s) && html.endsWith(u"</html>\n"_s)
                     && html.contains(u"<svg"_s) && html.contains(ids[0]) && html.contains(ids[1]),
                 qPrintable(html.left(2000)));
        const QString tex = exported(u"r.tex"_s);
        QVERIFY2(tex.contains(u"\\begin{table}"_s)
                     && tex.count(u"\\begin{table}"_s) == tex.count(u"\\end{table}"_s)
                     && tex.contains(u"qos"_s),
                 qPrintable(tex));
        // CSV: a row per cell and stage group, every row as many fields as the header.
        const QStringList rows = exported(u"r.csv"_s).split(u'\n', Qt::SkipEmptyParts);
        QVERIFY2(rows.size() >= 3 && rows[0].startsWith(u"cell,levels,state,group,count,mean_ms"_s),
                 qPrintable(rows.join(u'\n')));
        for (const QString& id : ids) {
            const auto ofCell = std::count_if(rows.begin(), rows.end(), [&](const QString& r) {
                return r.startsWith(id + u","_s) && r.contains(u",complete,"_s)
                    && r.count(u',') == rows[0].count(u',');
            });
            QVERIFY2(ofCell >= 1, qPrintable(id + u": "_s + rows.join(u'\n')));
        }
        const QJsonObject json = QJsonDocument::fromJson(exported(u"r.json"_s).toUtf8()).object();
        const QJsonArray cells = json.value(u"cells"_s).toArray();
        QCOMPARE(cells.size(), 2);
        for (int i = 0; i < 2; ++i) {
            QCOMPARE(cells[i].toObject().value(u"id"_s).toString(), ids[i]);
            QCOMPARE(cells[i].toObject().value(u"state"_s).toString(), u"complete"_s);
        }
        QCOMPARE(json.value(u"tables"_s).toArray().first().toObject().value(u"factor"_s).toString(),
                 u"qos"_s);
    }

    static QTableWidget* cellGrid(const ExperimentPage& page)
    {
        return named<QTableWidget>(page, u"cellGrid"_s);
    }
    static QLabel* planStatus(const ExperimentPage& page) { return named<QLabel>(page, u"planStatus"_s); }
    static QPushButton* runButton(const ExperimentPage& page)
    {
        return named<QPushButton>(page, u"runButton"_s);
    }
    static QPushButton* resumeButton(const ExperimentPage& page)
    {
        return named<QPushButton>(page, u"resumeButton"_s);
    }

    static QString stateOf(const ExperimentPage& page, int row)
    {
        return cellGrid(page)->item(row, page.stateColumn())->text();
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void aPlanIsCheckedAsItIsTyped()
    {
        ExperimentPage page;
        page.setPlanText(u"samples: 10\nfactors:\n  qos: [0, 7]\n"_s);
        QVERIFY2(planStatus(page)->text().contains(u"Not a plan"_s), qPrintable(planStatus(page)->text()));
        QVERIFY(!runButton(page)->isEnabled());
        QString error;
        QVERIFY(!noted(page.run(false), &error));

        page.setPlanText(u"name: grid\nsamples: 10\nfactors:\n  qos: [0, 1]\n  payload: [1000, 50%]\n"_s);
        QVERIFY2(planStatus(page)->text().contains(u"4 cell"_s), qPrintable(planStatus(page)->text()));
        QCOMPARE(cellGrid(page)->rowCount(), 4);
        // The two factors, state, samples, median, p99, the cell.
        QCOMPARE(cellGrid(page)->columnCount(), 7);
        QCOMPARE(cellGrid(page)->horizontalHeaderItem(0)->text(), u"qos"_s);
        QCOMPARE(cellGrid(page)->item(3, 1)->text(), u"50%"_s);
        QCOMPARE(cellGrid(page)->item(3, 6)->text(), u"004-qos-1-payload-50pct"_s);
        QCOMPARE(stateOf(page, 0), u"pending"_s);
        // A cell not run yet has the view's own background, not a black one (issue 33).
        const QTableWidget* grid = cellGrid(page);
        for (int row = 0; row < grid->rowCount(); ++row)
            for (int col = 0; col < grid->columnCount(); ++col)
                QVERIFY2(grid->item(row, col)->data(Qt::BackgroundRole).isNull(),
                         qPrintable(u"row %1 column %2"_s.arg(row).arg(col)));
        QVERIFY(runButton(page)->isEnabled());
        QVERIFY(!resumeButton(page)->isEnabled()); // no folder with an experiment
        // Without a folder it says so instead of running somewhere.
        QVERIFY(!noted(page.run(false), &error));
        QVERIFY2(error.contains(u"folder"_s), qPrintable(error));
    }

    // A plan's name is shown as it is written: a name that looks like HTML is no markup that
    // swallows the plan's status (it read "N ~ ^" for "N ~ ^ <script> <b>x", without its cells).
    void aPlanNameThatLooksLikeHtmlIsShownAsWritten()
    {
        ExperimentPage page;
        page.resize(1280, 800);
        page.setPlanText(u"name: 'N ~ ^ <script> <b>x'\nsamples: 10\nfactors:\n  qos: [0, 1]\n"_s);
        const QLabel* status = planStatus(page);
        // What the label draws: rich text (Qt's AutoText guess) loses its tags and what a
        // <script> holds.
        const bool rich = status->textFormat() == Qt::RichText
            || (status->textFormat() == Qt::AutoText && Qt::mightBeRichText(status->text()));
        const QString shown = rich ? QTextDocumentFragment::fromHtml(status->text()).toPlainText() : status->text();
        QVERIFY2(shown.contains(u"N ~ ^ <script> <b>x: 2 cell"_s), qPrintable(shown));
    }

    void aPlanRunsWithItsCellsLiveAndReported()
    {
        MainWindow window;
        window.show();
        ExperimentPage& page = *experimentPage(window);
        page.setProgram(QStringLiteral(BRIDGESCOPE_BINARY));
        window.pages()->setCurrentWidget(&page);
        page.setPlanText(u"name: page test\nsamples: 40\nwarmup: 3\ndefaults: {payload: 20000}\n"
                         "factors:\n  qos: [0, 1]\n"_s);
        const QString out = m_dir.filePath(u"page"_s);
        page.setFolder(out);
        QSignalSpy finished(&page, &ExperimentPage::experimentFinished);
        QString error;
        QVERIFY2(noted(page.run(false), &error), qPrintable(error));
        QVERIFY(page.isRunning());
        QVERIFY(!runButton(page)->isEnabled());
        QVERIFY(named<QPushButton>(page, u"stopButton"_s)->isEnabled());
        QVERIFY(named<QPlainTextEdit>(page, u"planEditor"_s)->isReadOnly());
        // The first cell shows as running while it records, with its totals coming in.
        QVERIFY(QTest::qWaitFor([&] { return stateOf(page, 0) == u"running"_s; }, 60000));
        QVERIFY(QTest::qWaitFor(
            [&] {
                const LatencySeries* s = page.liveSeries()->find(u"qos 0"_s);
                return (s && s->count() > 0) || !finished.isEmpty();
            },
            60000));
        QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, 240000));
        QCOMPARE(finished.first().first().toInt(), 0);
        QCOMPARE(stateOf(page, 0), u"complete"_s);
        QCOMPARE(stateOf(page, 1), u"complete"_s);
        QCOMPARE(named<QProgressBar>(page, u"experimentProgress"_s)->value(), 2);
        QVERIFY(cellGrid(page)->item(0, 0)->background().color().green() > 0); // coloured by state
        QVERIFY(!named<QPlainTextEdit>(page, u"experimentLog"_s)->toPlainText().isEmpty());

        // The report comes from the folder, and the live totals are those in the run files.
        QVERIFY(QTest::qWaitFor([&] { return page.report().has_value(); }, 30000));
        const ExperimentReport& report = *page.report();
        QCOMPARE(report.cells().size(), 2);
        for (int i = 0; i < 2; ++i) {
            const ExperimentReport::Cell& c = report.cells()[i];
            QVERIFY(c.total);
            const LatencySeries* live = page.liveSeries()->find(page.cells()[i].label());
            QVERIFY(live);
            QCOMPARE(live->totalCount(), c.total->totalCount());
            QVERIFY2(std::abs(live->stats().mean - c.total->stats().mean) < 1e-3,
                     qPrintable(u"%1 vs %2"_s.arg(live->stats().mean).arg(c.total->stats().mean)));
        }
        QCOMPARE(named<EcdfChart>(page, u"totalsChart"_s)->series().size(), 2);
        QVERIFY(cellGrid(page)->item(1, page.stateColumn() + 2)->text().toDouble() > 0); // median
        const QString reportText = named<QTextBrowser>(page, u"reportView"_s)->toPlainText();
        QVERIFY2(reportText.contains(u"qos"_s), qPrintable(reportText));

        // A finished cell opens on the Measure page.
        emit cellGrid(page)->cellActivated(1, 0);
        QCOMPARE(window.pages()->currentWidget(), window.measurePage());
        QVERIFY2(
            named<QLabel>(*window.measurePage()->runBar(), u"runStatus"_s)->text().contains(u"002-qos-1"_s),
            qPrintable(named<QLabel>(*window.measurePage()->runBar(), u"runStatus"_s)->text()));
        window.measurePage()->runBar()->backToLive();
        window.pages()->setCurrentWidget(&page);

        // The report in every format; Markdown with its figure beside it.
        for (const QString& name : {u"r.md"_s, u"r.pdf"_s, u"r.html"_s, u"r.tex"_s, u"r.csv"_s, u"r.json"_s})
            QVERIFY2(noted(page.exportReport(m_dir.filePath(name)), &error),
                     qPrintable(name + u": "_s + error));
        checkExports();
        if (QTest::currentTestFailed())
            return;
        QVERIFY(!noted(page.exportReport(m_dir.filePath(u"r.doc"_s)), &error));

        // Run again into the same folder is refused; Resume finds nothing left to do.
        QVERIFY(!noted(page.run(false), &error));
        QVERIFY2(error.contains(u"Resume"_s), qPrintable(error));
        QVERIFY(resumeButton(page)->isEnabled());
        finished.clear();
        QVERIFY2(noted(page.run(true), &error), qPrintable(error));
        QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, 30000));
        QCOMPARE(finished.first().first().toInt(), 0);
        QCOMPARE(stateOf(page, 0), u"complete"_s);

        // Opening the folder afresh shows the same cells and states.
        ExperimentPage other;
        QVERIFY2(noted(other.openFolder(out), &error), qPrintable(error));
        QCOMPARE(cellGrid(other)->rowCount(), 2);
        QCOMPARE(stateOf(other, 1), u"complete"_s);
        QVERIFY(QTest::qWaitFor([&] { return other.liveSeries()->find(u"qos 1"_s) != nullptr; }, 30000));
    }

    // What the page reads from its child is bounded and checked: a child that prints garbage,
    // lines for cells that do not exist, numbers that overflow, a 5 MiB line, a run path outside
    // the folder, and then exits, leaves the page working with only the sound lines applied.
    void aChildPrintingGarbageChangesOnlyWhatItMaySay()
    {
        const QString script = m_dir.filePath(u"hostile.sh"_s);
        QFile f(script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#!/bin/sh\n"
                "echo '{\"event\":\"started\",\"index\":0,\"cell\":\"001-qos-0\"}'\n"
                "echo 'not json at all'\n"
                "echo '{\"event\":\"started\",\"index\":99}'\n"
                "echo '{\"event\":\"started\",\"index\":-5}'\n"
                "echo '{\"event\":\"started\",\"index\":1,\"cell\":\"someone-else\"}'\n"
                "echo '{\"event\":\"progress\",\"index\":0,\"total_ms\":\"oops\"}'\n"
                "echo '{\"event\":\"progress\",\"index\":0,\"samples\":1e300,"
                "\"total_ms\":[1.5,\"x\",null,1e308,-1e308,2.5,[3]],\"remaining_s\":1e300}'\n"
                "head -c 5242880 /dev/zero | tr '\\0' 'x'; echo\n"
                "echo '{\"event\":\"finished\",\"index\":0,\"cell\":\"001-qos-0\",\"state\":\"complete\","
                "\"samples\":2,\"run\":\"../../../etc/passwd\"}'\n"
                "echo '{\"event\":\"throughput\",\"rate_hz\":\"fast\"}'\n"
                "exit 0\n");
        f.close();
        QVERIFY(f.setPermissions(f.permissions() | QFile::ExeOwner));
        ExperimentPage page;
        page.setProgram(script);
        page.setPlanText(u"name: hostile\nsamples: 10\nfactors:\n  qos: [0, 1]\n"_s);
        page.setFolder(m_dir.filePath(u"hostile"_s));
        QSignalSpy finished(&page, &ExperimentPage::experimentFinished);
        QString error;
        QVERIFY2(noted(page.run(false), &error), qPrintable(error));
        QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, 30000));
        QCOMPARE(finished.first().first().toInt(), 0);
        QCOMPARE(stateOf(page, 0), u"complete"_s);
        QCOMPARE(stateOf(page, 1), u"pending"_s);
        QCOMPARE(page.statuses()[0].samples, 2);
        QCOMPARE(page.statuses()[0].run, u"runs/001-qos-0.bsrun"_s); // not the line's path
        const LatencySeries* live = page.liveSeries()->find(u"qos 0"_s);
        QVERIFY(live);
        QCOMPARE(live->totalCount(), 2); // 1.5 and 2.5 ms; the rest is no measurement
        QCOMPARE(live->stats().mean, 2.0);
        QVERIFY(!page.liveSeries()->find(u"qos 1"_s));
        QVERIFY(runButton(page)->isEnabled());
    }

    void stopCleansUpAndLeavesTheCellToResume()
    {
        ExperimentPage page;
        page.setProgram(QStringLiteral(BRIDGESCOPE_BINARY));
        page.setPlanText(u"name: stopped\nsamples: 5000\nwarmup: 3\ndefaults: {payload: 1000}\n"
                         "factors:\n  qos: [0]\n"_s);
        const QString out = m_dir.filePath(u"stopped"_s);
        page.setFolder(out);
        QSignalSpy finished(&page, &ExperimentPage::experimentFinished);
        QString error;
        QVERIFY2(noted(page.run(false), &error), qPrintable(error));
        QVERIFY(QTest::qWaitFor(
            [&] {
                const LatencySeries* s = page.liveSeries()->find(u"qos 0"_s);
                return (s && s->count() >= 5) || !finished.isEmpty();
            },
            60000));
        QVERIFY(finished.isEmpty());
        page.stop();
        QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, 30000));
        QCOMPARE(finished.first().first().toInt(), 130);
        QCOMPARE(stateOf(page, 0), u"pending"_s);
        // A cell not run yet has the view's own background, not a black one (issue 33).
        const QTableWidget* grid = cellGrid(page);
        for (int row = 0; row < grid->rowCount(); ++row)
            for (int col = 0; col < grid->columnCount(); ++col)
                QVERIFY2(grid->item(row, col)->data(Qt::BackgroundRole).isNull(),
                         qPrintable(u"row %1 column %2"_s.arg(row).arg(col)));
        QVERIFY(runButton(page)->isEnabled());
        QVERIFY(resumeButton(page)->isEnabled());
        QString why;
        const auto plan = noted(ExperimentPlan::readFile(QDir(out).filePath(u"plan.yaml"_s)), &why);
        QVERIFY2(plan, qPrintable(why));
        const auto state = noted(ExperimentFolder(out).readState(*plan), &why);
        QVERIFY2(state, qPrintable(why));
        QCOMPARE(state->first().state, CellStatus::Pending);
    }
};

QTEST_MAIN(TestExperimentPage)
#include "tst_experimentpage.moc"
