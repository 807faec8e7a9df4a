// SPDX-License-Identifier: MIT
// The Discover page's ROS 2 graph: a Cyclone DDS node (tests/ros2peer) seen through Bridgescope's
// participant (Cyclone DDS, in bridgescope-dds), shown in the ROS 2 tab with its node, monitored, its samples
// decoded in the detail pane with the bundled definitions, an unknown type shown raw; the ROS 1 / ROS 2 /
// both switch joining and leaving the domain; a ROS 2 config on the Map page judged against the ROS 2 graph
// (QoS that cannot match, a publisher without a bridge).
#include "app/gui/mainwindow.h"
#include "app/gui/pageparts.h"
#include "config/configdocument.h"
#include "config/mappinghealth.h"
#include "config/mappingmodel.h"
#include "ddschild.h"
#include "namecheck.h"
#include "ros2peer.h"
#include "rtpscorpus.h"
#include "session/livesession.h"
#include "testservers.h"
#include "topics/topictablemodel.h"
#include "topics/topictree.h"
#include "viewhelpers.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/mappage.h"
#include "windowparts.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QPlainTextEdit>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QTabBar>
#include <QTableView>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <signal.h>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;
using namespace WindowParts;

namespace {
/// The displayed text of a column of the table, row by row.
QStringList column(const QTableView* view, int column)
{
    QStringList out;
    const QAbstractItemModel* m = view->model();
    for (int r = 0; r < m->rowCount(); ++r)
        out << m->index(r, column).data().toString();
    return out;
}

int rowOf(const QTableView* view, const QString& topic)
{
    return int(column(view, TopicTableModel::TopicColumn).indexOf(topic));
}

/// "name = value" of every top-level field the detail pane shows.
QStringList fields(const DetailPane* detail)
{
    QStringList out;
    const QAbstractItemModel* m = named<QTreeView>(*detail, u"fields"_s)->model();
    for (int r = 0; r < m->rowCount(); ++r)
        out << m->index(r, 0).data().toString() + u" = "_s + m->index(r, 1).data().toString();
    return out;
}

int healthOf(MapPage* page, const QString& ros, QString* detail = nullptr)
{
    page->updateHealth();
    MappingModel* model = page->editor()->model();
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->index(r, MappingModel::RosTopicColumn).data().toString() != ros)
            continue;
        if (detail)
            *detail = model->index(r, MappingModel::HealthColumn).data(Qt::ToolTipRole).toString();
        return model->index(r, 0).data(MappingModel::HealthStateRole).toInt();
    }
    return -2;
}
} // namespace

