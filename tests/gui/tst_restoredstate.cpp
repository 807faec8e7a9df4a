// SPDX-License-Identifier: MIT
// Issue 40, points 1, 5, 8 and 9: what one session leaves in the settings never cuts what the next
// one shows. Sessions play as a lab plays them, in one settings folder at 1280x800: the demo with
// small figures, quit; the demo again with figures a thousand times larger; the ROS 2 demo; the demo
// again. Every figure of every item view is whole (no "when the view has room" escape), names show
// at least their last segment, the ROS graph selector shows the session's graph, and Discover and
// the ECDF legend are readable.
#include "app/gui/demostart.h"
#include "app/gui/mainwindow.h"
#include "config/mappingmodel.h"
#include "demo/demolab.h"
#include "guisession.h"
#include "latency/latencyengine.h"
#include "models/latencystatsmodel.h"
#include "widgets/measure/pipelinemodel.h"
#include "models/mqtttopictree.h"
#include "namecheck.h"
#include "ros2/ros2participant.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "topics/topictablemodel.h"
#include "viewaudit.h"
#include "viewhelpers.h"
#include "widgets/links/linkmodel.h"
#include "widgets/common/ecdfchart.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/mappage.h"
#include "widgets/measure/measurepage.h"
#include "windowparts.h"

#include <memory>
#include <QChartView>
#include <QComboBox>
#include <QGraphicsItem>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QSettings>
#include <QTabBar>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;
using namespace WindowParts;

namespace {
/// The figure columns of a table: every column but these.
QList<int> allBut(const QAbstractItemModel* model, const QList<int>& names)
{
    QList<int> out;
    for (int c = 0; c < model->columnCount(); ++c)
        if (!names.contains(c))
            out << c;
    return out;
}

} // namespace

