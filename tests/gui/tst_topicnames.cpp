// SPDX-License-Identifier: MIT
// Names stay told apart: every view of topic names in the window, on the demo lab's graph (a dozen
// stamp topics that differ only inside their names), shows a different text for every different
// name, within its column, at 1280x800 and at 1920x1080; Qt's own middle elision does not. And in
// the same window on the same lab, a field of a live ROS topic plotted over time (the README's shot).
#include "app/gui/mainwindow.h"
#include "config/mappingmodel.h"
#include "demo/demolab.h"
#include "latency/pipeline.h"
#include "widgets/measure/pipelinemodel.h"
#include "mqtt/mqttprofile.h"
#include "models/mqtttopictree.h"
#include "namecheck.h"
#include "resulttext.h"
#include "session/fieldplotter.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "topics/topictablemodel.h"
#include "topics/topictree.h"
#include "viewhelpers.h"
#include "widgets/links/linkmodel.h"
#include "widgets/common/namedelegate.h"
#include "widgets/common/nameheader.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/discover/fieldplotchart.h"
#include "widgets/links/linkspage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/mappage.h"
#include "widgets/map/mappinginspector.h"
#include "widgets/measure/measurepage.h"
#include "windowparts.h"

#include <QChart>
#include <QElapsedTimer>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QLineSeries>
#include <QListView>
#include <QListWidget>
#include <QScrollBar>
#include <QSet>
#include <QStandardItemModel>
#include <QTableView>
#include <QTabWidget>
#include <QTest>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;
using namespace WindowParts;

class TestTopicNames : public QObject
{
    Q_OBJECT
private:
    DemoLab m_lab;
    std::unique_ptr<MainWindow> m_window;
    QSet<QString> m_roomy; ///< the views checkNotCutWithRoom found room in

