// SPDX-License-Identifier: MIT
// The Measure page on live stamps from a real rosmaster: the paper's pipeline with two hosts,
// Table I with derived rows, ECDFs, pause and reset, and editing the pipeline by keyboard and drag.
#include "app/gui/mainwindow.h"
#include "clock/clockserver.h"
#include "fixtures.h"
#include "models/latencystatsmodel.h"
#include "mqtt/mqttclockserver.h"
#include "resulttext.h"
#include "session/measuresession.h"
#include "syntheticrun.h"
#include "testservers.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/common/livetext.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/measure/measurepage.h"
#include "widgets/measure/pipelinemodel.h"
#include "widgets/measure/recorddialog.h"
#include "widgets/measure/stamptopicmodel.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QLogValueAxis>
#include <QProcess>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

using namespace Qt::StringLiterals;
using namespace ViewHelpers;

namespace {
/// The paper's stage means (Table I, mqtt_client) as stamp offsets in µs; the cloud's clock runs
/// `cloudAheadUs` (250 ms) ahead of the vehicle's.
QStringList paperStamps(const QStringList& topics, qint64 cloudAheadUs = 250'000)
{
    const qint64 stageUs[] = {200, 300, 19000, 100, 3600, 43400, 100, 100, 19000, 100, 200};
    const std::vector<bool> cloud = SyntheticRun::paper(1, 0, 1).remote;
    QStringList args;
    qint64 t = 0;
    for (int i = 0; i < topics.size(); ++i) {
        if (i > 0)
            t += stageUs[i - 1];
        args << u"--stamp"_s << u"%1:%2"_s.arg(topics[i]).arg(t + (cloud[std::size_t(i)] ? cloudAheadUs : 0));
    }
    return args;
}

int rowOf(QAbstractItemModel* model, const QString& id)
{
    for (int r = 0; r < model->rowCount(); ++r)
        if (model->index(r, 0).data(LatencyStatsModel::SeriesIdRole).toString() == id)
            return r;
    return -1;
}
} // namespace

class TestMeasurePage : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    QTemporaryDir m_dir;

    /// Runs stamp_publisher; `seed` also picks the first sample's stamp, so runs never share samples.
    std::unique_ptr<QProcess> publish(const QStringList& stamps, int samples, int seed)
    {
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(m_servers.rosEnvironment());
        p->start(QStringLiteral(STAMP_PUBLISHER),
                 QStringList {u"--samples"_s, QString::number(samples), u"--rate"_s, u"100"_s,
                              u"--jitter-us"_s, u"150"_s, u"--seed"_s, QString::number(seed),
                              u"--first-sample"_s, QString::number(1'700'000'000 + seed * 10'000)}
                     + stamps);
        return p;
    }