class TestRestoredState : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<DemoLab> m_lab;
    std::unique_ptr<MainWindow> m_window;

    /// Opens the window as `bridgescope --demo [--ros 2]` does: the window's memory of the last
    /// session first, then the demo lab behind it; returns once samples are joined.
    void open(int ros, double detectionMs)
    {
        m_window = std::make_unique<MainWindow>();
        MainWindow& w = *m_window;
        w.rememberSession();
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_COMPARE(w.size(), QSize(1280, 800));
        m_lab = std::make_unique<DemoLab>();
        DemoLab::Options options;
        options.program = QStringLiteral(BRIDGESCOPE_BINARY);
        options.payloadBytes = 20000;
        options.ros = ros;
        options.detectionMs = detectionMs;
        auto error = std::make_shared<QString>(u"not yet"_s);
        DemoLab* lab = m_lab.get();
        DemoStart::start(w, *lab, options, [&w, lab, error](const QString& why) {
            *error = why;
            if (why.isEmpty())
                DemoStart::show(w, *lab);
        });
        QTRY_VERIFY_WITH_TIMEOUT(*error != u"not yet"_s, 30000);
        QVERIFY2(error->isEmpty(), qPrintable(*error));
        QTRY_VERIFY_WITH_TIMEOUT(w.measure()->engine().counters().complete >= 5, 40000);
    }

    /// Quits as the user does: the window saves its state on close.
    void quit()
    {
        QVERIFY(m_window->close());
        m_window.reset();
        m_lab.reset();
    }

    /// Shows every page once, so that each lays out its views (what the user sees before quitting).
    void visitEveryPage()
    {
        MainWindow& w = *m_window;
        for (QWidget* page : {static_cast<QWidget*>(w.discoverPage()), static_cast<QWidget*>(mapPage(w)),
                              static_cast<QWidget*>(w.linksPage()), static_cast<QWidget*>(w.measurePage())}) {
            w.pages()->setCurrentWidget(page);
            // The columns fit themselves 100 ms after they are shown: until none cuts a figure.
            (void)QTest::qWaitFor([page] { return ViewAudit::elidedFiguresIn(page).isEmpty(); }, 3000);
        }
    }

    /// No figure cut in `view` (the columns grow once a second at most: waited for).
    static void checkFigures(QAbstractItemView* view, const QList<int>& columns)
    {
        QVERIFY2(view->isVisible(), qPrintable(view->objectName()));
        QTRY_VERIFY2_WITH_TIMEOUT(figuresCutProblem(view, columns).isEmpty(),
                                  qPrintable(figuresCutProblem(view, columns)), 5000);
    }

    static void checkNames(QAbstractItemView* view, int column, int minimumRows)
    {
        QTRY_VERIFY2_WITH_TIMEOUT(namesShownProblem(view, column, minimumRows).isEmpty(),
                                  qPrintable(namesShownProblem(view, column, minimumRows)), 5000);
    }

    /// Every item view of every page that shows figures, as shown.
    void checkEveryView(QTableView* rosView)
    {
        MainWindow& w = *m_window;
        w.pages()->setCurrentWidget(w.measurePage());
        MeasurePage* measure = w.measurePage();
        const QList<int> stats
            = allBut(named<QTableView>(*measure, u"statsView"_s)->model(), {LatencyStatsModel::SeriesColumn});
        checkFigures(named<QTableView>(*measure, u"summaryView"_s), stats);
        checkFigures(named<QTableView>(*measure, u"statsView"_s), stats);
        checkFigures(named<QTableView>(*measure, u"pipelineView"_s), {PipelineModel::IndexColumn});

        w.pages()->setCurrentWidget(w.linksPage());
        QTableView* links = named<QTableView>(*w.linksPage(), u"linkTable"_s);
        QTRY_VERIFY(links->model()->rowCount() > 0);
        checkFigures(links,
                     {LinkModel::StateColumn, LinkModel::BridgeColumn, LinkModel::DirectionColumn,
                      LinkModel::SourceRateColumn, LinkModel::DestinationRateColumn, LinkModel::LossColumn,
                      LinkModel::P50Column, LinkModel::P99Column, LinkModel::ObservedColumn});
        checkNames(links, LinkModel::SourceColumn, 1);
        checkNames(links, LinkModel::DestinationColumn, 1);

        w.pages()->setCurrentWidget(mapPage(w));
        QTableView* mappings = mapPage(w)->editor()->table();
        checkFigures(mappings, {MappingModel::HealthColumn});
        checkNames(mappings, MappingModel::RosTopicColumn, 1);

        w.pages()->setCurrentWidget(w.discoverPage());
        QTRY_VERIFY(rosView->model()->rowCount() > 5);
        checkFigures(rosView,
                     allBut(rosView->model(), {TopicTableModel::TopicColumn, TopicTableModel::TypeColumn}));
        checkNames(rosView, TopicTableModel::TopicColumn, 5);
        checkNames(rosView, TopicTableModel::TypeColumn, 5);
        QTreeView* tree = w.discoverPage()->mqttView();
        checkFigures(tree,
                     {MqttTopicTree::MessagesColumn, MqttTopicTree::RateColumn, MqttTopicTree::BytesColumn,
                      MqttTopicTree::QosColumn, MqttTopicTree::RetainedColumn, MqttTopicTree::LatencyColumn});
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        GuiSession::useSettingsFolder(m_dir.path());
        qunsetenv("ROS_MASTER_URI");
        qunsetenv("ROS_DOMAIN_ID");
    }

    void cleanup()
    {
        m_window.reset();
        m_lab.reset();
    }

    // Point 1: the demo with 4 ms stages, quit; then the same demo with a detection of 1234 ms.
    // The second session's figures are whole in every view, though the first one's widths came back.
    void aSecondSessionsFiguresAreWhole()
    {
        open(1, 4);
        visitEveryPage();
        quit();
        open(1, 1234);
        const LatencyEngine& engine = m_window->measure()->engine();
        QTRY_VERIFY_WITH_TIMEOUT(engine.series(engine.totalSeries()).stats().max > 1000, 20000);
        checkEveryView(named<QTableView>(*m_window->discoverPage(), u"rosTopics"_s));
        quit();
    }

    // Point 5: after ROS 1 sessions, the ROS 2 demo's topics and types show their last segments
    // (they were `…/o…/in` and `…/…ed`), and the selector says ROS 2.
    void aRos2SessionAfterRos1ShowsItsNames()
    {
        open(2, 40);
        DiscoverPage* discover = m_window->discoverPage();
        QCOMPARE(discover->rosGraphs(), DiscoverPage::RosGraphs::Ros2);
        QCOMPARE(discover->rosGraphsBox()->currentText(), u"ROS 2"_s);
        QCOMPARE(named<QTabWidget>(*discover, u"rosTabs"_s)->currentWidget()->findChild<QTableView*>(),
                 named<QTableView>(*discover, u"ros2Topics"_s));
        QTRY_VERIFY_WITH_TIMEOUT(named<QTableView>(*discover, u"ros2Topics"_s)->model()->rowCount() >= 10,
                                 20000);
        checkEveryView(named<QTableView>(*discover, u"ros2Topics"_s));
        quit();
    }

    // Point 5: after a ROS 2 session, the demo shows the ROS 1 graph under "ROS 1" (it showed an
    // empty ROS 2 list under "ROS graph: ROS 1" while the status line said 19 topics).
    void aRos1SessionAfterRos2ShowsItsGraph()
    {
        open(1, 40);
        DiscoverPage* discover = m_window->discoverPage();
        m_window->pages()->setCurrentWidget(discover);
        QCOMPARE(discover->rosGraphs(), DiscoverPage::RosGraphs::Ros1);
        QCOMPARE(discover->rosGraphsBox()->currentText(), u"ROS 1"_s);
        QTRY_VERIFY(named<QTableView>(*discover, u"rosTopics"_s)->isVisible());
        QVERIFY(!named<QTableView>(*discover, u"ros2Topics"_s)->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(named<QTableView>(*discover, u"rosTopics"_s)->model()->rowCount() >= 19,
                                 20000);
        checkEveryView(named<QTableView>(*discover, u"rosTopics"_s));
        quit();
    }

    // Point 8, in a second session at 1280x800: on Discover the ROS names and types are readable
    // without scrolling, the MQTT values get room beside their topics, and the detail opens below
    // them with its tabs whole.
    void discoverIsReadableAt1280x800()
    {
        open(1, 40);
        MainWindow& w = *m_window;
        DiscoverPage* discover = w.discoverPage();
        w.pages()->setCurrentWidget(discover);
        QTableView* ros = named<QTableView>(*discover, u"rosTopics"_s);
        QTRY_VERIFY_WITH_TIMEOUT(ros->model()->rowCount() >= 19, 20000);
        QTreeView* tree = discover->mqttView();
        const QModelIndex topic = ViewHelpers::find(tree->model(), u"benchmarking_suite/pointcloud"_s,
                                                    MqttTopicTree::FullTopicRole);
        QVERIFY(topic.isValid());
        tree->setCurrentIndex(topic);
        const QHeaderView* header = tree->header();
        const int value = MqttTopicTree::ValueColumn;
        const int room
            = tree->fontMetrics().horizontalAdvance(u"{\"header\": {\"stamp\": 1"_s); // 22 characters
        const auto valueShown = [&] {
            const int left = header->sectionViewportPosition(value);
            const int right = std::min(left + header->sectionSize(value), tree->viewport()->width());
            return right - std::max(left, 0);
        };
        QTRY_VERIFY2_WITH_TIMEOUT(valueShown() >= room,
                                  qPrintable(u"the values show %1 px of %2"_s.arg(valueShown()).arg(room)),
                                  5000);

        // The figures grow once a second: until none is cut.
        (void)QTest::qWaitFor([&w] { return ViewAudit::elidedFiguresIn(w.discoverPage()).isEmpty(); }, 3000);
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
            QVERIFY(w.grab().save(dir + u"/restored-discover.png"_s));
        // The ROS names keep their last levels whole and stay told apart (it showed
        // `/b…/t…/…cloud/…` and `g…/PoseArray`).
        checkNames(ros, TopicTableModel::TopicColumn, 19);
        checkNames(ros, TopicTableModel::TypeColumn, 19);

        // The selection opened the detail: its tabs whole, side by side.
        QTabBar* tabs = only<DetailPane>(*discover)->findChild<QTabWidget*>()->tabBar();
        QTRY_VERIFY(tabs->isVisible());
        for (int i = 0; i < tabs->count(); ++i) {
            const QString text = tabs->tabText(i).remove(u'&');
            const QRect rect = tabs->tabRect(i);
            QVERIFY2(rect.width() > tabs->fontMetrics().horizontalAdvance(text)
                         && rect.right() < tabs->width(),
                     qPrintable(u"tab '%1': %2 px at %3 of %4"_s.arg(text)
                                    .arg(rect.width())
                                    .arg(rect.x())
                                    .arg(tabs->width())));
        }
        QVERIFY2(only<DetailPane>(*discover)->height() >= 200,
                 qPrintable(QString::number(only<DetailPane>(*discover)->height())));
    }

    // Point 9: the ECDF's legend names each series whole (it read `object_detection…`,
    // `communication, …`, `1 beyond…`), on the Measure page at 1280x800.
    void ecdfLegendsAreWhole()
    {
        if (!m_window)
            open(1, 40);
        MainWindow& w = *m_window;
        w.pages()->setCurrentWidget(w.measurePage());
        EcdfChart* chart = w.measurePage()->chart();
        QTRY_VERIFY(chart->series().size() >= 3);
        const PipelineSeries& series = w.measure()->engine().pipelineSeries();
        QStringList wanted;
        for (const QString& id : chart->series())
            wanted << series.ecdfLabel(series.ecdfIndex(id));
        chart->refresh();
        for (const QString& id : chart->series())
            if (!chart->beyondText(id).isEmpty())
                wanted << chart->beyondText(id);
        // (The chart may rebuild its views as the pipeline's series come: asked for each time.)
        const auto missing = [&] {
            const QStringList drawn = GuiSession::drawnTexts(chart->views().first());
            for (const QString& t : std::as_const(wanted))
                if (!drawn.contains(t))
                    return u"'%1' not drawn whole; drawn: %2"_s.arg(t, drawn.join(u" | "_s));
            return QString();
        };
        QTRY_VERIFY2(missing().isEmpty(), qPrintable(missing()));
        QChartView* view = chart->views().first();
        // Inside the chart, under its plot.
        for (QGraphicsItem* item : view->scene()->items())
            if (auto* text = dynamic_cast<QGraphicsTextItem*>(item);
                text && wanted.contains(text->toPlainText())) {
                const QRectF r = text->sceneBoundingRect();
                QVERIFY2(view->sceneRect().contains(r), qPrintable(text->toPlainText()));
            }
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
            QVERIFY(w.grab().save(dir + u"/restored-measure.png"_s));
        quit();
    }
};

QTEST_MAIN(TestRestoredState)
#include "tst_restoredstate.moc"
