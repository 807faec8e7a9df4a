// SPDX-License-Identifier: MIT
// The Map page driven through its real views and models: drops of dragged topics create and
// retarget mappings, undo takes them back, the saved file validates and holds what was made, and
// health tells a publisher without a bridge from traffic on both sides (real rosmaster, mosquitto).
#include "app/gui/mainwindow.h"
#include "config/configdocument.h"
#include "config/configreader.h"
#include "config/mappinghealth.h"
#include "config/mappingmodel.h"
#include "config/mqttclientrelease.h"
#include "config/problemmodel.h"
#include "fixtures.h"
#include "guisession.h"
#include "models/mqtttopictree.h"
#include "session/livesession.h"
#include "testservers.h"
#include "topics/topictablemodel.h"
#include "viewhelpers.h"
#include "widgets/common/problemspanel.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/map/configeditor.h"
#include "widgets/map/configfilecontroller.h"
#include "widgets/map/mappage.h"
#include "windowparts.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QComboBox>
#include <QLineEdit>
#include <QMimeData>
#include <QProcess>
#include <QScopeGuard>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>

using namespace Qt::StringLiterals;
using namespace ViewHelpers;
using namespace WindowParts;

namespace {
QStringList mappings(const ConfigDocument& doc)
{
    QStringList out;
    for (const Mapping& m : doc.config().mappings)
        out << u"%1 %2 %3%4"_s.arg(m.direction == Direction::Ros2Mqtt ? u"out"_s : u"in"_s, m.rosTopic(),
                                   m.mqttTopic(), m.isSet(u"primitive"_s) ? u" primitive"_s : QString());
    return out;
}

int healthOf(MapPage* page, const QString& ros, const QString& mqtt)
{
    page->updateHealth();
    MappingModel* model = page->editor()->model();
    for (int r = 0; r < model->rowCount(); ++r) {
        const QModelIndex i = model->index(r, 0);
        if (model->index(r, MappingModel::RosTopicColumn).data().toString() == ros
            && model->index(r, MappingModel::MqttTopicColumn).data().toString() == mqtt)
            return i.data(MappingModel::HealthStateRole).toInt();
    }
    return -2;
}

/// The problems the list shows: each row's message, as the user reads it.
QStringList shownProblems(const MapPage& page)
{
    const auto* view = named<QTreeView>(page, u"problemsView"_s);
    QStringList rows;
    for (int r = 0; r < view->model()->rowCount(); ++r)
        rows << view->model()->index(r, ProblemModel::MessageColumn).data().toString();
    return rows;
}

bool showsProblem(const MapPage& page, const QString& part)
{
    const QStringList rows = shownProblems(page);
    return std::any_of(rows.cbegin(), rows.cend(), [&](const QString& r) { return r.contains(part); });
}
} // namespace