    /// The suite's pipeline file plus our hosts extension and `more`, as `name`; its topics in `topics`.
    QString writePaperPipeline(const QString& name, const QByteArray& more, QStringList* topics)
    {
        QByteArray yaml = Fixtures::read(u"benchmarking_suite/metrics_logger_mqtt_interface.yaml"_s);
        const Result<Pipeline> suite = Pipeline::read(yaml);
        if (!suite)
            return {};
        *topics = suite->topics();
        yaml += "\n" + more + "hosts:\n";
        for (int i = 0; i < topics->size(); ++i)
            yaml += "  " + topics->at(i).toUtf8() + ": " + SyntheticRun::paper(1, 0, 1).hosts()[i].toUtf8()
                + "\n";
        QFile f(m_dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(yaml) != yaml.size())
            return {};
        return f.fileName();
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_servers.startRosMaster());
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        m_servers.exportRosEnvironment();
    }

    void measuresThePapersPipelineLive()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        MeasurePage* page = w.measurePage();
        QTableView* statsView = named<QTableView>(*page, u"statsView"_s);
        MeasureSession* measure = w.measure();
        QAbstractItemModelTester statsTester(statsView->model());
        QAbstractItemModelTester pipelineTester(named<PipelineModel>(*page, u"pipelineModel"_s));
        QAbstractItemModelTester seenTester(named<QListView>(*page, u"stampTopicsView"_s)->model());
        w.resize(1280, 800); // the size of a first start (the README shows it)
        w.show();
        w.pages()->setCurrentWidget(page);
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        // The suite's pipeline file plus our hosts extension.
        QStringList topics;
        const QString file = writePaperPipeline(u"pipeline.yaml"_s, {}, &topics);
        QVERIFY(!file.isEmpty());
        QString error;
        QVERIFY2(noted(page->loadPipeline(file), &error), qPrintable(error));
        QCOMPARE(named<PipelineModel>(*page, u"pipelineModel"_s)->rowCount(), 12);
        QCOMPARE(named<QSpinBox>(*page, u"windowBox"_s)->value(), 600);
        QVERIFY(named<QLabel>(*page, u"modeLabel"_s)->text().contains(u"pipeline.yaml"_s));
        // 11 stages, the total, round trip, one way and clock offset.
        QAbstractItemModel* table = statsView->model();
        QCOMPARE(table->rowCount(), 15);

        auto pub = publish(paperStamps(topics), 400, 3);
        QTRY_VERIFY_WITH_TIMEOUT(measure->engine().samples() >= 400, 60000);
        QTRY_COMPARE_WITH_TIMEOUT(
            table->index(rowOf(table, u"total"_s), LatencyStatsModel::CountColumn).data().toString(),
            u"400"_s, 5000);
        QVERIFY(pub->waitForFinished(10000));

        // Table I: what the table shows is what the engine computed.
        const LatencyEngine& e = measure->engine();
        const int total = rowOf(table, u"total"_s);
        QCOMPARE(table->index(total, LatencyStatsModel::MeanColumn).data().toString(),
                 LatencyStatsModel::msText(e.series(e.totalSeries()).stats().mean));
        QVERIFY(table->index(total, 0).data(Qt::FontRole).value<QFont>().bold());
        const int crossing = rowOf(table, u"stage:2"_s);
        QVERIFY(table->index(crossing, 0).data().toString().startsWith(u"⇄"_s));
        QVERIFY(table->index(crossing, 0).data(Qt::FontRole).value<QFont>().italic());
        // The cloud's 250 ms lead shows up in the offset estimate, not in the one-way latency.
        const LatencyStats offset = e.series(e.pipelineSeries().clockOffsetSeries()).stats();
        QVERIFY2(std::abs(offset.median - 250.0) < 1.0, qPrintable(QString::number(offset.median)));
        const LatencyStats oneWay = e.series(e.pipelineSeries().oneWaySeries()).stats();
        QVERIFY2(std::abs(oneWay.mean - 19.15) < 0.5, qPrintable(QString::number(oneWay.mean)));
        QVERIFY(named<LiveText>(*page, u"measureCounts"_s)->text().contains(u"400 complete"_s));

        // Plot the detection stage and the one-way latency next to the total.
        table->setData(table->index(rowOf(table, u"stage:5"_s), 0), Qt::Checked, Qt::CheckStateRole);
        table->setData(table->index(rowOf(table, u"one_way"_s), 0), Qt::Checked, Qt::CheckStateRole);
        EcdfChart* chart = page->chart();
        QCOMPARE(chart->series(), (QStringList {u"stage:5"_s, u"total"_s, u"one_way"_s}));
        chart->refresh();
        const qsizetype points = chart->pointCount(u"total"_s);
        QVERIFY(points > 10);
        QVERIFY(points <= 2 * chart->views().first()->width() + 2);
        const auto [lo, hi] = chart->range(u"total"_s);
        QVERIFY(lo <= e.series(e.pipelineSeries().oneWaySeries()).stats().min);
        // Up to the largest, or a high quantile with what lies beyond marked (issue 33).
        QVERIFY(hi >= e.series(e.totalSeries()).stats().max || !chart->beyondText(u"total"_s).isEmpty());
        QTest::qWait(50); // the legend lays its markers out on the next event loop pass
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            w.grab().save(shots + u"/measure.png"_s);
        // A stage of a fraction of a ms next to the total: the axis margin stops at 0, since no
        // plotted latency is negative.
        table->setData(table->index(rowOf(table, u"stage:0"_s), 0), Qt::Checked, Qt::CheckStateRole);
        chart->refresh();
        auto* x = qobject_cast<QValueAxis*>(chart->views().first()->chart()->axes(Qt::Horizontal).first());
        QVERIFY(x);
        QCOMPARE(x->min(), 0.0);
        table->setData(table->index(rowOf(table, u"stage:0"_s), 0), Qt::Unchecked, Qt::CheckStateRole);
        chart->refresh();

        named<QCheckBox>(*page, u"logScaleBox"_s)->click();
        QVERIFY(qobject_cast<QLogValueAxis*>(chart->views().first()->chart()->axes(Qt::Horizontal).first()));
        named<QCheckBox>(*page, u"smallMultiplesBox"_s)->click();
        QCOMPARE(chart->views().size(), 3);
        named<QCheckBox>(*page, u"smallMultiplesBox"_s)->click();
        named<QCheckBox>(*page, u"logScaleBox"_s)->click();
        QCOMPARE(chart->views().size(), 1);

        // Pause freezes the table while measuring goes on; resuming shows what came meanwhile.
        statsView->setFocus();
        QTest::keyClick(statsView, Qt::Key_P, Qt::ControlModifier);
        QVERIFY(named<QAction>(*page, u"pauseAction"_s)->isChecked());
        QVERIFY(named<LiveText>(*page, u"measureCounts"_s)->text().contains(u"paused"_s));
        pub = publish(paperStamps(topics), 100, 4);
        QTRY_VERIFY_WITH_TIMEOUT(e.samples() >= 500, 60000);
        QCOMPARE(table->index(total, LatencyStatsModel::CountColumn).data().toString(), u"400"_s);
        QTest::keyClick(statsView, Qt::Key_P, Qt::ControlModifier);
        QTRY_COMPARE_WITH_TIMEOUT(table->index(total, LatencyStatsModel::CountColumn).data().toString(),
                                  u"500"_s, 5000);
        // The window: the last 100 samples only.
        named<QSpinBox>(*page, u"windowBox"_s)->setValue(100);
        QCOMPARE(table->index(total, LatencyStatsModel::CountColumn).data().toString(), u"100"_s);
        QTest::keyClick(statsView, Qt::Key_R, Qt::ControlModifier);
        QCOMPARE(table->index(total, LatencyStatsModel::CountColumn).data().toString(), u"0"_s);
        QVERIFY(named<LiveText>(*page, u"measureCounts"_s)->text().contains(u"0 complete"_s));
    }

    // Issue 43: the window probes the clock services of the pipeline's hosts on the broker it is
    // connected to, says what it does and what does not answer, and pins each crossing corrected
    // by the measured offset with its interval; a service that goes away is said too.
    void clocksAreMeasuredAndEachCrossingCorrected()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        MeasurePage* page = w.measurePage();
        w.resize(1280, 800);
        w.show();
        w.pages()->setCurrentWidget(page);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* clocks = named<LiveText>(*page, u"measureClocks"_s);
        QVERIFY(!clocks->isVisible()); // nothing probed before the user's pipeline

        QStringList topics;
        const QString file = writePaperPipeline(u"clocks.yaml"_s, {}, &topics);
        QString error;
        QVERIFY2(noted(page->loadPipeline(file), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(clocks->isVisible() && clocks->text().contains(u"cloud, vehicle"_s), 10000);
        // No service yet: said, with what to run, once the first probes went unanswered.
        QTRY_VERIFY_WITH_TIMEOUT(clocks->text().contains(u"No clock service answers for cloud, vehicle"_s),
                                 10000);

        // The hosts' services: the cloud's clock 250 ms ahead, as its stamps are.
        const auto serve = [this](const QString& name, double offsetMs) {
            ClockServerOptions o;
            o.name = name;
            o.clockOffsetMs = offsetMs;
            auto server = std::make_unique<ClockServer>(o);
            auto mqtt = std::make_unique<MqttClockServer>(server.get());
            mqtt->open(MqttProfile::fromUrl(m_servers.brokerUrl()));
            return std::pair {std::move(server), std::move(mqtt)};
        };
        auto vehicle = serve(u"vehicle"_s, 0);
        auto cloud = serve(u"cloud"_s, 250);
        QTRY_VERIFY_WITH_TIMEOUT(clocks->text().startsWith(u"Clocks measured: cloud +250."_s)
                                     || clocks->text().startsWith(u"Clocks measured: cloud +249.9"_s),
                                 15000);
        QVERIFY2(clocks->text().contains(u" ms ± "_s) && clocks->text().contains(u"against vehicle"_s),
                 qPrintable(clocks->text()));

        auto pub = publish(paperStamps(topics), 300, 5);
        const LatencyEngine& e = w.measure()->engine();
        const int out = e.pipeline().crossings().first();
        QTRY_VERIFY_WITH_TIMEOUT(e.pipelineSeries().correctedSeries(out) >= 0
                                     && e.series(e.pipelineSeries().correctedSeries(out)).count() >= 250,
                                 60000);
        QVERIFY(pub->waitForFinished(10000));
        // Pinned: each way corrected, within its interval, and the asymmetry beside half the round trip.
        auto* summary = named<QTableView>(*page, u"summaryView"_s);
        QAbstractItemModel* pinned = summary->model();
        QTRY_VERIFY(rowOf(pinned, SeriesId::ofCorrected(out).toString()) >= 0);
        const int row = rowOf(pinned, SeriesId::ofCorrected(out).toString());
        const QString label = pinned->index(row, 0).data().toString();
        QVERIFY2(label.startsWith(u"communication, vehicle → cloud, clocks measured ± "_s),
                 qPrintable(label));
        QVERIFY(rowOf(pinned, u"asymmetry"_s) >= 0);
        QVERIFY(rowOf(pinned, u"one_way"_s) >= 0);
        // The synthetic crossings take about 19 ms each way, whatever the 250 ms between the clocks.
        const double median = pinned->index(row, LatencyStatsModel::MedianColumn)
                                  .data(LatencyStatsModel::ValueRole)
                                  .toDouble();
        QVERIFY2(std::abs(median - 19) < 2, qPrintable(QString::number(median)));
        QVERIFY2(ViewAudit::elidedFiguresIn(&w).isEmpty(),
                 qPrintable(ViewAudit::elidedFiguresIn(&w).join(u'\n')));
        QCOMPARE(clocks->width() <= page->width(), true);
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            w.grab().save(shots + u"/measure-clocks.png"_s);

        // The cloud's service goes away: the estimate is kept, less certain with time, and it is said.
        cloud = {};
        QTRY_VERIFY_WITH_TIMEOUT(clocks->text().contains(u"No answer from the clock service of cloud"_s),
                                 15000);
        QVERIFY(clocks->text().startsWith(u"Clocks measured: cloud"_s));
    }

    // Regression (issue 40, item 4): the automatic order put the vehicle's return stamps before
    // the cloud's (its clock 35 ms ahead) and pinned a negative round trip on top, with no word.
    // A pinned figure that cannot be a latency is flagged next to it, with why and what to do; the
    // automatic order takes the clock offset into account.
    void aNegativePinnedFigureIsFlaggedAndAutomaticFindsTheOrder()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        MeasurePage* page = w.measurePage();
        MeasureSession* measure = w.measure();
        w.resize(1280, 800);
        w.show();
        w.pages()->setCurrentWidget(page);
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        // The paper's pipeline, said to run on one clock while the cloud's is 35 ms ahead: the
        // way back reads 19 - 35 ms.
        QStringList topics;
        const QString file = writePaperPipeline(u"one-clock.yaml"_s, "one_clock: true\n", &topics);
        QVERIFY(!file.isEmpty());
        QString error;
        QVERIFY2(noted(page->loadPipeline(file), &error), qPrintable(error));
        QLabel* warning = named<QLabel>(*page, u"measureWarning"_s);
        QVERIFY(!warning->isVisible());
        auto pub = publish(paperStamps(topics, 35'000), 100, 11);
        QTRY_VERIFY_WITH_TIMEOUT(measure->engine().samples() >= 100, 60000);
        QVERIFY(pub->waitForFinished(10000));

        // The pinned row says it, and the line above the pinned rows says why and what to do.
        QAbstractItemModel* pinned = named<QTableView>(*page, u"summaryView"_s)->model();
        const int back = rowOf(pinned, u"back"_s);
        QVERIFY(back >= 0);
        QTRY_VERIFY_WITH_TIMEOUT(pinned->index(back, 0).data().toString().startsWith(u"⚠ "_s), 5000);
        QVERIFY(
            pinned->index(back, LatencyStatsModel::MedianColumn).data(LatencyStatsModel::ValueRole).toDouble()
            < 0);
        QTRY_VERIFY_WITH_TIMEOUT(warning->isVisible(), 5000);
        const QString text = warning->text();
        QVERIFY2(text.contains(u"communication, back (cloud → vehicle): median -1"_s), qPrintable(text));
        QVERIFY2(text.contains(u"a latency cannot be negative"_s), qPrintable(text));
        QVERIFY2(text.contains(u">Set hosts</a>"_s) && text.contains(u">load a pipeline</a>"_s),
                 qPrintable(text));
        QVERIFY(pinned->index(back, 0).data(Qt::ToolTipRole).toString().contains(u"Load Pipeline"_s));
        // Next to the pinned rows, whole at 1280x800.
        QWidget* summary = named<QTableView>(*page, u"summaryView"_s);
        const QRect at = warning->geometry();
        QCOMPARE(warning->parentWidget(), summary->parentWidget());
        QVERIFY2(at.bottom() < summary->geometry().top() && summary->geometry().top() - at.bottom() < 12,
                 qPrintable(u"warning %1..%2, pinned rows from %3"_s.arg(at.top())
                                .arg(at.bottom())
                                .arg(summary->geometry().top())));
        QVERIFY(warning->height() >= warning->heightForWidth(warning->width()));
        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
            w.grab().save(shots + u"/measure-warning.png"_s);

        // Automatic: the cloud's stamps go between the vehicle's, whatever its clock says.
        measure->setAutomatic();
        pub = publish(paperStamps(topics, 35'000), 100, 12);
        QTRY_VERIFY_WITH_TIMEOUT(measure->engine().samples() >= 50, 60000);
        QVERIFY(pub->waitForFinished(10000));
        QCOMPARE(measure->pipeline().topics(), topics);
        QCOMPARE(measure->pipeline().crossings(), (QList<int> {2, 8}));
        const LatencyEngine& e = measure->engine();
        QTRY_VERIFY_WITH_TIMEOUT(!warning->isVisible(), 5000);
        QVERIFY2(
            std::abs(e.series(e.pipelineSeries().clockOffsetSeries()).stats().median - 35.0) < 1.0,
            qPrintable(QString::number(e.series(e.pipelineSeries().clockOffsetSeries()).stats().median)));
        QVERIFY(e.series(e.pipelineSeries().roundTripSeries()).stats().median > 0);
        QVERIFY(!pinned->index(rowOf(pinned, u"round_trip"_s), 0).data().toString().startsWith(u"⚠"_s));
    }

    void pipelineIsEditedByKeyboardAndDrag()
    {
        MainWindow w;
        MeasurePage* page = w.measurePage();
        w.resize(1400, 900);
        w.show();
        w.pages()->setCurrentWidget(page);
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        // Automatic: three stamp topics published in scrambled order come out sorted.
        auto pub = publish({u"--stamp"_s, u"/lab/vehicle/done:30000"_s, u"--stamp"_s,
                            u"/lab/vehicle/send:0"_s, u"--stamp"_s, u"/lab/cloud/recv:10000"_s},
                           60, 5);
        QTRY_COMPARE_WITH_TIMEOUT(
            w.measure()->pipeline().topics(),
            (QStringList {u"/lab/vehicle/send"_s, u"/lab/cloud/recv"_s, u"/lab/vehicle/done"_s}), 60000);
        QVERIFY(w.measure()->isAutomatic());
        QVERIFY(named<QLabel>(*page, u"modeLabel"_s)->text().startsWith(u"Automatic"_s));
        QTRY_COMPARE_WITH_TIMEOUT(named<QListView>(*page, u"stampTopicsView"_s)->model()->rowCount(), 3,
                                  5000);
        QVERIFY(pub->waitForFinished(20000));

        QTableView* view = named<QTableView>(*page, u"pipelineView"_s);
        PipelineModel* model = named<PipelineModel>(*page, u"pipelineModel"_s);
        view->setFocus();
        view->setCurrentIndex(model->index(0, PipelineModel::TopicColumn));
        QTest::keyClick(view, Qt::Key_Delete);
        QCOMPARE(w.measure()->pipeline().topics(),
                 (QStringList {u"/lab/cloud/recv"_s, u"/lab/vehicle/done"_s}));
        QVERIFY(!w.measure()->isAutomatic());
        QCOMPARE(named<QLabel>(*page, u"modeLabel"_s)->text(), u"Edited by hand."_s);

        // Drag the removed topic back from the topics seen, onto the first row.
        QListView* seen = named<QListView>(*page, u"stampTopicsView"_s);
        const QModelIndex send = find(seen->model(), u"/lab/vehicle/send"_s, StampTopicModel::TopicRole);
        QVERIFY(send.isValid());
        QVERIFY(!send.data(StampTopicModel::InPipelineRole).toBool());
        dragAndDrop(seen, {send}, view, centre(view, model->index(0, PipelineModel::TopicColumn)));
        QCOMPARE(w.measure()->pipeline().topics(),
                 (QStringList {u"/lab/vehicle/send"_s, u"/lab/cloud/recv"_s, u"/lab/vehicle/done"_s}));

        // Ctrl+Down and Ctrl+Up move a stamp.
        view->setCurrentIndex(model->index(0, PipelineModel::TopicColumn));
        QTest::keyClick(view, Qt::Key_Down, Qt::ControlModifier);
        QCOMPARE(w.measure()->pipeline().topics().at(1), u"/lab/vehicle/send"_s);
        QCOMPARE(view->currentIndex().row(), 1);
        QTest::keyClick(view, Qt::Key_Up, Qt::ControlModifier);
        QCOMPARE(w.measure()->pipeline().topics().at(0), u"/lab/vehicle/send"_s);

        // Hosts are guessed from the names and can be edited: all on one host, no crossing left.
        QCOMPARE(w.measure()->pipeline().crossings(), (QList<int> {0, 1}));
        QVERIFY(model->setData(model->index(1, PipelineModel::HostColumn), u"vehicle"_s));
        QCOMPARE(w.measure()->pipeline().crossings(), QList<int>());
        QCOMPARE(w.measure()->engine().pipelineSeries().roundTripSeries(), -1);

        // Save and load the pipeline as a file the suite can read too.
        QTemporaryDir dir;
        QString error;
        QVERIFY2(noted(page->savePipeline(dir.filePath(u"p.yaml"_s)), &error), qPrintable(error));
        const Result<Pipeline> back = Pipeline::readFile(dir.filePath(u"p.yaml"_s));
        QVERIFY(back);
        QCOMPARE(back->topics(), w.measure()->pipeline().topics());
        QCOMPARE(back->host(1), u"vehicle"_s);
        // The Automatic button goes back to what the stamps say.
        w.measure()->setAutomatic();
        QCOMPARE(w.measure()->pipeline().crossings(), (QList<int> {0, 1}));
    }

    // Issue 40, point 10: the run file's label read `Run &file:` (a form row whose field is a
    // layout gets no buddy, so the & showed); it shows "Run file:" and Alt+F goes to the path.
    void theRecordDialogsLabelsAreMnemonics()
    {
        RecordDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowActive(&dialog));
        QLabel* file = nullptr;
        for (QLabel* l : dialog.findChildren<QLabel*>())
            if (l->text().remove(u'&') == u"Run file:"_s)
                file = l;
        QVERIFY(file);
        auto* path = qobject_cast<QLineEdit*>(file->buddy());
        QVERIFY2(path, "the & of `Run &file:` is shown: the label has no buddy");
        QCOMPARE(path->text(), dialog.path());
        for (QLabel* l : dialog.findChildren<QLabel*>())
            QVERIFY2(!l->text().contains(u'&') || l->buddy(), qPrintable(l->text()));
        QTest::keyClick(&dialog, Qt::Key_F, Qt::AltModifier);
        QTRY_COMPARE(QApplication::focusWidget(), path);
    }
};

QTEST_MAIN(TestMeasurePage)
#include "tst_measurepage.moc"
