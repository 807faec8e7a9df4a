// SPDX-License-Identifier: MIT
// Runs and reports in the GUI: record from the Measure page against a real rosmaster, open the run
// and go back to live, compare three suite CSV files on the Reports page (three columns), export
// every kind of file, and save and copy the chart.
#include "app/gui/mainwindow.h"
#include "exportcheck.h"
#include "record/runfile.h"
#include "record/suitecsv.h"
#include "resulttext.h"
#include "session/measuresession.h"
#include "syntheticrun.h"
#include "testservers.h"
#include "viewhelpers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/runbar.h"
#include "widgets/reports/reportspage.h"
#include "windowparts.h"

#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QGuiApplication>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QMimeData>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using namespace WindowParts;

namespace {
/// Writes `run` as a suite CSV, `hours` later than it was made (runs of a day never share samples).
QString writeCsv(const QTemporaryDir& dir, const QString& name, SyntheticRun run, int hours)
{
    for (std::vector<qint64>& sample : run.samples)
        for (qint64& t : sample)
            t += hours * 3600LL * 1'000'000'000LL;
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(SuiteCsv::write(run.topics, run.samples));
    return path;
}

/// The first Markdown table's header row: "| Mean latency [ms] | run a | run b | ... |".
QStringList markdownColumns(const QString& md)
{
    for (const QString& line : md.split(u'\n'))
        if (line.startsWith(u"| "_s)) {
            QStringList cells = line.split(u'|');
            cells.removeFirst();
            cells.removeLast();
            for (QString& c : cells)
                c = c.trimmed();
            return cells;
        }
    return {};
}
} // namespace