class TestMapPage : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    std::vector<std::unique_ptr<QProcess>> m_nodes;
    QTemporaryDir m_settings; ///< the sessions' one settings folder, not the user's

    void rostopic(const QStringList& args)
    {
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(m_servers.rosEnvironment());
        p->start(u"rostopic"_s, args);
        m_nodes.push_back(std::move(p));
    }
    void mqttPub(const QStringList& args)
    {
        QProcess p;
        p.start(u"mosquitto_pub"_s,
                QStringList {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(m_servers.mosquittoPort())}
                    + args);
        p.waitForFinished(10000);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        GuiSession::useSettingsFolder(m_settings.path());
        QVERIFY(m_servers.startMosquitto());
        QVERIFY(m_servers.startRosMaster());
        const QProcessEnvironment env = m_servers.rosEnvironment();
        m_servers.exportRosEnvironment();
        rostopic({u"pub"_s, u"-r"_s, u"5"_s, u"/vehicle/speed"_s, u"std_msgs/Float64"_s, u"data: 12.5"_s});
        rostopic({u"pub"_s, u"-r"_s, u"2"_s, u"/lidar/points"_s, u"std_msgs/String"_s, u"data: scan"_s});
        mqttPub({u"-t"_s, u"plant/temperature"_s, u"-r"_s, u"-m"_s, u"21.5"_s});
        mqttPub({u"-t"_s, u"mqtt_client/ros_msg_type/cloud/objects"_s, u"-r"_s, u"-f"_s,
                 Fixtures::path(u"mqtt_client/wire/pose.type.bin"_s)});
        mqttPub({u"-t"_s, u"cloud/objects"_s, u"-r"_s, u"-f"_s,
                 Fixtures::path(u"mqtt_client/wire/pose.payload.bin"_s)});
        mqttPub({u"-t"_s, u"site/humidity"_s, u"-r"_s, u"-m"_s, u"40"_s});
        mqttPub({u"-t"_s, u"site/temperature"_s, u"-r"_s, u"-m"_s, u"21.5"_s});
    }

    void cleanupTestCase()
    {
        for (auto& p : m_nodes) {
            p->terminate();
            p->waitForFinished(10000);
        }
    }

    void dragDropUndoSaveReload()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        MapPage* page = mapPage(w);
        w.pages()->setCurrentWidget(page);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QAbstractItemModelTester mappingTester(page->editor()->table()->model(),
                                               QAbstractItemModelTester::FailureReportingMode::QtTest);
        QTreeView* rosView = named<QTreeView>(*page, u"mapRosTopics"_s);
        QTreeView* mqttView = named<QTreeView>(*page, u"mapMqttTopics"_s);
        QAbstractItemModelTester rosTester(rosView->model(),
                                           QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester mqttTester(mqttView->model(),
                                            QAbstractItemModelTester::FailureReportingMode::QtTest);
        QTRY_VERIFY_WITH_TIMEOUT(
            find(rosView->model(), u"/vehicle/speed"_s, TopicTableModel::TopicRole).isValid()
                && find(rosView->model(), u"/lidar/points"_s, TopicTableModel::TopicRole).isValid(),
            30000);
        QTRY_VERIFY_WITH_TIMEOUT(
            find(mqttView->model(), u"cloud/objects"_s, MqttTopicTree::FullTopicRole).isValid()
                && find(mqttView->model(), u"plant/temperature"_s, MqttTopicTree::FullTopicRole).isValid(),
            10000);
        mqttView->expandAll();
        ConfigDocument* doc = w.document();
        QUndoStack* undo = undoStack(w);

        QAbstractItemView* ros = named<QTreeView>(*page, u"mapRosTopics"_s);
        QAbstractItemView* mqtt = named<QTreeView>(*page, u"mapMqttTopics"_s);
        QAbstractItemView* table = page->editor()->table();
        auto rosRow = [&](const QString& t) { return find(ros->model(), t, TopicTableModel::TopicRole); };
        auto mqttNode
            = [&](const QString& t) { return find(mqtt->model(), t, MqttTopicTree::FullTopicRole); };

        // 1. A ROS topic onto an MQTT level: under that level.
        dragAndDrop(ros, {rosRow(u"/vehicle/speed"_s)}, mqtt, centre(mqtt, mqttNode(u"plant"_s)));
        QCOMPARE(mappings(*doc), QStringList {u"out /vehicle/speed plant/vehicle/speed"_s});
        // 2. Onto an existing MQTT topic that a device fills with plain text: exactly it, as a
        //    primitive. mqtt_client bridges a ROS topic once, so the mapping moves there.
        dragAndDrop(ros, {rosRow(u"/vehicle/speed"_s)}, mqtt, centre(mqtt, mqttNode(u"plant/temperature"_s)));
        QCOMPARE(mappings(*doc), QStringList {u"out /vehicle/speed plant/temperature primitive"_s});
        // 3. An MQTT topic onto the ROS topics (not onto one): a new ROS name.
        dragAndDrop(mqtt, {mqttNode(u"cloud/objects"_s)}, ros, below(ros));
        QCOMPARE(mappings(*doc).last(), u"in /cloud/objects cloud/objects"_s);
        // 4. Several ROS topics onto the mapping table: under the prefix.
        named<QLineEdit>(*page, u"mqttPrefix"_s)->setText(u"vehicle"_s);
        dragAndDrop(ros, {rosRow(u"/lidar/points"_s), rosRow(u"/vehicle/speed"_s)}, table, below(table));
        QCOMPARE(mappings(*doc),
                 (QStringList {u"out /vehicle/speed vehicle/vehicle/speed primitive"_s,
                               u"in /cloud/objects cloud/objects"_s,
                               u"out /lidar/points vehicle/lidar/points"_s}));
        QCOMPARE(undo->count(), 4); // one undo step per drop
        // 5. An MQTT topic onto a mapping: retargeted.
        const QModelIndex first = table->model()->index(0, MappingModel::MqttTopicColumn);
        dragAndDrop(mqtt, {mqttNode(u"cloud/objects"_s)}, table, centre(table, first));
        QCOMPARE(mappings(*doc).first(), u"out /vehicle/speed cloud/objects primitive"_s);
        // Undo the retarget and the last drop, redo one.
        undo->undo();
        QCOMPARE(mappings(*doc).first(), u"out /vehicle/speed vehicle/vehicle/speed primitive"_s);
        undo->undo();
        QCOMPARE(mappings(*doc),
                 (QStringList {u"out /vehicle/speed plant/temperature primitive"_s,
                               u"in /cloud/objects cloud/objects"_s}));
        undo->redo();
        QCOMPARE(doc->mappingCount(), 3);

        // 6. The keyboard way: select a ROS topic, bridge it (here: moves its mapping).
        ros->selectionModel()->select(rosRow(u"/lidar/points"_s),
                                      QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        mqtt->selectionModel()->clearSelection();
        named<QLineEdit>(*page, u"mqttPrefix"_s)->setText(u"kbd"_s);
        page->bridgeToMqttAction()->trigger();
        QCOMPARE(mappings(*doc).last(), u"out /lidar/points kbd/lidar/points"_s);
        ros->selectionModel()->select(rosRow(u"/lidar/points"_s),
                                      QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        mqtt->selectionModel()->select(mqttNode(u"cloud/objects"_s),
                                       QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        ros->selectionModel()->clearSelection();
        page->bridgeToRosAction()->trigger(); // cloud/objects is bridged already: nothing new
        QCOMPARE(doc->mappingCount(), 3);

        // Save, check with the command line, reload: the mappings that were made.
        QTemporaryDir dir;
        const QString path = dir.filePath(u"vehicle.yaml"_s);
        QVERIFY(w.files()->saveTo(path, ConfigLayout::Ros1));
        QProcess validate;
        validate.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"config"_s, u"validate"_s, path});
        QVERIFY(validate.waitForFinished(20000));
        QVERIFY2(validate.exitCode() == 0, validate.readAllStandardOutput().constData());
        QStringList made = mappings(*doc);
        ConfigDocument reloaded;
        QVERIFY(reloaded.load(path).ok);
        QStringList back = mappings(reloaded);
        made.sort(); // the file lists ros2mqtt before mqtt2ros
        back.sort();
        QCOMPARE(back, made);
    }

    // Issue 40: MQTT topics dropped on a ROS topic's row went below that topic's namespace
    // (`plant/*` under `/…/pointcloud/`, dropped on `/…/pointcloud/in`). A topic row takes one
    // MQTT topic exactly (it is published there); several keep their own names at the root, as
    // dropped beside the rows; a namespace's row takes them below it.
    void dropsOnRosTopicsAndNamespaces()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        MapPage* page = mapPage(w);
        w.pages()->setCurrentWidget(page);
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QAbstractItemView* ros = named<QTreeView>(*page, u"mapRosTopics"_s);
        QAbstractItemView* mqtt = named<QTreeView>(*page, u"mapMqttTopics"_s);
        auto rosRow = [&](const QString& t) { return find(ros->model(), t, TopicTableModel::TopicRole); };
        auto mqttNode
            = [&](const QString& t) { return find(mqtt->model(), t, MqttTopicTree::FullTopicRole); };
        QTRY_VERIFY_WITH_TIMEOUT(rosRow(u"/lidar/points"_s).isValid(), 30000);
        QTRY_VERIFY_WITH_TIMEOUT(
            mqttNode(u"site/humidity"_s).isValid() && mqttNode(u"site/temperature"_s).isValid(), 10000);
        named<QTreeView>(*page, u"mapMqttTopics"_s)->expandAll();
        ConfigDocument* doc = w.document();
        const auto made = [doc] { return mappings(*doc).replaceInStrings(u" primitive"_s, QString()); };

        // Several onto a topic: their own names, at the root.
        dragAndDrop(mqtt, {mqttNode(u"site"_s)}, ros, centre(ros, rosRow(u"/lidar/points"_s)));
        QCOMPARE(
            made(),
            (QStringList {u"in /site/humidity site/humidity"_s, u"in /site/temperature site/temperature"_s}));
        undoStack(w)->undo();
        // One onto a topic: exactly that topic.
        dragAndDrop(mqtt, {mqttNode(u"site/humidity"_s)}, ros, centre(ros, rosRow(u"/lidar/points"_s)));
        QCOMPARE(made(), QStringList {u"in /lidar/points site/humidity"_s});
        undoStack(w)->undo();
        // Onto a namespace: below it.
        const QModelIndex lidar = find(ros->model(), u"lidar/"_s, Qt::DisplayRole);
        QVERIFY2(lidar.isValid(), "no row for the namespace /lidar/");
        dragAndDrop(mqtt, {mqttNode(u"site"_s)}, ros, centre(ros, lidar));
        QCOMPARE(made(),
                 (QStringList {u"in /lidar/site/humidity site/humidity"_s,
                               u"in /lidar/site/temperature site/temperature"_s}));
        // A namespace dragged onto the MQTT side bridges every topic below it.
        undoStack(w)->undo();
        dragAndDrop(ros, {lidar}, mqtt, centre(mqtt, mqttNode(u"site"_s)));
        QCOMPARE(made(), QStringList {u"out /lidar/points site/lidar/points"_s});
    }

    void healthSeesBridgesAndTheirAbsence()
    {
        MainWindow w;
        w.discoverPage()->setRosMasterUri(m_servers.rosMasterUri());
        w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        MapPage* page = mapPage(w);
        w.show();
        QTRY_VERIFY_WITH_TIMEOUT(w.session()->rosTopics()->rowOf(u"/vehicle/speed"_s) >= 0, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(w.session()->mqtt()->state() == MqttConnection::State::Connected, 10000);
        page->bridgeRosTopics({{u"/vehicle/speed"_s, u"std_msgs/Float64"_s}}, u"health"_s);
        page->bridgeRosTopics({{u"/not/published"_s, u"std_msgs/Float64"_s}}, u"health"_s);
        // A publisher with no bridge behind it is flagged.
        QCOMPARE(healthOf(page, u"/vehicle/speed"_s, u"health/vehicle/speed"_s),
                 int(MappingHealth::NoBridge));
        QCOMPARE(healthOf(page, u"/not/published"_s, u"health/not/published"_s), int(MappingHealth::Missing));
        // Traffic on both sides: healthy.
        QTimer feeder;
        connect(&feeder, &QTimer::timeout, this, [this] {
            mqttPub({u"-t"_s, u"health/vehicle/speed"_s, u"-m"_s, u"12.5"_s});
        });
        feeder.start(200);
        QTRY_COMPARE_WITH_TIMEOUT(healthOf(page, u"/vehicle/speed"_s, u"health/vehicle/speed"_s),
                                  int(MappingHealth::Healthy), 15000);
        feeder.stop();
        const QModelIndex row = page->editor()->model()->indexOfMapping(w.document()->mapping(0).id,
                                                                        MappingModel::HealthColumn);
        QVERIFY(row.data().toString().contains(u"→"_s));

        if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty()) {
            // For the docs: the paper's vehicle config on top of what is discovered. Test publishers
            // stand in for the vehicle's nodes and for a cloud bridge: lidar packets on ROS and on
            // MQTT (a bridge running), the object list on MQTT only (no bridge on this side yet).
            rostopic({u"pub"_s, u"-r"_s, u"10"_s, u"/benchmarking_suite/packets"_s, u"std_msgs/String"_s,
                      u"data: scan"_s});
            QVERIFY(w.files()->openFile(
                QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/resources/examples/paper_vehicle.yaml")));
            w.pages()->setCurrentWidget(page);
            w.resize(1600, 950);
            page->editor()->setInspectorWidth(380);
            QTimer traffic;
            int n = 0;
            connect(&traffic, &QTimer::timeout, this, [&] {
                ++n;
                mqttPub({u"-t"_s, u"benchmarking_suite/packets"_s, u"-m"_s, QString::number(n)});
                mqttPub({u"-t"_s, u"benchmarking_suite/object_list"_s, u"-m"_s, u"[]"_s});
            });
            traffic.start(100);
            QTRY_VERIFY_WITH_TIMEOUT(w.session()->rosTopics()->rowOf(u"/benchmarking_suite/packets"_s) >= 0,
                                     30000);
            QTest::qWait(2500);
            named<QTreeView>(*page, u"mapMqttTopics"_s)->expandAll();
            page->updateHealth();
            w.grab().save(shots + u"/map.png"_s);
            traffic.stop();
        }
    }

    // Issue 45 on the Map page: a release chosen beside the Problems list is kept for the file
    // across sessions (one settings folder) and changes what is flagged; what the broker carries
    // adds the lab's traps to the same list (text with no mqtt_client type announced, #12/#78), and
    // a Fast DDS discovery server in the environment is said once (#67).
    void releaseKeptPerFileAndLabLints()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(u"bridge.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("mqtt_client:\n"
                "  ros__parameters:\n"
                "    bridge:\n"
                "      mqtt2ros:\n"
                "        mqtt_topics: [plant/temperature, cloud/objects, site/humidity]\n"
                "        plant/temperature:\n"
                "          ros_topic: /plant/temperature\n"
                "        cloud/objects:\n"
                "          ros_topic: /cloud/objects\n"
                "        site/humidity:\n"
                "          ros_topic: /site/humidity\n"
                "          primitive: true\n"
                "          ros_type: std_msgs/msg/String\n");
        f.close();
        qputenv("ROS_DISCOVERY_SERVER", "127.0.0.1:11811");
        const auto restore = qScopeGuard([] { qunsetenv("ROS_DISCOVERY_SERVER"); });
        {
            MainWindow w;
            w.resize(1280, 800);
            w.discoverPage()->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
            MapPage* page = mapPage(w);
            QVERIFY(w.files()->openFile(path));
            w.pages()->setCurrentWidget(page);
            w.show();
            auto* release = named<QComboBox>(*page, u"targetRelease"_s);
            QCOMPARE(release->currentText(), u"auto"_s);
            QTRY_VERIFY_WITH_TIMEOUT(w.session()->mqtt()->state() == MqttConnection::State::Connected, 10000);
            // plant/temperature is retained text from a plain publisher; cloud/objects is mqtt_client's.
            QTRY_VERIFY2_WITH_TIMEOUT(showsProblem(*page, u"'plant/temperature' carries messages"_s),
                                      qPrintable(shownProblems(*page).join(u'\n')), 15000);
            QVERIFY(!showsProblem(*page, u"'cloud/objects' carries messages"_s));
            QVERIFY(!showsProblem(*page, u"'site/humidity' carries messages"_s));
            QVERIFY(showsProblem(*page, u"ROS_DISCOVERY_SERVER=127.0.0.1:11811"_s));
            QVERIFY(!showsProblem(*page, u"reads 'ros_type' from 2.3 on"_s));
            if (const QString shots = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
                w.grab().save(shots + u"/map-release-lints.png"_s);

            // The user picks 2.2 with the keyboard (Alt+G, Down): ros_type came with 2.3.
            QVERIFY(QTest::qWaitForWindowActive(&w));
            QTest::keyClick(&w, Qt::Key_G, Qt::AltModifier);
            QTRY_VERIFY(release->hasFocus());
            QTest::keyClick(release, Qt::Key_Down);
            QCOMPARE(release->currentText(), u"2.2"_s);
            QTRY_VERIFY2(showsProblem(*page, u"reads 'ros_type' from 2.3 on"_s),
                         qPrintable(shownProblems(*page).join(u'\n')));
            QVERIFY(release->toolTip().contains(u"2.2"_s));
        }
        {
            // The next session, same settings: the file opens against 2.2 again.
            MainWindow w;
            w.resize(1280, 800);
            MapPage* page = mapPage(w);
            QVERIFY(w.files()->openFile(path));
            auto* release = named<QComboBox>(*page, u"targetRelease"_s);
            QCOMPARE(release->currentText(), u"2.2"_s);
            QVERIFY(showsProblem(*page, u"reads 'ros_type' from 2.3 on"_s));
            // Another file is not: it is checked against the newest release its layout loads.
            w.files()->newFile();
            QCOMPARE(release->currentText(), u"auto"_s);
            QVERIFY(w.files()->openFile(path));
            QCOMPARE(release->currentText(), u"2.2"_s);
            // Back to auto: forgotten for the file.
            release->setFocus();
            QTest::keyClick(release, Qt::Key_Up);
            QCOMPARE(release->currentText(), u"auto"_s);
            QTRY_VERIFY(!showsProblem(*page, u"reads 'ros_type' from 2.3 on"_s));
            QVERIFY(!ProblemsPanel::savedTarget(QFileInfo(path).absoluteFilePath()));
        }
        // What the settings file holds is not trusted: an entry without a tab or with a release no
        // one has reads as auto, and the list is kept to its bound however long it was.
        QStringList entries {u"no tab here"_s, u"2.9\t/x.yaml"_s, u"\t/y.yaml"_s};
        for (int i = 0; i < 500; ++i)
            entries << u"2.3\t/f%1.yaml"_s.arg(i);
        QSettings().setValue(u"map/releaseTargets"_s, entries);
        QVERIFY(!ProblemsPanel::savedTarget(u"/x.yaml"_s));
        QVERIFY(!ProblemsPanel::savedTarget(u"/y.yaml"_s));
        QCOMPARE(ProblemsPanel::savedTarget(u"/f7.yaml"_s), MqttClientRelease::V2_3);
        ProblemsPanel::saveTarget(u"/z.yaml"_s, MqttClientRelease::V2_4_1);
        QCOMPARE(QSettings().value(u"map/releaseTargets"_s).toStringList().size(),
                 ProblemsPanel::kMaxSavedTargets);
        QCOMPARE(ProblemsPanel::savedTarget(u"/z.yaml"_s), MqttClientRelease::V2_4_1);
    }
};

QTEST_MAIN(TestMapPage)
#include "tst_mappage.moc"