class TestDiscoverRos2 : public QObject
{
    Q_OBJECT
    int m_domain = 0;

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        m_domain = Ros2Peer::freeDomain(141, 180);
    }

    void ros2Graph()
    {
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/lab/talker"_s, u"--size"_s, u"256"_s, u"--pub"_s,
                         u"/chatter:std_msgs/msg/String:20"_s, u"--pub"_s,
                         u"/blob:bridgescope_test/msg/Opaque:10:best_effort"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));

        LiveSession session;
        DiscoverPage page(PageParts::discover(&session));
        QTabWidget* rosTabs = named<QTabWidget>(page, u"rosTabs"_s);
        page.resize(1280, 760);
        page.show();
        QCOMPARE(page.rosGraphs(), DiscoverPage::RosGraphs::Ros1);
        QVERIFY(!session.isRos2Running()); // no DDS traffic unless asked for
        page.setRos2Options({m_domain, true});
        page.setRosGraphs(DiscoverPage::RosGraphs::Ros2);
        QVERIFY(session.isRos2Running());
        QCOMPARE(page.rosGraphsBox()->currentIndex(), 1);
        QCOMPARE(rosTabs->currentIndex(), 1);
        QVERIFY(!rosTabs->tabBar()->isVisible());

        QTableView* view = named<QTableView>(page, u"ros2Topics"_s);
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(view, u"/chatter"_s) >= 0 && rowOf(view, u"/blob"_s) >= 0, 15000);
        const int chatter = rowOf(view, u"/chatter"_s);
        QCOMPARE(column(view, TopicTableModel::TypeColumn).at(chatter), u"std_msgs/msg/String"_s);
        QCOMPARE(column(view, TopicTableModel::PublishersColumn).at(chatter), u"1"_s);
        QTRY_VERIFY_WITH_TIMEOUT(named<QLabel>(page, u"ros2State"_s)->text().contains(u"topics 2, nodes 1"_s),
                                 5000);
        QVERIFY(named<QLabel>(page, u"rosState"_s)->text().contains(u"ROS 2 only"_s));

        // Monitor, select: decoded fields, QoS and node in the title
        TopicTableModel* model = session.ros2Topics();
        QVERIFY(model->setData(model->index(model->rowOf(u"/chatter"_s), TopicTableModel::MonitorColumn),
                               Qt::Checked, Qt::CheckStateRole));
        view->setCurrentIndex(view->model()->index(chatter, TopicTableModel::TopicColumn));
        DetailPane* detail = only<DetailPane>(page);
        QCOMPARE(detail->topic(), u"/chatter"_s);
        QTRY_VERIFY_WITH_TIMEOUT(fields(detail).join(u'|').contains(u"data = hello "_s), 10000);
        QVERIFY2(detail->title()->text().contains(u"/lab/talker (reliable, volatile)"_s),
                 qPrintable(detail->title()->text()));
        QTRY_VERIFY_WITH_TIMEOUT(
            column(view, TopicTableModel::RateColumn).at(rowOf(view, u"/chatter"_s)).toDouble() > 10, 10000);

        // a type without a definition: said so, the bytes shown raw
        QVERIFY(model->setData(model->index(model->rowOf(u"/blob"_s), TopicTableModel::MonitorColumn),
                               Qt::Checked, Qt::CheckStateRole));
        view->setCurrentIndex(view->model()->index(rowOf(view, u"/blob"_s), TopicTableModel::TopicColumn));
        QTRY_VERIFY_WITH_TIMEOUT(
            fields(detail).join(u'|').contains(u"No ROS 2 definition of bridgescope_test/msg/Opaque"_s),
            10000);
        QVERIFY2(fields(detail).join(u'|').contains(u"268 byte"_s), qPrintable(fields(detail).join(u'|')));
        QVERIFY(!named<QPlainTextEdit>(*detail, u"payload"_s)->toPlainText().isEmpty());
        QVERIFY2(detail->title()->text().contains(u"best effort"_s), qPrintable(detail->title()->text()));

        // both graphs: two tabs; ROS 1 only: the domain is left and the ROS 2 table empties
        page.setRosGraphs(DiscoverPage::RosGraphs::Both);
        QVERIFY(rosTabs->tabBar()->isVisible());
        QVERIFY(rosTabs->isTabVisible(0) && rosTabs->isTabVisible(1));
        QVERIFY(session.isRos2Running());
        page.setRosGraphs(DiscoverPage::RosGraphs::Ros1);
        QVERIFY(!session.isRos2Running());
        QCOMPARE(model->rowCount(), 0);
        QVERIFY(!rosTabs->isTabVisible(1));
    }

    // A hostile node: a String claiming 4 GiB, and an unreadable ros_discovery_info. The pane says
    // why the sample does not decode, the status line counts the announcement, the rest goes on.
    void hostilePeer()
    {
        const QString gid = u"01"_s.repeated(16) + u"00"_s.repeated(8);
        Ros2Peer evil(m_domain,
                      {u"--node"_s, u"/evil"_s, u"--pub"_s, u"/huge:std_msgs/msg/String:20"_s, u"--raw"_s,
                       u"/huge:00010000f0ffffff61626300"_s, u"--pub"_s, u"/fine:std_msgs/msg/String:20"_s,
                       u"--graph-raw"_s, u"00010000"_s + gid + u"ffffffff"_s});
        QVERIFY2(evil.waitFor(u"ready"_s), qPrintable(evil.errors()));
        LiveSession session;
        DiscoverPage page(PageParts::discover(&session));
        QLabel* ros2State = named<QLabel>(page, u"ros2State"_s);
        page.resize(1280, 760);
        page.show();
        page.setRos2Options({m_domain, true});
        page.setRosGraphs(DiscoverPage::RosGraphs::Ros2);
        QTableView* view = named<QTableView>(page, u"ros2Topics"_s);
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(view, u"/huge"_s) >= 0 && rowOf(view, u"/fine"_s) >= 0, 15000);
        QTRY_VERIFY2_WITH_TIMEOUT(ros2State->text().contains(u"unreadable node announcements 1"_s),
                                  qPrintable(ros2State->text()), 10000);

        TopicTableModel* model = session.ros2Topics();
        for (const QString& topic : {u"/huge"_s, u"/fine"_s})
            QVERIFY(model->setData(model->index(model->rowOf(topic), TopicTableModel::MonitorColumn),
                                   Qt::Checked, Qt::CheckStateRole));
        view->setCurrentIndex(view->model()->index(rowOf(view, u"/huge"_s), TopicTableModel::TopicColumn));
        DetailPane* detail = only<DetailPane>(page);
        QTRY_VERIFY_WITH_TIMEOUT(fields(detail).join(u'|').contains(u"needs 4294967280 more bytes"_s), 10000);
        QVERIFY(
            !named<QPlainTextEdit>(*detail, u"payload"_s)->toPlainText().isEmpty()); // the bytes, shown raw
        // the well-formed topic of the same node decodes, and both keep their rates
        view->setCurrentIndex(view->model()->index(rowOf(view, u"/fine"_s), TopicTableModel::TopicColumn));
        QTRY_VERIFY_WITH_TIMEOUT(fields(detail).join(u'|').contains(u"data = hello "_s), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(
            column(view, TopicTableModel::RateColumn).at(rowOf(view, u"/huge"_s)).toDouble() > 10, 10000);
    }

    // Hostile datagrams on the domain (issue 31), which Cyclone DDS goes through, then a crash of
    // the DDS child (as Fast DDS 2.9.1 had on one of them): the window lives on, says that ROS 2
    // discovery restarted, and lists the well-behaved node again.
    void windowSurvivesHostileDatagrams()
    {
        const int domain = Ros2Peer::freeDomain(RtpsCorpus::kFirstDomain, RtpsCorpus::kLastDomain);
        Ros2Peer talker(domain, {u"--node"_s, u"/steady"_s, u"--pub"_s, u"/steady:std_msgs/msg/String:20"_s,
                                 u"--duration"_s, u"120"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        LiveSession session;
        DiscoverPage page(PageParts::discover(&session));
        QLabel* ros2State = named<QLabel>(page, u"ros2State"_s);
        page.resize(1280, 760);
        page.show();
        page.setRos2Options({domain, true});
        page.setRosGraphs(DiscoverPage::RosGraphs::Ros2);
        QTableView* view = named<QTableView>(page, u"ros2Topics"_s);
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(view, u"/steady"_s) >= 0, 15000);
        RtpsCorpus::send(domain, RtpsCorpus::load(u"fastdds"_s), 500);
        QTest::qWait(500); // the stimulus: the child has half a second to choke on the corpus
        QVERIFY(!ros2State->text().contains(u"restarted"_s));
        QVERIFY(DdsChild::kill(SIGSEGV) > 0);
        QTRY_VERIFY2_WITH_TIMEOUT(ros2State->text().contains(u"restarted"_s), qPrintable(ros2State->text()),
                                  20000);
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(view, u"/steady"_s) >= 0 && session.ros2()->graph().participants > 0, 60000);
        QVERIFY(ros2State->text().contains(u"restarted"_s)); // and it stays said
    }

    void mapRos2Config()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/lidar_driver"_s, u"--pub"_s,
                         u"/scan_text:std_msgs/msg/String:10:best_effort"_s, u"--pub"_s,
                         u"/odom_text:std_msgs/msg/String:10"_s, u"--pub"_s,
                         u"/robot1/pose:geometry_msgs/msg/PoseStamped:10"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        // mqtt_client v2.5's ROS 2 layout: one mapping asks for reliable delivery from a best-effort
        // publisher (it would never subscribe), one takes the publisher's QoS (auto).
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.ros2.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("/**/*:\n"
                "  ros__parameters:\n"
                "    broker: {host: localhost, port: 1883}\n"
                "    bridge:\n"
                "      ros2mqtt:\n"
                "        ros_topics: [/scan_text, /odom_text, /robot1/pose]\n"
                "        /scan_text:\n"
                "          mqtt_topic: lab/scan_text\n"
                "          advanced: {ros: {qos: {reliability: reliable}}}\n"
                "        /odom_text:\n"
                "          mqtt_topic: lab/odom_text\n"
                "        /robot1/pose:\n"
                "          mqtt_topic: lab/robot1/pose\n");
        f.close();

        MainWindow w;
        QVERIFY(w.document()->load(path).ok);
        QCOMPARE(w.document()->config().layout, ConfigLayout::Ros2);
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(servers.brokerUrl()));
        w.discoverPage()->setRos2Options({m_domain, true});
        w.discoverPage()->setRosGraphs(DiscoverPage::RosGraphs::Ros2);
        MapPage* page = mapPage(w);
        w.show();
        QTRY_VERIFY_WITH_TIMEOUT(w.session()->mqtt()->state() == MqttConnection::State::Connected, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(w.session()->ros2Topics()->rowOf(u"/odom_text"_s) >= 0
                                     && w.session()->ros2Topics()->rowOf(u"/scan_text"_s) >= 0,
                                 15000);
        QString detail;
        // (the node's name follows its endpoints, with its ros_discovery_info)
        QTRY_VERIFY2_WITH_TIMEOUT(healthOf(page, u"/scan_text"_s, &detail) == int(MappingHealth::QosMismatch)
                                      && detail.contains(u"/lidar_driver publishes best effort"_s),
                                  qPrintable(detail), 5000);
        // auto QoS matches; the publisher is there, no bridge carries it to the broker
        QCOMPARE(healthOf(page, u"/odom_text"_s), int(MappingHealth::NoBridge));
        // the Map's ROS list is the ROS 2 graph now
        QAbstractItemModel* rosList = named<QTreeView>(*page, u"mapRosTopics"_s)->model();
        QVERIFY(ViewHelpers::find(rosList, u"/scan_text"_s, TopicTableModel::TopicRole).isValid());
        // At 1280x800 the ROS 2 types keep their last segment, in the bold of bridged topics too.
        w.resize(1280, 800);
        w.pages()->setCurrentWidget(page);
        QTRY_VERIFY(rosList->rowCount() >= 3);
        // the columns fit themselves 100 ms after a change: wait for the fit
        for (int column : {int(TopicTree::TopicColumn), int(TopicTree::TypeColumn)}) {
            QString problem;
            QTRY_VERIFY2_WITH_TIMEOUT(
                (problem = treeNamesShownProblem(named<QTreeView>(*page, u"mapRosTopics"_s), column, 3))
                    .isEmpty(),
                qPrintable(problem), 5000);
        }
        // the node leaves: its topics are missing from the graph
        talker.terminate();
        QTRY_COMPARE_WITH_TIMEOUT(healthOf(page, u"/odom_text"_s, &detail), int(MappingHealth::Missing),
                                  10000);
        QVERIFY2(detail.contains(u"ROS 2 domain"_s), qPrintable(detail));
    }
};

QTEST_MAIN(TestDiscoverRos2)
#include "tst_discoverros2.moc"