class TestReportsPage : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    QTemporaryDir m_dir;
    QStringList m_csvs;

    /// Shows `w` on the Measure page with the test's master and the pipeline `yaml` (written as
    /// `name`) loaded.
    bool showMeasuring(MainWindow& w, const QString& name, const QByteArray& yaml)
    {
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        w.show();
        w.pages()->setCurrentWidget(w.measurePage());
        QFile f(m_dir.filePath(name));
        if (!QTest::qWaitForWindowExposed(&w) || !f.open(QIODevice::WriteOnly) || f.write(yaml) != yaml.size())
            return false;
        f.close();
        QString error;
        const bool loaded = noted(w.measurePage()->loadPipeline(f.fileName()), &error);
        if (!loaded)
            qWarning("%s", qPrintable(error));
        return loaded;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_servers.startRosMaster());
        m_servers.exportRosEnvironment();
        m_csvs << writeCsv(m_dir, u"mqtt_client.csv"_s, SyntheticRun::paper(300, 250'000'000, 1), 0)
               << writeCsv(m_dir, u"mqtt_bridge.csv"_s, SyntheticRun::paper(300, 250'000'000, 2), 1)
               << writeCsv(m_dir, u"overlay.csv"_s, SyntheticRun::paper(300, 250'000'000, 3), 2);
    }

    // A recording that gets nothing says, within seconds, what it waits for: which topics, from
    // which ROS master, since when (issue 33; the record command says so since issue 17).
    void aSilentRecordingSaysWhatItWaitsFor()
    {
        MainWindow w;
        w.resize(1280, 800);
        QVERIFY(showMeasuring(w, u"silent.yaml"_s,
                              "topics_in_order: [/quiet/lab/a, /quiet/lab/b, /quiet/lab/c, /quiet/lab/d, "
                              "/quiet/lab/e]\n"));
        RunBar* bar = w.measurePage()->runBar();
        QLabel* runStatus = named<QLabel>(*bar, u"runStatus"_s);
        QString error;
        const QTime started = QTime::currentTime();
        QVERIFY2(
            noted(bar->startRecording(m_dir.filePath(u"silent.bsrun"_s), u"silent"_s, QString()), &error),
            qPrintable(error));
        QVERIFY(!runStatus->text().contains(u"nothing has arrived"_s)); // not at once
        QTRY_VERIFY_WITH_TIMEOUT(runStatus->text().contains(u"nothing has arrived"_s), 9000);
        const QString said = runStatus->toolTip();
        QVERIFY2(said.startsWith(u"nothing has arrived since %1 ("_s.arg(started.toString(u"HH:mm:ss"_s)))
                     || said.startsWith(u"nothing has arrived since %1 ("_s.arg(started.addSecs(1).toString(u"HH:mm:ss"_s))),
                 qPrintable(said));
        QVERIFY2(said.contains(u"no stamp yet on 5 topics under /quiet/lab/ (a, b, c, d, and 1 more)"_s),
                 qPrintable(said));
        QVERIFY2(said.contains(u"the ROS master "_s + m_servers.rosMasterUri()), qPrintable(said));
        // Shown where the recording is, within the window's width.
        QVERIFY(runStatus->isVisible());
        QVERIFY2(w.width() <= 1280, qPrintable(QString::number(w.width())));
        QVERIFY2(noted(bar->stopRecording(), &error) || !error.isEmpty(), qPrintable(error));
        QCOMPARE(runStatus->toolTip(), QString());
    }

    void recordsOpensAndGoesBackToLive()
    {
        MainWindow w;
        QVERIFY(showMeasuring(w, u"lab.yaml"_s, "topics_in_order: [/lab/a, /lab/b, /lab/c]\nhosts: {/lab/c: cloud}\n"));
        MeasurePage* page = w.measurePage();
        RunBar* bar = page->runBar();
        QLabel* runStatus = named<QLabel>(*bar, u"runStatus"_s);
        QString error;

        const QString path = m_dir.filePath(u"runs/gui.bsrun"_s); // the folder is made on the way
        QSignalSpy recorded(bar, &RunBar::runRecorded);
        QVERIFY2(noted(bar->startRecording(path, u"gui run"_s, u"from the test"_s), &error),
                 qPrintable(error));
        QVERIFY(named<QPushButton>(*bar, u"recordButton"_s)->text().contains(u"Stop"_s));
        QVERIFY(!named<QPushButton>(*bar, u"openButton"_s)->isEnabled());
        QVERIFY(
            !named<QSpinBox>(*page, u"windowBox"_s)->isEnabled()); // the pipeline is fixed while recording

        QProcess pub;
        pub.setProcessEnvironment(m_servers.rosEnvironment());
        pub.start(QStringLiteral(STAMP_PUBLISHER),
                  {u"--samples"_s, u"150"_s, u"--rate"_s, u"100"_s, u"--first-sample"_s, u"1700300000"_s,
                   u"--stamp"_s, u"/lab/a:0"_s, u"--stamp"_s, u"/lab/b:2000"_s, u"--stamp"_s,
                   u"/lab/c:7000"_s});
        QTRY_VERIFY_WITH_TIMEOUT(w.measure()->engine().samples() >= 150, 30000);
        QVERIFY(pub.waitForFinished(10000));
        QVERIFY(runStatus->text().contains(u"gui run"_s));
        const LatencyStats live = w.measure()->engine().series(w.measure()->engine().totalSeries()).stats();
        QVERIFY2(noted(bar->stopRecording(), &error), qPrintable(error));
        QCOMPARE(recorded.count(), 1);
        QCOMPARE(recorded.first().first().toString(), path);
        // The run goes to the Reports page's inputs straight away.
        QVERIFY(reportsPage(w)->inputs().contains(path));
        QVERIFY(named<QSpinBox>(*page, u"windowBox"_s)->isEnabled());

        // Opened again, the Measure page shows it as it was; live stamps wait.
        QVERIFY2(noted(bar->openRun(path), &error), qPrintable(error));
        QVERIFY(w.measure()->isShowingRun());
        QVERIFY(named<QPushButton>(*bar, u"liveButton"_s)->isVisible());
        QVERIFY(!named<QPushButton>(*bar, u"recordButton"_s)->isEnabled());
        const LatencyStats shown = w.measure()->engine().series(w.measure()->engine().totalSeries()).stats();
        QCOMPARE(shown.count, live.count);
        QCOMPARE(shown.mean, live.mean);
        QCOMPARE(shown.p999, live.p999);
        QVERIFY(named<QLabel>(*page, u"modeLabel"_s)->text().contains(u"gui run"_s)
                || runStatus->text().contains(u"gui run"_s));

        // Save the chart as PNG and SVG, copy it to the clipboard.
        const QString png = m_dir.filePath(u"chart.png"_s);
        const QString svg = m_dir.filePath(u"chart.svg"_s);
        QVERIFY2(noted(page->saveChart(png), &error), qPrintable(error));
        QVERIFY2(noted(page->saveChart(svg), &error), qPrintable(error));
        const QImage image(png);
        QVERIFY(!image.isNull() && image.width() > 100);
        const QString svgProblem = ExportCheck::svgProblem(svg, 11);
        QVERIFY2(svgProblem.isEmpty(), qPrintable(svgProblem));
        QVERIFY(!noted(page->saveChart(m_dir.filePath(u"chart.bmpx"_s)), &error));
        page->chart()->copyToClipboard();
        QVERIFY(!QGuiApplication::clipboard()->image().isNull());

        // Save As of a shown run writes a copy that opens.
        const QString copy = m_dir.filePath(u"copy.bsrun"_s);
        QVERIFY2(noted(bar->saveRunAs(copy), &error), qPrintable(error));
        const std::optional<RunData> original = noted(RunFile::read(path), &error);
        QVERIFY2(original, qPrintable(error));
        const std::optional<RunData> copied = noted(RunFile::read(copy), &error);
        QVERIFY2(copied, qPrintable(error));
        QCOMPARE(copied->info.name, u"gui run"_s);
        QCOMPARE(copied->info.notes, u"from the test"_s);
        QCOMPARE(copied->topics, original->topics);
        QCOMPARE(qint64(copied->stamps.size()), qint64(original->stamps.size()));
        QVERIFY(copied->stamps.size() >= 3 * 150); // every stamp of 150 samples on three topics
        for (std::size_t i = 0; i < copied->stamps.size(); ++i)
            QVERIFY(copied->stamps[i].topic == original->stamps[i].topic
                    && copied->stamps[i].sampleNs == original->stamps[i].sampleNs
                    && copied->stamps[i].timeNs == original->stamps[i].timeNs
                    && copied->stamps[i].receivedNs == original->stamps[i].receivedNs);

        bar->backToLive();
        QVERIFY(!w.measure()->isShowingRun());
        QVERIFY(named<QPushButton>(*bar, u"recordButton"_s)->isEnabled());
        QVERIFY(named<QPushButton>(*bar, u"liveButton"_s)->isHidden());

        // A broken file is refused with its name; the page stays live.
        const QString broken = m_dir.filePath(u"broken.bsrun"_s);
        QFile b(broken);
        QVERIFY(b.open(QIODevice::WriteOnly));
        b.write("SQLite format 3\0garbage", 23);
        b.close();
        QVERIFY(!noted(bar->openRun(broken), &error));
        QVERIFY2(error.contains(u"broken.bsrun"_s), qPrintable(error));
        QVERIFY(!w.measure()->isShowingRun());
    }

    void comparesThreeRunsAndExportsEveryFormat()
    {
        MainWindow w;
        ReportsPage* reports = reportsPage(w);
        w.resize(1280, 800); // the size of a first start (the README shows it)
        w.show();
        w.pages()->setCurrentWidget(reports);
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        QSignalSpy updated(reports, &ReportsPage::previewUpdated);
        reports->setFormat(ReportFormats::Format::Markdown);
        reports->addInputs(m_csvs.mid(0, 2));
        // The third comes dropped from a file manager.
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(m_csvs[2])});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(reports, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(reports, &drop);
        QCOMPARE(named<QListWidget>(*reports, u"reportInputs"_s)->count(), 3);
        QTRY_VERIFY_WITH_TIMEOUT(!updated.isEmpty() && !reports->isBusy(), 30000);
        const QStringList columns = markdownColumns(reports->previewText());
        QCOMPARE(columns.size(), 4); // the stages and one column per run, in input order
        QCOMPARE(columns.mid(1), (QStringList {u"mqtt_client"_s, u"mqtt_bridge"_s, u"overlay"_s}));
        QVERIFY(reports->previewText().contains(u"Total"_s));

        // Joined, the three files are one run: one column.
        updated.clear();
        named<QCheckBox>(*reports, u"joinBox"_s)->click();
        QTRY_VERIFY_WITH_TIMEOUT(!updated.isEmpty() && !reports->isBusy(), 30000);
        QCOMPARE(markdownColumns(reports->previewText()).first(), u"Stage"_s); // one run's statistics
        named<QCheckBox>(*reports, u"joinBox"_s)->click();
        QTRY_VERIFY_WITH_TIMEOUT(markdownColumns(reports->previewText()).size() == 4 && !reports->isBusy(),
                                 30000);

        // The HTML preview shows the figure.
        updated.clear();
        reports->setFormat(ReportFormats::Format::Html);
        QTRY_VERIFY_WITH_TIMEOUT(!updated.isEmpty() && !reports->isBusy(), 30000);
        QTest::qWait(50);
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            w.grab().save(shots + u"/reports.png"_s);

        QString error;
        const QString pdf = m_dir.filePath(u"report.pdf"_s);
        reports->setFormat(ReportFormats::Format::Pdf);
        QVERIFY2(noted(reports->exportTo(pdf), &error), qPrintable(error));
        QFile pdfFile(pdf);
        QVERIFY(pdfFile.open(QIODevice::ReadOnly));
        QVERIFY(pdfFile.read(5) == "%PDF-");
        if (const QString pdfinfo = QStandardPaths::findExecutable(u"pdfinfo"_s); !pdfinfo.isEmpty()) {
            QProcess p;
            p.start(pdfinfo, {pdf});
            QVERIFY(p.waitForFinished(30000));
            QVERIFY(QString::fromUtf8(p.readAllStandardOutput())
                        .contains(QRegularExpression(u"Pages:\\s+[1-9]"_s)));
        }
        // The suite CSV holds one run: a comparison is refused with the way out, joined it is written.
        updated.clear();
        reports->setFormat(ReportFormats::Format::Csv);
        QVERIFY(!noted(reports->exportTo(m_dir.filePath(u"compared.csv"_s)), &error));
        // Issue 40, point 10: the window names its checkbox, not the command line's --join.
        const QString joinBox = named<QCheckBox>(*reports, u"joinBox"_s)->text().remove(u'&');
        QVERIFY2(error.contains(joinBox) && !error.contains(u"--join"_s), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(!updated.isEmpty() && !reports->isBusy(), 30000);
        QVERIFY2(reports->previewText().contains(joinBox) && !reports->previewText().contains(u"--join"_s),
                 qPrintable(reports->previewText()));
        QVERIFY(!QFile::exists(m_dir.filePath(u"compared.csv"_s)));
        named<QCheckBox>(*reports, u"joinBox"_s)->click();
        QVERIFY2(noted(reports->exportTo(m_dir.filePath(u"joined.csv"_s)), &error), qPrintable(error));
        QFile joined(m_dir.filePath(u"joined.csv"_s));
        QVERIFY(joined.open(QIODevice::ReadOnly));
        const std::optional<SuiteCsv::Data> rows
            = noted(SuiteCsv::parse(joined.readAll(), joined.fileName()), &error);
        QVERIFY2(rows, qPrintable(error));
        QCOMPARE(rows->samples.size(), std::size_t(900)); // three runs of 300 samples
        named<QCheckBox>(*reports, u"joinBox"_s)->click();
        for (const auto& [format, suffix] : {std::pair {ReportFormats::Format::Json, u"json"_s},
                                             {ReportFormats::Format::Latex, u"tex"_s},
                                             {ReportFormats::Format::Html, u"html"_s}}) {
            reports->setFormat(format);
            const QString out = m_dir.filePath(u"report."_s + suffix);
            QVERIFY2(noted(reports->exportTo(out), &error), qPrintable(error));
            QVERIFY2(QFileInfo(out).size() > 100, qPrintable(out));
        }
        // An export that cannot be written says so and leaves nothing behind.
        const QString nowhere = m_dir.filePath(u"missing/dir/report.md"_s);
        reports->setFormat(ReportFormats::Format::Markdown);
        QVERIFY(!noted(reports->exportTo(nowhere), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!QFile::exists(nowhere));
    }

    // A long export shows progress and stops when the user cancels; nothing is written.
    void aLongExportCanBeCancelled()
    {
        const QString big = writeCsv(m_dir, u"long.csv"_s, SyntheticRun::paper(180'000, 0, 9), 5);
        MainWindow w;
        ReportsPage* reports = reportsPage(w);
        w.show();
        w.pages()->setCurrentWidget(reports);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        reports->setFormat(ReportFormats::Format::Html);
        reports->addInputs({big});
        QTRY_VERIFY_WITH_TIMEOUT(!reports->isBusy(), 60000); // the preview first
        bool sawProgress = false;
        QTimer::singleShot(300, reports, [&] {
            if (auto* dialog = reports->findChild<QProgressDialog*>()) {
                sawProgress = true;
                dialog->cancel();
            }
        });
        const QString out = m_dir.filePath(u"cancelled.html"_s);
        QString error;
        QVERIFY(!noted(reports->exportTo(out), &error));
        QVERIFY(sawProgress);
        QVERIFY2(error.contains(u"cancelled"_s), qPrintable(error));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_MAIN(TestReportsPage)
#include "tst_reportspage.moc"
