// SPDX-License-Identifier: MIT
// Issue 34: the Measure page on a ROS 2 graph. A Cyclone DDS node (tests/ros2peer) publishes a
// chain of benchmarking_suite/msg/TimeStamped topics on a private domain; the window, joined to
// that domain, shows at 1280x800 the count, median and p99 of every stage and of the total as
// numpy computes them from the stamps the node printed.
#include "app/gui/mainwindow.h"
#include "latency/pipeline.h"
#include "models/latencystatsmodel.h"
#include "resulttext.h"
#include "ros2peer.h"
#include "ros2stampchain.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "viewhelpers.h"
#include "widgets/measure/measurepage.h"

#include <QJsonArray>
#include <QStandardPaths>
#include <QTableView>
#include <QTabWidget>
#include <QTest>

using namespace Qt::StringLiterals;
using ViewHelpers::named;

namespace {
constexpr int kSamples = 100;

int rowOf(QAbstractItemModel* model, const QString& id)
{
    return ViewHelpers::find(model, id, LatencyStatsModel::SeriesIdRole).row();
}
} // namespace

class TestMeasureRos2 : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void showsTheFiguresNumpyComputes()
    {
        const int domain = Ros2Peer::freeDomain(101, 120);
        MainWindow w;
        QString error;
        QVERIFY2(noted(w.session()->startRos2({domain, true}), &error), qPrintable(error));
        MeasurePage* page = w.measurePage();
        w.measure()->setPipeline(Pipeline(Ros2StampChain::topics(), 1000));
        w.resize(1280, 800);
        w.show();
        w.pages()->setCurrentWidget(page);
        QVERIFY(QTest::qWaitForWindowExposed(&w));

        Ros2Peer chain(domain, Ros2StampChain::args(kSamples));
        QVERIFY2(chain.waitFor(u"ready"_s), qPrintable(chain.errors()));
        QAbstractItemModel* table = named<QTableView>(*page, u"statsView"_s)->model();
        QTRY_COMPARE_WITH_TIMEOUT(
            table->index(rowOf(table, u"total"_s), LatencyStatsModel::CountColumn).data().toString(),
            QString::number(kSamples), 20000);
        for (const QString& t : Ros2StampChain::topics())
            QVERIFY(chain.waitFor(u"stamp %1 %2 "_s.arg(t).arg(kSamples)));
        QTemporaryDir dir;
        int rows = 0;
        const QJsonObject ref = Ros2StampChain::reference(dir, Ros2StampChain::suiteCsv(chain.lines(), &rows));
        QCOMPARE(rows, kSamples);
        QVERIFY(!ref.isEmpty());
        const auto check = [&](const QString& id, const QJsonObject& numpy) {
            const int row = rowOf(table, id);
            QVERIFY2(row >= 0, qPrintable(id));
            QVERIFY(
                !named<QTableView>(*page, u"statsView"_s)->isColumnHidden(LatencyStatsModel::MedianColumn));
            QCOMPARE(table->index(row, LatencyStatsModel::CountColumn).data().toString(),
                     QString::number(numpy.value(u"count"_s).toInt()));
            QCOMPARE(table->index(row, LatencyStatsModel::MedianColumn).data().toString(),
                     LatencyStatsModel::msText(numpy.value(u"median_ms"_s).toDouble()));
            QCOMPARE(table->index(row, LatencyStatsModel::P99Column).data().toString(),
                     LatencyStatsModel::msText(numpy.value(u"p99_ms"_s).toDouble()));
        };
        const QJsonArray stages = ref.value(u"stages"_s).toArray();
        QCOMPARE(stages.size(), 3);
        for (int s = 0; s < stages.size(); ++s)
            check(u"stage:%1"_s.arg(s), stages[s].toObject());
        check(u"total"_s, ref.value(u"total"_s).toObject());
        if (qEnvironmentVariableIsSet("BRIDGESCOPE_SCREENSHOT"))
            w.grab().save(qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT"));
    }
};

QTEST_MAIN(TestMeasureRos2)
#include "tst_measureros2.moc"
