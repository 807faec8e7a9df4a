// SPDX-License-Identifier: MIT
// The Discover page with real traffic: a real rosmaster with rostopic nodes, a real mosquitto
// with what mqtt_client sends (for ROS 1 and ROS 2), JSON and a 2 MB binary payload.
#include "app/gui/mainwindow.h"
#include "fixtures.h"
#include "models/mqtttopicfilter.h"
#include "models/mqtttopictree.h"
#include "mqttclientros2.h"
#include "session/livesession.h"
#include "testservers.h"
#include "topics/topictablemodel.h"
#include "viewhelpers.h"
#include "widgets/common/livetext.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/tools/mqttprofiledialog.h"

#include <QAbstractItemModelTester>
#include <QDialogButtonBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QTableView>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;

namespace {
QStringList fieldNames(QAbstractItemModel* model, const QModelIndex& parent = {})
{
    QStringList out;
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        out << i.data().toString();
        for (const QString& c : fieldNames(model, i))
            out << i.data().toString() + u'.' + c;
    }
    return out;
}

void run(const QString& program, const QStringList& args)
{
    QProcess p;
    p.start(program, args);
    p.waitForFinished(20000);
}

QString writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}
} // namespace

class TestDiscoverPage : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    std::unique_ptr<QProcess> m_pub;

    QStringList pubArgs() const
    {
        return {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(m_servers.mosquittoPort())};
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_servers.startMosquitto());
        QVERIFY(m_servers.startRosMaster());
        const QProcessEnvironment env = m_servers.rosEnvironment();
        m_servers.exportRosEnvironment();
        m_pub = std::make_unique<QProcess>();
        m_pub->setProcessEnvironment(env);
        m_pub->start(u"rostopic"_s,
                     {u"pub"_s, u"-r"_s, u"10"_s, u"/vehicle/pose"_s, u"geometry_msgs/PoseStamped"_s,
                      u"{header: {frame_id: base_link}, pose: {position: {x: 4.25}}}"_s});
        run(u"mosquitto_pub"_s,
            pubArgs()
                + QStringList {u"-t"_s, u"mqtt_client/ros_msg_type/vehicle/pose"_s, u"-r"_s, u"-f"_s,
                               Fixtures::path(u"mqtt_client/wire/pose.type.bin"_s)});
        run(u"mosquitto_pub"_s,
            pubArgs()
                + QStringList {u"-t"_s, u"vehicle/pose"_s, u"-r"_s, u"-f"_s,
                               Fixtures::path(u"mqtt_client/wire/pose.payload.bin"_s)});
        run(u"mosquitto_pub"_s,
            pubArgs()
                + QStringList {u"-t"_s, u"fleet/car1/status"_s, u"-r"_s, u"-m"_s,
                               u"{\"speed\": 12.5, \"gear\": \"D\"}"_s});
        // A hostile JSON payload: 5,000 keys, each an array of 200 numbers (a million values).
        QByteArray wide = "{";
        const QByteArray numbers = '[' + QByteArray("1,").repeated(199) + "1]";
        for (int i = 0; i < 5000; ++i)
            wide += (i ? ",\"k" : "\"k") + QByteArray::number(i) + "\":" + numbers;
        wide += '}';
        run(u"mosquitto_pub"_s,
            pubArgs()
                + QStringList {u"-t"_s, u"fleet/hostile/json"_s, u"-r"_s, u"-f"_s,
                               writeFile(m_servers.tempPath() + u"/wide.json"_s, wide)});
        // mqtt_client for ROS 2: a stamped std_msgs/msg/String, and a type without a bundled
        // definition.
        const QString dir = m_servers.tempPath();
        const QList<std::pair<QString, QByteArray>> ros2 {
            {u"mqtt_client/ros_msg_type/ros2/chatter"_s,
             MqttClientRos2::announcement("std_msgs/msg/String", true)},
            {u"ros2/chatter"_s, MqttClientRos2::stamped(1700000000, 0, MqttClientRos2::string("hello ros2"))},
            {u"mqtt_client/ros_msg_type/ros2/state"_s,
             MqttClientRos2::announcement("my_pkg/msg/State", false)},
            {u"ros2/state"_s, MqttClientRos2::serialize([](auto& cdr) { cdr << uint8_t(3); })},
        };
        int n = 0;
        for (const auto& [topic, bytes] : ros2)
            run(u"mosquitto_pub"_s,
                pubArgs()
                    + QStringList {u"-t"_s, topic, u"-r"_s, u"-f"_s,
                                   writeFile(dir + u"/ros2-%1.bin"_s.arg(n++), bytes)});
    }

    void cleanupTestCase()
    {
        m_pub->terminate();
        m_pub->waitForFinished(10000);
    }

    void showsBothSidesAndWhatATopicCarries()
    {
        MainWindow w;
        DiscoverPage* page = w.discoverPage();
        DetailPane* detail = only<DetailPane>(*page);
        page->setRosMasterUri(m_servers.rosMasterUri());
        page->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QAbstractItemModelTester treeTester(page->mqttView()->model(),
                                            QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester rosTester(named<QTableView>(*page, u"rosTopics"_s)->model(),
                                           QAbstractItemModelTester::FailureReportingMode::QtTest);

        // Both sides fill up.
        QTRY_VERIFY_WITH_TIMEOUT(
            ViewHelpers::find(page->mqttView()->model(), u"vehicle/pose"_s, MqttTopicTree::FullTopicRole)
                .isValid(),
            15000);
        QTRY_VERIFY_WITH_TIMEOUT(ViewHelpers::find(named<QTableView>(*page, u"rosTopics"_s)->model(),
                                                   u"/vehicle/pose"_s, TopicTableModel::TopicRole)
                                     .isValid(),
                                 20000);
        QVERIFY(named<QLabel>(*page, u"mqttState"_s)->text().contains(u"connected"_s));
        QVERIFY(named<QLabel>(*page, u"rosState"_s)->text().contains(u"reachable"_s));

        // The MQTT topic that mqtt_client announced decodes into fields.
        const QModelIndex pose
            = ViewHelpers::find(page->mqttView()->model(), u"vehicle/pose"_s, MqttTopicTree::FullTopicRole);
        page->mqttView()->setCurrentIndex(pose);
        QTRY_VERIFY(detail->title()->text().contains(u"geometry_msgs/PoseStamped"_s));
        const QStringList fields = fieldNames(named<QTreeView>(*detail, u"fields"_s)->model());
        QVERIFY2(fields.contains(u"pose.position.x"_s), qPrintable(fields.join(u' ')));

        // So does one that mqtt_client for ROS 2 announced; a type without a definition says so.
        page->mqttView()->setCurrentIndex(
            ViewHelpers::find(page->mqttView()->model(), u"ros2/chatter"_s, MqttTopicTree::FullTopicRole));
        QTRY_VERIFY_WITH_TIMEOUT(detail->title()->text().contains(
                                     u"ROS 2 type std_msgs/msg/String (announced by mqtt_client), stamped"_s),
                                 10000);
        QTRY_VERIFY(fieldNames(named<QTreeView>(*detail, u"fields"_s)->model()).contains(u"data"_s));
        QCOMPARE(named<QTreeView>(*detail, u"fields"_s)->model()->index(0, 1).data().toString(),
                 u"hello ros2"_s);
        page->mqttView()->setCurrentIndex(
            ViewHelpers::find(page->mqttView()->model(), u"ros2/state"_s, MqttTopicTree::FullTopicRole));
        QTRY_VERIFY(fieldNames(named<QTreeView>(*detail, u"fields"_s)->model())
                        .join(u' ')
                        .contains(u"No ROS 2 definition of my_pkg/msg/State"_s));
        QVERIFY(
            named<LiveText>(*page, u"counters"_s)->text().contains(u"1 topic(s) of an unknown ROS 2 type"_s));

        // JSON shows as fields too.
        page->mqttView()->setCurrentIndex(ViewHelpers::find(page->mqttView()->model(), u"fleet/car1/status"_s,
                                                            MqttTopicTree::FullTopicRole));
        QTRY_VERIFY(fieldNames(named<QTreeView>(*detail, u"fields"_s)->model()).contains(u"speed"_s));
        QVERIFY(named<QPlainTextEdit>(*detail, u"payload"_s)->toPlainText().contains(u"\"gear\": \"D\""_s));
        // A hostile one shows a bounded number of fields, and says that the rest is not shown.
        QElapsedTimer shown;
        shown.start();
        page->mqttView()->setCurrentIndex(ViewHelpers::find(
            page->mqttView()->model(), u"fleet/hostile/json"_s, MqttTopicTree::FullTopicRole));
        QTRY_VERIFY_WITH_TIMEOUT(
            fieldNames(named<QTreeView>(*detail, u"fields"_s)->model()).contains(u"k0.[0]"_s), 20000);
        const QStringList wideFields = fieldNames(named<QTreeView>(*detail, u"fields"_s)->model());
        QVERIFY2(wideFields.size() <= 5000 + 100, qPrintable(QString::number(wideFields.size())));
        QVERIFY(wideFields.contains(u"…"_s));
        QVERIFY2(shown.elapsed() < 15000, qPrintable(QString::number(shown.elapsed())));

        // Filtering by name keeps the path to a match.
        QTest::keyClicks(named<QLineEdit>(*page, u"mqttFilter"_s), u"car1"_s);
        QTRY_VERIFY(
            !ViewHelpers::find(page->mqttView()->model(), u"vehicle/pose"_s, MqttTopicTree::FullTopicRole)
                 .isValid());
        QVERIFY(
            ViewHelpers::find(page->mqttView()->model(), u"fleet/car1/status"_s, MqttTopicTree::FullTopicRole)
                .isValid());
        named<QLineEdit>(*page, u"mqttFilter"_s)->clear();

        // Monitoring a ROS topic subscribes to it; its last message decodes.
        QAbstractItemModel* ros = named<QTableView>(*page, u"rosTopics"_s)->model();
        const QModelIndex rosPose = ViewHelpers::find(ros, u"/vehicle/pose"_s, TopicTableModel::TopicRole);
        QVERIFY(ros->setData(rosPose.siblingAtColumn(TopicTableModel::MonitorColumn), Qt::Checked,
                             Qt::CheckStateRole));
        named<QTableView>(*page, u"rosTopics"_s)->setCurrentIndex(rosPose);
        QTRY_VERIFY_WITH_TIMEOUT(
            fieldNames(named<QTreeView>(*detail, u"fields"_s)->model()).contains(u"pose.position.x"_s),
            30000);
        QTRY_VERIFY_WITH_TIMEOUT(
            !rosPose.siblingAtColumn(TopicTableModel::RateColumn).data().toString().isEmpty(), 10000);
        QVERIFY(detail->title()->text().contains(u"base_link"_s)
                == false); // fields, not the title, hold values

        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
            // For the docs: a few live topics beside the retained ones.
            MqttConnection fleet;
            fleet.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
            QTRY_VERIFY(fleet.state() == MqttConnection::State::Connected);
            int n = 0;
            QTimer live;
            connect(&live, &QTimer::timeout, [&] {
                ++n;
                for (int car = 1; car <= 4; ++car) {
                    fleet.publish(u"fleet/car%1/speed"_s.arg(car),
                                  QByteArray::number(10 + car + (n % 7) * 0.5));
                    if (n % 5 == 0)
                        fleet.publish(u"fleet/car%1/status"_s.arg(car),
                                      u"{\"speed\": %1, \"gear\": \"D\", \"battery\": %2}"_s.arg(10 + car)
                                          .arg(80 - n % 20)
                                          .toUtf8());
                }
            });
            live.start(100);
            QTest::qWait(3500);
            page->mqttView()->setCurrentIndex(ViewHelpers::find(page->mqttView()->model(), u"vehicle/pose"_s,
                                                                MqttTopicTree::FullTopicRole));
            QTest::qWait(600);
            w.grab().save(dir + u"/discover.png"_s);
        }
    }

    void largeAndBinaryPayloadsShowWithoutFreezing()
    {
        QByteArray big(2 * 1024 * 1024, Qt::Uninitialized);
        for (int i = 0; i < big.size(); ++i)
            big[i] = char((i * 131) & 0xff);
        const QString file = m_servers.tempPath() + u"/big.bin"_s;
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(big);
        f.close();
        MainWindow w;
        DiscoverPage* page = w.discoverPage();
        DetailPane* detail = only<DetailPane>(*page);
        page->connectBroker(MqttProfile::fromUrl(m_servers.brokerUrl()));
        w.show();
        QTRY_VERIFY_WITH_TIMEOUT(named<QLabel>(*page, u"mqttState"_s)->text().contains(u"connected"_s),
                                 10000);
        run(u"mosquitto_pub"_s, pubArgs() + QStringList {u"-t"_s, u"lidar/raw"_s, u"-f"_s, file});
        QTRY_VERIFY_WITH_TIMEOUT(
            ViewHelpers::find(page->mqttView()->model(), u"lidar/raw"_s, MqttTopicTree::FullTopicRole)
                .isValid(),
            10000);
        page->mqttView()->setCurrentIndex(
            ViewHelpers::find(page->mqttView()->model(), u"lidar/raw"_s, MqttTopicTree::FullTopicRole));
        QTRY_VERIFY(named<QLabel>(*detail, u"payloadNote"_s)->text().contains(u"showing the first"_s));
        // Hex, because the bytes are no text; the stored payload is whole.
        QVERIFY(named<QPlainTextEdit>(*detail, u"payload"_s)
                    ->toPlainText()
                    .startsWith(u"00000000  00 83 06 89"_s));
        QCOMPARE(w.session()->mqttTopics()->topicData().history(u"lidar/raw"_s)->back().payload.size(),
                 2 * 1024 * 1024);
    }

    // Issue 11: credentials typed into the URL (and a name copied from it) leave the URL and
    // the name for the user and password fields; the URL shown and stored has none.
    void credentialsTypedIntoTheUrlLeaveIt()
    {
        MqttProfileDialog d(MqttProfile::fromUrl(u"tcp://127.0.0.1:1883"_s));
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        int changed = 0;
        for (QLineEdit* e : d.findChildren<QLineEdit*>()) {
            if (e->text() == u"tcp://127.0.0.1:1883"_s) { // the URL, and the name that defaults to it
                e->selectAll();
                QTest::keyClicks(e, u"tcp://alice:s3cr3t@lab-broker:1883"_s);
                ++changed;
            }
        }
        QCOMPARE(changed, 2);
        d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        QCOMPARE(d.result(), int(QDialog::Accepted));
        const MqttProfile p = d.profile();
        QCOMPARE(p.url, u"tcp://lab-broker:1883"_s);
        QCOMPARE(p.name, u"tcp://lab-broker:1883"_s);
        QCOMPARE(p.username, u"alice"_s);
        QCOMPARE(p.password, u"s3cr3t"_s);
    }
};

QTEST_MAIN(TestDiscoverPage)
#include "tst_discoverpage.moc"