    static void checkNames(QAbstractItemView* view, int column, int minimumRows)
    {
        // The columns fit themselves 100 ms after a change and figures grow once a second: on a
        // loaded machine the last fit may still be on its way.
        QString problem;
        (void)QTest::qWaitFor(
            [&] { return (problem = namesShownProblem(view, column, minimumRows)).isEmpty(); }, 3000);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    /// Rows that show their names without the prefix they share have it in their column's title.
    static void checkPrefixSaid(QTableView* view, int column)
    {
        auto* delegate = qobject_cast<NameDelegate*>(view->itemDelegateForColumn(column));
        auto* header = qobject_cast<NameHeader*>(view->horizontalHeader());
        QVERIFY(delegate && header);
        const QString prefix = delegate->strippedPrefix();
        const QAbstractItemModel* model = view->model();
        for (int r = 0; r < model->rowCount(); ++r) {
            const QString name = model->index(r, column).data().toString();
            const QString shown = delegate->displayedText(model->index(r, column));
            if (!prefix.isEmpty())
                QVERIFY2(name.startsWith(prefix) && !shown.startsWith(prefix), qPrintable(shown));
            else
                QVERIFY2(shown.startsWith(u'/') || shown.startsWith(u'…'), qPrintable(shown));
        }
        QVERIFY2(prefix.isEmpty() || header->title(column).endsWith(prefix),
                 qPrintable(header->title(column)));
    }

    /// No column's text is cut when the view has room for every column's text.
    void checkNotCutWithRoom(QTableView* view)
    {
        QString problem;
        bool roomy = false;
        // The fitter sizes the columns 100 ms after a change, and figures grow once a second.
        (void)QTest::qWaitFor([&] { return (problem = cutWithRoomProblem(view, &roomy)).isEmpty(); }, 3000);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        if (roomy)
            m_roomy << view->objectName();
    }

    /// The names' columns fit the view: no scrolling sideways to read a row.
    static void checkNoSideways(QAbstractItemView* view)
    {
        QTRY_VERIFY2(!view->horizontalScrollBar()->isVisible(), qPrintable(view->objectName()));
    }

    void checkEveryView()
    {
        MainWindow* w = m_window.get();
        w->pages()->setCurrentWidget(w->discoverPage());
        checkNames(named<QTableView>(*w->discoverPage(), u"rosTopics"_s), TopicTableModel::TopicColumn, 19);
        checkNames(named<QTableView>(*w->discoverPage(), u"rosTopics"_s), TopicTableModel::TypeColumn, 19);
        w->pages()->setCurrentWidget(mapPage(*w));
        // The Map's ROS topics are a namespace tree: every row's own segment whole.
        for (int column : {int(TopicTree::TopicColumn), int(TopicTree::TypeColumn)}) {
            QString problem;
            (void)QTest::qWaitFor(
                [&] {
                    return (problem = treeNamesShownProblem(named<QTreeView>(*mapPage(*w), u"mapRosTopics"_s),
                                                            column, 19))
                        .isEmpty();
                },
                3000);
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        checkNames(mapPage(*w)->editor()->table(), MappingModel::RosTopicColumn, 2);
        checkNames(mapPage(*w)->editor()->table(), MappingModel::MqttTopicColumn, 2);
        checkNoSideways(named<QTreeView>(*mapPage(*w), u"mapRosTopics"_s));
        checkNoSideways(mapPage(*w)->editor()->table());
        // The inspector beside the table shows the selected mapping's topics whole.
        QTableView* mappings = mapPage(*w)->editor()->table();
        mappings->selectRow(0);
        MappingInspector* inspector = only<MappingInspector>(*mapPage(*w)->editor());
        for (QLineEdit* edit :
             {named<QLineEdit>(*inspector, u"ros_topic"_s), named<QLineEdit>(*inspector, u"mqtt_topic"_s)}) {
            QTRY_VERIFY(!edit->text().isEmpty());
            QVERIFY2(edit->fontMetrics().horizontalAdvance(edit->text()) + 12 <= edit->width(),
                     qPrintable(u"%1 in %2 px"_s.arg(edit->text()).arg(edit->width())));
        }
        w->pages()->setCurrentWidget(w->measurePage());
        checkNames(named<QTableView>(*w->measurePage(), u"pipelineView"_s), PipelineModel::TopicColumn, 8);
        checkPrefixSaid(named<QTableView>(*w->measurePage(), u"pipelineView"_s), PipelineModel::TopicColumn);
        // The stamp topics seen: a list, whose caption says the prefix its rows leave out.
        QListView* seen = named<QListView>(*w->measurePage(), u"stampTopicsView"_s);
        checkNames(seen, 0, 8);
        auto* seenNames = qobject_cast<NameDelegate*>(seen->itemDelegateForColumn(0));
        QVERIFY(seenNames);
        if (const QString prefix = seenNames->strippedPrefix(); !prefix.isEmpty()) {
            QLabel* caption = nullptr;
            for (QLabel* label : w->measurePage()->findChildren<QLabel*>())
                if (label->buddy() == seen)
                    caption = label;
            QVERIFY(caption);
            QTRY_VERIFY2(caption->text().contains(prefix), qPrintable(caption->text()));
            for (int r = 0; r < seen->model()->rowCount(); ++r)
                QVERIFY(!seenNames->displayedText(seen->model()->index(r, 0)).startsWith(prefix));
        }
        w->pages()->setCurrentWidget(w->linksPage());
        checkNames(named<QTableView>(*w->linksPage(), u"linkTable"_s), LinkModel::SourceColumn, 4);
        checkNames(named<QTableView>(*w->linksPage(), u"linkTable"_s), LinkModel::DestinationColumn, 4);
        checkNotCutWithRoom(named<QTableView>(*w->linksPage(), u"linkTable"_s));
        w->pages()->setCurrentWidget(w->discoverPage());
        checkNotCutWithRoom(named<QTableView>(*w->discoverPage(), u"rosTopics"_s));
        w->pages()->setCurrentWidget(mapPage(*w));
        checkNotCutWithRoom(mapPage(*w)->editor()->table());
        w->pages()->setCurrentWidget(w->measurePage());
        checkNotCutWithRoom(named<QTableView>(*w->measurePage(), u"pipelineView"_s));
    }

private slots:
    void initTestCase()
    {
        DemoLab::Options options;
        options.program = QStringLiteral(BRIDGESCOPE_BINARY);
        options.payloadBytes = 20000; // the views are tested, not the lab
        QString error;
        QVERIFY2(noted(m_lab.start(options), &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        MainWindow* w = m_window.get();
        w->discoverPage()->setRosMasterUri(m_lab.rosMasterUri());
        w->discoverPage()->connectBroker(MqttProfile::fromUrl(m_lab.brokerUrl()));
        w->files()->openFile(m_lab.vehicleConfigPath());
        QVERIFY2(noted(w->linksPage()->addConfigFiles({m_lab.cloudConfigPath()}, true), &error),
                 qPrintable(error));
        QTRY_VERIFY(
            w->linksPage()->setWatched(m_lab.vehicleConfigPath(), true)); // listed a second after it opened
        const std::optional<Pipeline> pipeline = noted(Pipeline::readFile(m_lab.pipelinePath()), &error);
        QVERIFY2(pipeline, qPrintable(error));
        w->measure()->setPipeline(*pipeline);
        w->resize(1280, 800);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w));
        QTRY_VERIFY_WITH_TIMEOUT(
            named<QTableView>(*w->discoverPage(), u"rosTopics"_s)->model()->rowCount() >= 19, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(named<QTableView>(*w->linksPage(), u"linkTable"_s)->model()->rowCount() >= 4,
                                 15000);
    }

    void distinctAt1280x800()
    {
        QCOMPARE(m_window->size(), QSize(1280, 800));
        m_roomy.clear();
        checkEveryView();
        // The Links table has room for every column's text at this size: its names show whole.
        QVERIFY2(m_roomy.contains(u"linkTable"_s), qPrintable(m_roomy.values().join(u", "_s)));
        // What the views drew before: Qt's middle elision at the same width joins stamp topics.
        // (the width the Map's topic tree gives its names)
        QTreeView* map = named<QTreeView>(*mapPage(*m_window), u"mapRosTopics"_s);
        const QAbstractItemModel* model = m_window->session()->rosTopics();
        QHash<QString, QString> nameOf;
        int joined = 0;
        for (int r = 0; r < model->rowCount(); ++r) {
            const QString name = model->index(r, TopicTableModel::TopicColumn).data().toString();
            const QString elided = map->fontMetrics().elidedText(
                name, Qt::ElideMiddle, map->columnWidth(TopicTree::TopicColumn) - 8);
            joined += nameOf.value(elided, name) != name;
            nameOf.insert(elided, name);
        }
        QVERIFY2(joined > 0, "the test's names no longer need shortening at this size");
    }

    void distinctAt1920x1080()
    {
        m_window->resize(1920, 1080);
        QTRY_COMPARE(m_window->size(), QSize(1920, 1080));
        m_roomy.clear();
        checkEveryView();
        // Room for every column's text in these at this size (so the check is not idle).
        const QStringList roomy = m_roomy.values();
        QVERIFY2(m_roomy.contains(u"pipelineView"_s) && m_roomy.contains(u"mappingTable"_s),
                 qPrintable(roomy.join(u", "_s)));
    }

    // Issue 33: the stamp topics all start with /benchmarking_suite/timestamps/; when a column
    // is too narrow for whole names, the rows show the rest and the title shows the prefix once.
    void aSharedPrefixIsShownOnce()
    {
        QStandardItemModel model(0, 1);
        model.setHorizontalHeaderLabels({u"Topic"_s});
        const QStringList names = DemoLab::pipelineTopics();
        for (const QString& name : names)
            model.appendRow(new QStandardItem(name));
        QTableView view;
        view.setModel(&model);
        NameDelegate* delegate = NameDelegate::install(&view, 0);
        auto* header = qobject_cast<NameHeader*>(view.horizontalHeader());
        QVERIFY(header);
        view.resize(900, 500);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QString prefix = u"/benchmarking_suite/timestamps/"_s;
        QCOMPARE(NameDelegate::sharedPrefix(names), prefix);
        // Room for whole names: they show whole, under the model's title.
        view.setColumnWidth(0, 800);
        QCOMPARE(delegate->strippedPrefix(), QString());
        QCOMPARE(header->title(0), u"Topic"_s);
        for (int r = 0; r < model.rowCount(); ++r)
            QCOMPARE(delegate->displayedText(model.index(r, 0)), names[r]);
        // Room for the rest only: every row shows its name without the prefix, the title has it.
        const int rest = view.fontMetrics().horizontalAdvance(u"mqtt_interface_vehicle/object_list/out"_s);
        view.setColumnWidth(0, rest + 40);
        QCOMPARE(delegate->strippedPrefix(), prefix);
        QCOMPARE(header->title(0), u"Topic in "_s + prefix);
        for (int r = 0; r < model.rowCount(); ++r)
            QCOMPARE(delegate->displayedText(model.index(r, 0)), names[r].mid(prefix.size()));
        // A list has a caption above it instead of a title.
        QWidget pane;
        auto* caption = new QLabel(u"Stamp topics seen:"_s, &pane);
        auto* list = new QListView(&pane);
        list->setModel(&model);
        NameDelegate* listNames = NameDelegate::install(list, 0);
        listNames->setCaption(caption);
        caption->setGeometry(0, 0, 300, 20);
        list->setGeometry(0, 20, rest + 40, 300);
        pane.show();
        QVERIFY(QTest::qWaitForWindowExposed(&pane));
        QTRY_COMPARE(caption->text(), u"Stamp topics seen in "_s + prefix + u":"_s);
        QCOMPARE(listNames->displayedText(model.index(0, 0)), names[0].mid(prefix.size()));
        // Names that share no namespace have no prefix to strip.
        QCOMPARE(NameDelegate::sharedPrefix({u"/a/b"_s, u"/c/d"_s}), QString());
        QCOMPARE(NameDelegate::sharedPrefix({u"/a/b"_s, u"/a/bc"_s}), u"/a/"_s);
        QCOMPARE(NameDelegate::sharedPrefix({u"/a/b"_s, u"/a/b/c"_s}), u"/a/"_s);
        QCOMPARE(NameDelegate::sharedPrefix({u"/a/b/"_s, u"/a/b/c"_s}), QString()); // a whole name
    }

    // Issue 33: Health read `10.0 Hz …, 1.6 ms`, the destination's rate hidden; both rates and
    // the latency show whole at 1280x800.
    void healthShowsBothRatesWhole()
    {
        MainWindow* w = m_window.get();
        w->resize(1280, 800);
        QTRY_COMPARE(w->size(), QSize(1280, 800));
        w->pages()->setCurrentWidget(mapPage(*w));
        QTableView* table = mapPage(*w)->editor()->table();
        const QAbstractItemModel* model = table->model();
        const auto healthy = [&] {
            int n = 0;
            for (int r = 0; r < model->rowCount(); ++r)
                n += model->index(r, MappingModel::HealthColumn).data().toString().contains(u" → "_s);
            return n;
        };
        QTRY_VERIFY_WITH_TIMEOUT(healthy() == model->rowCount(), 20000);
        // Figures grow once a second and the column follows within ColumnFitter::kGrowMs: every
        // row's health, as shown then, fits its column.
        const QStyleOptionViewItem option = cellOption(table);
        const auto cutProblem = [&]() -> QString {
            for (int r = 0; r < model->rowCount(); ++r) {
                const QModelIndex index = model->index(r, MappingModel::HealthColumn);
                const QString text = index.data().toString();
                const int needs = table->itemDelegateForIndex(index)->sizeHint(option, index).width();
                if (needs > table->columnWidth(MappingModel::HealthColumn))
                    return u"%1 needs %2 px, has %3"_s.arg(text).arg(needs).arg(
                        table->columnWidth(MappingModel::HealthColumn));
            }
            return QString();
        };
        QString problem;
        QTRY_VERIFY2_WITH_TIMEOUT((problem = cutProblem()).isEmpty(), qPrintable(problem), 5000);
        for (int r = 0; r < model->rowCount(); ++r) {
            const QModelIndex index = model->index(r, MappingModel::HealthColumn);
            const QString text = index.data().toString();
            QVERIFY2(text.count(u"Hz"_s) == 1 && text.contains(u'→'), qPrintable(text));
            QVERIFY(index.data(Qt::ToolTipRole).toString().contains(u"arrive"_s)
                    || index.data(Qt::ToolTipRole).toString().contains(u"published"_s));
        }
    }

    // Issue 33: Discover's MQTT tree shows each topic's last value, and the bytes, QoS and
    // retained columns are seen without scrolling sideways at 1280x800.
    void mqttFiguresAndValuesWithoutScrolling()
    {
        MainWindow* w = m_window.get();
        w->resize(1280, 800);
        QTRY_COMPARE(w->size(), QSize(1280, 800));
        w->pages()->setCurrentWidget(w->discoverPage());
        QTreeView* tree = w->discoverPage()->mqttView();
        const QHeaderView* header = tree->header();
        // The columns fit themselves shortly after the page shows: wait for the fit, then each
        // figure column is shown, ends inside the viewport and has its title whole.
        const auto columnProblem = [&]() -> QString {
            for (int c : {int(MqttTopicTree::BytesColumn), int(MqttTopicTree::QosColumn),
                          int(MqttTopicTree::RetainedColumn), int(MqttTopicTree::MessagesColumn),
                          int(MqttTopicTree::RateColumn)}) {
                const QString title = tree->model()->headerData(c, Qt::Horizontal).toString();
                if (tree->isColumnHidden(c))
                    return title + u" hidden"_s;
                const int right = header->sectionViewportPosition(c) + header->sectionSize(c);
                if (right > tree->viewport()->width())
                    return u"%1 ends at %2 of %3 px"_s.arg(title).arg(right).arg(tree->viewport()->width());
                if (header->sectionSize(c) < header->fontMetrics().horizontalAdvance(title) + 8)
                    return title + u" cut"_s; // its title whole
            }
            return QString();
        };
        QString problem;
        QTRY_VERIFY2_WITH_TIMEOUT((problem = columnProblem()).isEmpty(), qPrintable(problem), 5000);
        QVERIFY(!tree->isColumnHidden(MqttTopicTree::ValueColumn));
        const QModelIndex topic = ViewHelpers::find(tree->model(), u"benchmarking_suite/pointcloud"_s,
                                                    MqttTopicTree::FullTopicRole);
        QVERIFY(topic.isValid());
        const QString value = topic.siblingAtColumn(MqttTopicTree::ValueColumn).data().toString();
        QVERIFY2(!value.isEmpty() && !value.contains(u'\n')
                     && value.size() <= MqttTopicTree::kPreviewChars + 1,
                 qPrintable(value));
    }

    void fullNameInTheTooltip()
    {
        QTableView* view = named<QTableView>(*m_window->discoverPage(), u"rosTopics"_s);
        const QModelIndex index = view->model()->index(0, TopicTableModel::TopicColumn);
        QCOMPARE(index.data(Qt::ToolTipRole).toString(), index.data().toString());
    }

    // The vehicle bridge's latency topic (std_msgs/Float64, one per stamped message): monitored,
    // its `data` field picked in the detail pane, plotted as it arrives.
    void aFieldOfALiveTopicPlotsOverTime()
    {
        MainWindow* w = m_window.get();
        w->resize(1280, 800);
        w->pages()->setCurrentWidget(w->discoverPage());
        const QString topic = u"/mqtt_interface_vehicle/latencies/vehicle/object_list"_s;
        QTableView* view = named<QTableView>(*w->discoverPage(), u"rosTopics"_s);
        const QAbstractItemModel* model = view->model();
        QModelIndex row;
        for (int r = 0; r < model->rowCount(); ++r)
            if (model->index(r, TopicTableModel::TopicColumn).data().toString() == topic)
                row = model->index(r, TopicTableModel::MonitorColumn);
        QVERIFY2(row.isValid(), "the demo has no latency topic");
        QVERIFY(view->model()->setData(row, Qt::Checked, Qt::CheckStateRole));
        view->setCurrentIndex(row.siblingAtColumn(TopicTableModel::TopicColumn));
        DetailPane* detail = only<DetailPane>(*w->discoverPage());
        QTRY_COMPARE(detail->topic(), topic);
        const auto dataField = [detail]() -> QModelIndex {
            const QAbstractItemModel* m = named<QTreeView>(*detail, u"fields"_s)->model();
            for (int r = 0; r < m->rowCount(); ++r)
                if (m->index(r, 0).data(DetailPane::FieldPathRole).toStringList() == QStringList {u"data"_s})
                    return m->index(r, 0);
            return {};
        };
        QTRY_VERIFY_WITH_TIMEOUT(dataField().isValid(), 15000);
        named<QTreeView>(*detail, u"fields"_s)->setCurrentIndex(dataField());
        named<QAction>(*detail, u"plotAction"_s)->trigger(); // as Ctrl+L does
        const FieldPlotter* plotter = named<FieldPlotter>(*detail, u"fieldPlotter"_s);
        QCOMPARE(plotter->series().size(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(plotter->series()[0].points.size() >= 30, 20000);
        // One point per message at 10 Hz, in time order, each a latency in seconds (mqtt_client's
        // unit; negative here: the cloud's clock, which stamped the message, is 35 ms ahead).
        const QList<QPointF>& points = plotter->series()[0].points;
        QSet<double> distinct;
        for (int i = 0; i < points.size(); ++i) {
            QVERIFY2(std::abs(points[i].y()) < 5, qPrintable(QString::number(points[i].y())));
            if (i > 0)
                QVERIFY(points[i].x() >= points[i - 1].x());
            distinct.insert(points[i].y());
        }
        QVERIFY(distinct.size() > 5); // measured, not a constant
        QCOMPARE(plotter->series()[0].errors, 0u);
        // With the other bridge's latency beside it, the legend (the list below the chart, issue 40)
        // names both whole: topic and field, each entry as tall as its wrapped name needs.
        const QString other = u"/mqtt_interface_cloud/latencies/cloud/pointcloud"_s;
        QVERIFY(named<FieldPlotter>(*detail, u"fieldPlotter"_s)
                    ->add({PlotField::Source::Ros, other, {u"data"_s}}));
        FieldPlotChart* chart = named<FieldPlotChart>(*detail, u"plotChart"_s);
        detail->findChild<QTabWidget*>()->setCurrentWidget(chart->parentWidget());
        QTRY_COMPARE(chart->lines().size(), 2);
        QTRY_VERIFY(chart->lines()[1]->count() > 0);
        const QString first = chart->lines()[0]->name();
        const QString second = chart->lines()[1]->name();
        QCOMPARE(first, topic + u": data"_s);
        QCOMPARE(second, other + u": data"_s);
        QListWidget* legend = named<QListWidget>(*detail, u"plotList"_s);
        QTRY_COMPARE(legend->count(), 2);
        for (int i = 0; i < 2; ++i) {
            const QRect rect = legend->visualItemRect(legend->item(i));
            QCOMPARE(legend->item(i)->text(), chart->lines()[i]->name());
            QVERIFY2(DetailPane::wrappedHeight(legend->item(i)->text(), legend->font(),
                                               rect.width() - DetailPane::kLegendMargins)
                         <= rect.height(),
                     qPrintable(legend->item(i)->text()));
        }
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
            detail->findChild<QTabWidget*>()->setCurrentWidget(
                named<FieldPlotChart>(*detail, u"plotChart"_s)->parentWidget());
            QTest::qWait(500);
            w->grab().save(dir + u"/field-plot.png"_s);
        }
    }

    // Names from a master or a broker are hostile: 2,000 topics whose last segment is 60 KB are
    // measured with bounded work, and the column floor stays a screen wide, not kilometres.
    void hostileNamesAreMeasuredBoundedly()
    {
        QStandardItemModel model(2000, 1);
        const QString huge = u"/ns/"_s + QString(60000, u'x');
        for (int r = 0; r < model.rowCount(); ++r)
            model.setItem(r, 0, new QStandardItem(huge + QString::number(r)));
        QTableView view;
        view.setModel(&model);
        NameDelegate* delegate = NameDelegate::install(&view, 0);
        QElapsedTimer timer;
        timer.start();
        const int floor = delegate->tailWidth();
        QVERIFY2(timer.elapsed() < 2000, qPrintable(QString::number(timer.elapsed())));
        QVERIFY2(floor > 0 && floor < view.fontMetrics().horizontalAdvance(QString(500, u'x')),
                 qPrintable(QString::number(floor)));
    }

    void cleanupTestCase() { m_window.reset(); }
};

QTEST_MAIN(TestTopicNames)
#include "tst_topicnames.moc"
