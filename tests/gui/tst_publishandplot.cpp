// SPDX-License-Identifier: MIT
// Publishing from the Discover page and clearing retained messages, against a real mosquitto:
// a separate subscriber (mosquitto_sub) sees exactly what the dialog sent. Field plots in the
// detail pane follow real publishers (MQTT JSON, a ROS node on a real rosmaster, and a ROS 2 node
// on Cyclone DDS, tests/ros2peer).
#include "app/gui/pageparts.h"
#include "fixtures.h"
#include "models/mqtttopictree.h"
#include "resulttext.h"
#include "ros/rosmonitor.h"
#include "ros2peer.h"
#include "session/fieldplotter.h"
#include "session/livesession.h"
#include "testservers.h"
#include "topics/topictablemodel.h"
#include "viewhelpers.h"
#include "widgets/discover/detailpane.h"
#include "widgets/discover/discoverpage.h"
#include "widgets/discover/fieldplotchart.h"
#include "widgets/discover/publishdialog.h"
#include "wire/mqttclientwire.h"
#include "wire/ros2definitions.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

#include <functional>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>

using namespace Qt::StringLiterals;
using ViewHelpers::named;
using ViewHelpers::only;

namespace {
/// One message as a subscriber of its own got it.
struct Received
{
    bool got = false;
    int qos = -1;
    bool retained = false;
    QByteArray payload;
};

/// The y values of a plotted field, oldest first.
QList<double> values(const PlotSeries& s)
{
    QList<double> out;
    for (const QPointF& p : s.points)
        out << p.y();
    return out;
}

/// The values as text, for a failure's message.
QString shown(const QList<double>& values)
{
    QStringList out;
    for (double v : values)
        out << QString::number(v);
    return out.join(u' ');
}

/// The fields view's index of the field at `path`, or an invalid one.
QModelIndex fieldAt(DetailPane* detail, const QStringList& path, const QModelIndex& parent = {})
{
    QAbstractItemModel* m = named<QTreeView>(*detail, u"fields"_s)->model();
    for (int r = 0; r < m->rowCount(parent); ++r) {
        const QModelIndex i = m->index(r, 0, parent);
        if (i.data(DetailPane::FieldPathRole).toStringList() == path)
            return i;
        if (const QModelIndex deeper = fieldAt(detail, path, i); deeper.isValid())
            return deeper;
    }
    return {};
}

/// Picks the field with the Plot action, as a user does from the fields view.
bool plotFromView(DetailPane* detail, const QStringList& path)
{
    const QModelIndex i = fieldAt(detail, path);
    if (!i.isValid())
        return false;
    named<QTreeView>(*detail, u"fields"_s)->setCurrentIndex(i);
    if (!named<QAction>(*detail, u"plotAction"_s)->isEnabled())
        return false;
    const qsizetype before = named<FieldPlotter>(*detail, u"fieldPlotter"_s)->series().size();
    named<QAction>(*detail, u"plotAction"_s)->trigger();
    return named<FieldPlotter>(*detail, u"fieldPlotter"_s)->series().size() == before + 1;
}

/// Answers the next message box with `button`, keeping its text (polls: the box may come late).
void answerNextBox(QMessageBox::StandardButton button, QString* text)
{
    auto* timer = new QTimer;
    QElapsedTimer started;
    started.start();
    QObject::connect(timer, &QTimer::timeout, [timer, button, text, started] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box || started.hasExpired(30000)) {
            timer->stop();
            timer->deleteLater();
        }
        if (box) {
            *text = box->text();
            box->button(button)->click();
        }
    });
    timer->start(20);
}
} // namespace

class TestPublishAndPlot : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;

    QStringList brokerArgs() const
    {
        return {u"-h"_s, u"127.0.0.1"_s, u"-p"_s, QString::number(m_servers.mosquittoPort())};
    }

    void mosquittoPub(const QStringList& args)
    {
        QProcess p;
        p.start(u"mosquitto_pub"_s, brokerArgs() + args);
        QVERIFY(p.waitForFinished(20000));
        QCOMPARE(p.exitCode(), 0);
    }

    /// Subscribes to `topic` at QoS 2 with mosquitto_sub, runs `afterSubscribed` once the broker
    /// acknowledged, and waits up to `seconds` for one message (the GUI keeps running meanwhile).
    Received receiveOne(const QString& topic, int seconds, const std::function<void()>& afterSubscribed = {},
                        bool skipRetained = false)
    {
        QProcess sub;
        // Line-buffered, or its "received SUBACK" would wait in a pipe buffer until it exits.
        sub.start(u"stdbuf"_s,
                  QStringList {u"-oL"_s, u"mosquitto_sub"_s} + brokerArgs()
                      + QStringList {u"-t"_s, topic, u"-q"_s, u"2"_s, u"-C"_s, u"1"_s, u"-W"_s,
                                     QString::number(seconds), u"-d"_s, u"-F"_s, u"MSG %q %r %x"_s}
                      + (skipRetained ? QStringList {u"-R"_s} : QStringList {}));
        QByteArray out;
        QDeadlineTimer subscribed(10000);
        while (!out.contains("SUBACK") && !subscribed.hasExpired()) {
            QTest::qWait(20);
            out += sub.readAllStandardOutput();
        }
        if (!out.contains("SUBACK"))
            qWarning("mosquitto_sub did not subscribe: %s", out.constData());
        if (afterSubscribed)
            afterSubscribed();
        QDeadlineTimer done((seconds + 5) * 1000);
        while (sub.state() != QProcess::NotRunning && !done.hasExpired())
            QTest::qWait(20);
        out += sub.readAllStandardOutput();
        Received r;
        static const QRegularExpression line(u"^MSG (\\d) (\\d) ([0-9a-f]*)$"_s,
                                             QRegularExpression::MultilineOption);
        const QRegularExpressionMatch m = line.match(QString::fromLatin1(out));
        if (m.hasMatch()) {
            r.got = true;
            r.qos = m.captured(1).toInt();
            r.retained = m.captured(2) == u"1"_s;
            r.payload = QByteArray::fromHex(m.captured(3).toLatin1());
        }
        return r;
    }

    /// The Discover page on its own live session, connected to the test broker.
    struct Page
    {
        explicit Page(const QString& brokerUrl)
        {
            page.connectBroker(MqttProfile::fromUrl(brokerUrl));
            page.show();
        }
        LiveSession session;
        DiscoverPage page {PageParts::discover(&session)};
    };

    static QModelIndex topicIndex(DiscoverPage& page, const QString& topic)
    {
        return ViewHelpers::find(page.mqttView()->model(), topic, MqttTopicTree::FullTopicRole);
    }

    /// A page connected to the test broker, showing `topic` once it is there.
    void select(DiscoverPage& page, const QString& topic)
    {
        QTRY_VERIFY_WITH_TIMEOUT(topicIndex(page, topic).isValid(), 15000);
        page.mqttView()->setCurrentIndex(topicIndex(page, topic));
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_servers.startMosquitto());
        QVERIFY(m_servers.startRosMaster());
        m_servers.exportRosEnvironment();
        mosquittoPub({u"-t"_s, u"mqtt_client/ros_msg_type/vehicle/pose"_s, u"-r"_s, u"-f"_s,
                      Fixtures::path(u"mqtt_client/wire/pose.type.bin"_s)});
        mosquittoPub({u"-t"_s, u"vehicle/pose"_s, u"-r"_s, u"-f"_s,
                      Fixtures::path(u"mqtt_client/wire/pose.payload.bin"_s)});
        mosquittoPub({u"-t"_s, u"mqtt_client/ros_msg_type/chat"_s, u"-r"_s, u"-f"_s,
                      Fixtures::path(u"mqtt_client/wire/string_stamped.type.bin"_s)});
        mosquittoPub({u"-t"_s, u"chat"_s, u"-r"_s, u"-f"_s,
                      Fixtures::path(u"mqtt_client/wire/string_stamped.payload.bin"_s)});
        mosquittoPub({u"-t"_s, u"fleet/car1/status"_s, u"-r"_s, u"-m"_s, u"{\"speed\": 12.5}"_s});
    }

    void publishesTextAndJson()
    {
        Page p(m_servers.brokerUrl());
        LiveSession& session = p.session;
        DiscoverPage& page = p.page;
        select(page, u"fleet/car1/status"_s);

        // The button opens the dialog on the selected topic; a JSON payload is shown as JSON.
        page.findChild<QToolButton*>(u"publishTool"_s)->click();
        auto* dialog = page.findChild<PublishDialog*>();
        QVERIFY(dialog);
        QPushButton* publishButton = named<QPushButton>(*dialog, u"publishButton"_s);
        QComboBox* format = named<QComboBox>(*dialog, u"publishFormat"_s);
        QPlainTextEdit* payloadEdit = named<QPlainTextEdit>(*dialog, u"publishPayload"_s);
        QCOMPARE(named<QLineEdit>(*dialog, u"publishTopic"_s)->text(), u"fleet/car1/status"_s);
        QCOMPARE(format->currentIndex(), int(PublishDialog::Json));
        QCOMPARE(payloadEdit->toPlainText(), u"{\"speed\": 12.5}"_s);

        // Text at QoS 1 to a live subscriber.
        named<QLineEdit>(*dialog, u"publishTopic"_s)->setText(u"test/text"_s);
        format->setCurrentIndex(PublishDialog::Text);
        payloadEdit->setPlainText(u"hello, wörld"_s);
        named<QComboBox>(*dialog, u"publishQos"_s)->setCurrentIndex(1);
        Received r = receiveOne(u"test/text"_s, 10, [&] { publishButton->click(); });
        QVERIFY2(r.got, qPrintable(named<QLabel>(*dialog, u"publishStatus"_s)->text()));
        QCOMPARE(r.payload, QByteArray("hello, w\xc3\xb6rld"));
        QCOMPARE(r.qos, 1);
        QCOMPARE(r.retained, false);
        QVERIFY(named<QLabel>(*dialog, u"publishStatus"_s)
                    ->text()
                    .contains(u"published 13 bytes to test/text"_s));

        // JSON, retained at QoS 2: a subscriber that comes later gets it from the broker.
        named<QLineEdit>(*dialog, u"publishTopic"_s)->setText(u"test/json"_s);
        format->setCurrentIndex(PublishDialog::Json);
        payloadEdit->setPlainText(u"{\"a\": [1, 2.5, \"x\"]}"_s);
        named<QComboBox>(*dialog, u"publishQos"_s)->setCurrentIndex(2);
        named<QCheckBox>(*dialog, u"publishRetained"_s)->setChecked(true);
        QVERIFY(dialog->publish());
        QTRY_VERIFY_WITH_TIMEOUT(session.mqttTopics()->topicData().info(u"test/json"_s).has_value(), 10000);
        r = receiveOne(u"test/json"_s, 5);
        QVERIFY(r.got);
        QCOMPARE(r.payload, QByteArray("{\"a\": [1, 2.5, \"x\"]}"));
        QCOMPARE(r.qos, 2);
        QCOMPARE(r.retained, true);

        // Invalid JSON is refused with a message, and nothing reaches the broker.
        named<QLineEdit>(*dialog, u"publishTopic"_s)->setText(u"test/bad"_s);
        named<QCheckBox>(*dialog, u"publishRetained"_s)->setChecked(false);
        format->setCurrentIndex(PublishDialog::Json);
        payloadEdit->setPlainText(u"{\"a\": 1,}"_s);
        r = receiveOne(u"test/bad"_s, 2, [&] { publishButton->click(); });
        QVERIFY(!r.got);
        QVERIFY2(named<QLabel>(*dialog, u"publishStatus"_s)->text().contains(u"Not sent: not JSON"_s),
                 qPrintable(named<QLabel>(*dialog, u"publishStatus"_s)->text()));
        QVERIFY(!session.mqttTopics()->topicData().info(u"test/bad"_s));
    }

    void publishesRosMessagesAsMqttClientDoes()
    {
        Page p(m_servers.brokerUrl());
        LiveSession& session = p.session;
        DiscoverPage& page = p.page;
        select(page, u"vehicle/pose"_s);
        QTRY_VERIFY(session.mqttTopics()->topicData().registryFor(u"vehicle/pose"_s));
        named<QAction>(page, u"publishAction"_s)->trigger();
        auto* dialog = page.findChild<PublishDialog*>();
        QVERIFY(dialog);
        QPushButton* publishButton = named<QPushButton>(*dialog, u"publishButton"_s);
        QComboBox* format = named<QComboBox>(*dialog, u"publishFormat"_s);
        QLabel* status = named<QLabel>(*dialog, u"publishStatus"_s);
        QPlainTextEdit* payloadEdit = named<QPlainTextEdit>(*dialog, u"publishPayload"_s);
        QCOMPARE(format->currentIndex(), int(PublishDialog::RosMessage));
        QVERIFY(format->currentText().contains(u"geometry_msgs/PoseStamped"_s));
        // Prefilled from the captured message (x 1.5, frame "map").
        QString yaml = payloadEdit->toPlainText();
        QVERIFY2(yaml.contains(u"    x: 1.5\n"_s) && yaml.contains(u"frame_id: \"map\""_s), qPrintable(yaml));
        yaml.replace(u"    x: 1.5\n"_s, u"    x: 7.75\n"_s);
        payloadEdit->setPlainText(yaml);
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty())
            dialog->grab().save(dir + u"/publish-dialog.png"_s);

        // Retained is set and the broker keeps one: asked first; cancelled, nothing is sent.
        named<QCheckBox>(*dialog, u"publishRetained"_s)->setChecked(true);
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        Received r = receiveOne(u"vehicle/pose"_s, 3, [&] { QVERIFY(!dialog->publish()); });
        QVERIFY(question.contains(u"retained message for vehicle/pose"_s));
        QCOMPARE(r.payload, Fixtures::read(u"mqtt_client/wire/pose.payload.bin"_s)); // the old one

        named<QCheckBox>(*dialog, u"publishRetained"_s)->setChecked(false);
        r = receiveOne(
            u"vehicle/pose"_s, 10, [&] { publishButton->click(); }, true);
        QVERIFY2(r.got && !r.retained, qPrintable(status->text()));
        const auto info = MqttClientWire::decodeType(Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s));
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(info->name, info->definition));
        QString error;
        const auto value = noted(RosMessageDecoder::decode(reg, info->name, r.payload), &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->find(u"pose.position.x"_s)->value.toDouble(), 7.75);
        QCOMPARE(value->find(u"pose.position.y"_s)->value.toDouble(), -2.25);
        QCOMPARE(value->find(u"header.frame_id"_s)->value.toString(), u"map"_s);
        QCOMPARE(value->find(u"header.stamp"_s)->value.toString(), u"1700000001.000000005"_s);

        // A value that does not fit its field is refused by name.
        yaml.replace(u"seq: 3"_s, u"seq: -3"_s);
        payloadEdit->setPlainText(yaml);
        QVERIFY(!dialog->publish());
        QVERIFY2(status->text().contains(u"header.seq: -3 does not fit uint32"_s),
                 qPrintable(status->text()));

        // A stamped type gets mqtt_client's send stamp before the message.
        named<QLineEdit>(*dialog, u"publishTopic"_s)->setText(u"chat"_s);
        QCOMPARE(format->currentIndex(), int(PublishDialog::RosMessage));
        QCOMPARE(payloadEdit->toPlainText(), u"data: \"hello mqtt\"\n"_s);
        payloadEdit->setPlainText(u"data: ahoy"_s);
        const qint64 before = QDateTime::currentMSecsSinceEpoch();
        r = receiveOne(
            u"chat"_s, 10, [&] { publishButton->click(); }, true);
        const auto split = MqttClientWire::splitStamped(r.payload);
        QVERIFY(split);
        QVERIFY(split->stampNs / 1000000 >= before - 1000 && split->stampNs / 1000000 <= before + 60000);
        QCOMPARE(split->message,
                 QByteArray("\x04\x00\x00\x00"
                            "ahoy",
                            8));
    }

    // mqtt_client for ROS 2: a stamped geometry_msgs/msg/PoseStamped announced in CDR. The dialog
    // offers the type, prefills the last message's values, and sends CDR after a 12-byte CDR stamp,
    // which decodes to what was typed.
    void publishesRos2MessagesAsMqttClientDoes()
    {
        RosMsgTypeInfo type;
        type.name = u"geometry_msgs/msg/PoseStamped"_s;
        type.stamped = true;
        type.dialect = RosTypeRegistry::Dialect::Ros2;
        const RosTypeRegistry registry = Ros2Definitions::registry();
        QString error;
        const auto first = noted(
            RosMessageEncoder::encodeCdr(
                registry, type.name,
                QVariantMap {
                    {u"header"_s, QVariantMap {{u"frame_id"_s, u"odom"_s}}},
                    {u"pose"_s, QVariantMap {{u"position"_s, QVariantMap {{u"x"_s, 2.5}, {u"y"_s, 4}}}}}}),
            &error);
        QVERIFY2(first, qPrintable(error));
        {
            MqttConnection robot;
            robot.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
            QTRY_VERIFY(robot.state() == MqttConnection::State::Connected);
            QVERIFY(robot.publish(u"mqtt_client/ros_msg_type/robot2/pose"_s, MqttClientWire::encodeType(type),
                                  1, true));
            QVERIFY(robot.publish(u"robot2/pose"_s,
                                  MqttClientWire::stamped(1'700'000'000'000'000'000, *first, type.dialect), 1,
                                  true));
            QTest::qWait(300);
        }
        Page p(m_servers.brokerUrl());
        select(p.page, u"robot2/pose"_s);
        QTRY_VERIFY(p.session.mqttTopics()->topicData().registryFor(u"robot2/pose"_s));
        named<QAction>(p.page, u"publishAction"_s)->trigger();
        auto* dialog = p.page.findChild<PublishDialog*>();
        QVERIFY(dialog);
        QComboBox* format = named<QComboBox>(*dialog, u"publishFormat"_s);
        QLabel* status = named<QLabel>(*dialog, u"publishStatus"_s);
        QPlainTextEdit* payloadEdit = named<QPlainTextEdit>(*dialog, u"publishPayload"_s);
        QTRY_COMPARE(format->currentIndex(), int(PublishDialog::RosMessage));
        QVERIFY(format->currentText().contains(type.name));
        QString yaml = payloadEdit->toPlainText();
        QVERIFY2(yaml.contains(u"    x: 2.5\n"_s) && yaml.contains(u"frame_id: \"odom\""_s),
                 qPrintable(yaml));
        yaml.replace(u"    x: 2.5\n"_s, u"    x: -6.125\n"_s);
        payloadEdit->setPlainText(yaml);

        const qint64 before = QDateTime::currentMSecsSinceEpoch();
        const Received r = receiveOne(
            u"robot2/pose"_s, 10, [&] { named<QPushButton>(*dialog, u"publishButton"_s)->click(); }, true);
        QVERIFY2(r.got, qPrintable(status->text()));
        const auto split = MqttClientWire::splitStamped(r.payload, type.dialect);
        QVERIFY(split);
        QVERIFY(r.payload.startsWith(QByteArray("\x00\x01\x00\x00", 4))); // the stamp's own header
        QVERIFY(split->stampNs / 1000000 >= before - 1000 && split->stampNs / 1000000 <= before + 60000);
        const auto value = noted(RosMessageDecoder::decodeCdr(registry, type.name, split->message), &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->find(u"pose.position.x"_s)->value.toDouble(), -6.125);
        QCOMPARE(value->find(u"pose.position.y"_s)->value.toDouble(), 4.0);
        QCOMPARE(value->find(u"header.frame_id"_s)->value.toString(), u"odom"_s);

        // CDR strings end at a NUL: a NUL typed into one is refused by name
        payloadEdit->setPlainText(yaml.replace(u"\"odom\""_s, u"\"od\\0om\""_s));
        QVERIFY(!dialog->publish());
        QVERIFY2(status->text().contains(u"header.frame_id"_s), qPrintable(status->text()));
    }

    void clearsRetainedMessagesAfterAsking()
    {
        mosquittoPub({u"-t"_s, u"keep/a"_s, u"-r"_s, u"-m"_s, u"A"_s});
        mosquittoPub({u"-t"_s, u"keep/b/c"_s, u"-r"_s, u"-m"_s, u"C"_s});
        mosquittoPub({u"-t"_s, u"keep/b/d"_s, u"-r"_s, u"-m"_s, u"D"_s});
        Page p(m_servers.brokerUrl());
        LiveSession& session = p.session;
        DiscoverPage& page = p.page;
        select(page, u"keep/b/d"_s);
        select(page, u"keep/a"_s);

        // Cancelled: the message stays.
        QString question;
        answerNextBox(QMessageBox::Cancel, &question);
        QCOMPARE(page.clearRetained(), 0);
        QVERIFY2(question.contains(u"retained message of keep/a"_s), qPrintable(question));
        Received r = receiveOne(u"keep/a"_s, 3);
        QVERIFY(r.got && r.retained);
        QCOMPARE(r.payload, QByteArray("A"));

        // Accepted (from the key): a fresh subscriber gets nothing.
        answerNextBox(QMessageBox::Yes, &question);
        QApplication::setActiveWindow(&page);
        QVERIFY(QTest::qWaitForWindowActive(&page));
        page.mqttView()->setFocus();
        question.clear();
        QTest::keyClick(page.mqttView(), Qt::Key_Delete);
        QTRY_VERIFY(question.contains(u"retained message of keep/a"_s));
        QTRY_VERIFY_WITH_TIMEOUT(!session.mqttTopics()->topicData().store().mayHoldRetained(u"keep/a"_s),
                                 10000);
        QVERIFY(!receiveOne(u"keep/a"_s, 2).got);

        // A level: both topics under it, counted in the question.
        page.mqttView()->setCurrentIndex(topicIndex(page, u"keep/b"_s));
        answerNextBox(QMessageBox::Yes, &question);
        QCOMPARE(page.clearRetained(), 2);
        QVERIFY2(question.contains(u"2 topics at or under keep/b"_s), qPrintable(question));
        QVERIFY(!receiveOne(u"keep/b/#"_s, 2).got);
    }

    void plotsJsonFieldsOfALivePublisher()
    {
        mosquittoPub(
            {u"-t"_s, u"plot/json"_s, u"-r"_s, u"-m"_s, u"{\"a\": -1, \"v\": [0, -1], \"name\": \"x\"}"_s});
        Page p(m_servers.brokerUrl());
        DetailPane* detail = only<DetailPane>(p.page);
        FieldPlotChart* plotChart = named<FieldPlotChart>(*detail, u"plotChart"_s);
        QListWidget* plotList = named<QListWidget>(*detail, u"plotList"_s);
        select(p.page, u"plot/json"_s);
        QTRY_VERIFY(fieldAt(detail, {u"v"_s, u"[1]"_s}).isValid());
        QVERIFY(!plotFromView(detail, {u"name"_s})); // text is no number
        QVERIFY(plotFromView(detail, {u"a"_s}));
        QVERIFY(plotFromView(detail, {u"v"_s, u"[1]"_s}));

        MqttConnection publisher;
        publisher.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QTRY_VERIFY(publisher.state() == MqttConnection::State::Connected);
        // A new message rebuilds the fields; the one the user is on stays current, ready to plot.
        QVERIFY(publisher.publish(u"plot/json"_s, "{\"a\": -2, \"v\": [0, -2], \"name\": \"x\"}"));
        QTRY_COMPARE(fieldAt(detail, {u"a"_s}).siblingAtColumn(1).data().toString(), u"-2"_s);
        QCOMPARE(named<QTreeView>(*detail, u"fields"_s)
                     ->currentIndex()
                     .data(DetailPane::FieldPathRole)
                     .toStringList(),
                 (QStringList {u"v"_s, u"[1]"_s}));
        QVERIFY(named<QAction>(*detail, u"plotAction"_s)->isEnabled());
        QTRY_COMPARE(named<FieldPlotter>(*detail, u"fieldPlotter"_s)->series()[0].points.size(), 1); // the -2
        named<FieldPlotter>(*detail, u"fieldPlotter"_s)->clear();
        QVERIFY(plotFromView(detail, {u"a"_s}));
        QVERIFY(plotFromView(detail, {u"v"_s, u"[1]"_s}));
        QList<double> as;
        QList<double> vs;
        for (int i = 0; i < 30; ++i) {
            QVERIFY(publisher.publish(u"plot/json"_s,
                                      u"{\"a\": %1, \"v\": [%2, %3], \"name\": \"n\"}"_s.arg(i)
                                          .arg(i * 0.5)
                                          .arg(i * 1.25)
                                          .toUtf8()));
            as << i;
            vs << i * 1.25;
            QTest::qWait(10);
        }
        const FieldPlotter* plotter = named<FieldPlotter>(*detail, u"fieldPlotter"_s);
        QTRY_COMPARE_WITH_TIMEOUT(plotter->series()[1].points.size(), 30, 10000);
        QCOMPARE(values(plotter->series()[0]), as);
        QCOMPARE(values(plotter->series()[1]), vs);
        QCOMPARE(plotter->series()[0].errors, 0u);
        if (const QString dir = qEnvironmentVariable("BRIDGESCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
            detail->findChild<QTabWidget*>()->setCurrentWidget(plotChart->parentWidget());
            p.page.resize(1280, 700);
            QTest::qWait(300);
            p.page.grab().save(dir + u"/field-plot.png"_s);
        }

        // The chart shows the same points, a line per field in colours of its own; at a window's
        // width the legend has room for the whole names.
        p.page.resize(1280, 700);
        detail->findChild<QTabWidget*>()->setCurrentWidget(plotChart->parentWidget());
        const QList<QLineSeries*>& lines = plotChart->lines();
        QCOMPARE(lines.size(), 2);
        QTRY_COMPARE(lines[0]->name(), u"plot/json: a"_s);
        QCOMPARE(lines[1]->name(), u"plot/json: v[1]"_s);
        QCOMPARE(lines[1]->points(), plotter->series()[1].points);
        QVERIFY(lines[0]->color() != lines[1]->color());
        // It follows the next message by itself (once per tick).
        QVERIFY(publisher.publish(u"plot/json"_s, "{\"a\": 30, \"v\": [0, 37.5]}"));
        QTRY_COMPARE(lines[0]->points().size(), 31);
        QCOMPARE(lines[1]->points().last().y(), 37.5);

        // Removed from the list: one line stays.
        plotList->setCurrentRow(0);
        plotList->setFocus();
        for (QPushButton* b : detail->findChildren<QPushButton*>()) {
            if (b->text() == u"Remo&ve"_s)
                b->click();
        }
        QCOMPARE(plotter->series().size(), 1);
        QCOMPARE(plotChart->lines().size(), 1);
        QCOMPARE(plotChart->lines()[0]->name(), u"plot/json: v[1]"_s);
    }

    void plotsRosFieldsOfALivePublisher()
    {
        Page p(m_servers.brokerUrl());
        p.page.setRosMasterUri(m_servers.rosMasterUri());
        DetailPane* detail = only<DetailPane>(p.page);
        p.session.rosMonitor()->monitor(u"/plot/stamps"_s);
        QProcess node;
        node.setProcessEnvironment(m_servers.rosEnvironment());
        node.start(QStringLiteral(STAMP_PUBLISHER),
                   {u"--samples"_s, u"60"_s, u"--rate"_s, u"20"_s, u"--stamp"_s, u"/plot/stamps:0"_s,
                    u"--first-sample"_s, u"1700000000"_s});
        detail->showRosTopic(u"/plot/stamps"_s);
        QTRY_VERIFY_WITH_TIMEOUT(fieldAt(detail, {u"time"_s}).isValid(), 30000);
        QVERIFY(plotFromView(detail, {u"header"_s, u"seq"_s}));
        QVERIFY(plotFromView(detail, {u"time"_s}));
        // Waiting with the event loop running: a blocked GUI thread would get all messages in
        // one tick, and the plot would decimate them.
        QTRY_COMPARE_WITH_TIMEOUT(node.state(), QProcess::NotRunning, 30000);
        QCOMPARE(node.exitCode(), 0);
        const FieldPlotter* plotter = named<FieldPlotter>(*detail, u"fieldPlotter"_s);
        QTRY_VERIFY_WITH_TIMEOUT(
            !plotter->series()[0].points.isEmpty() && plotter->series()[0].points.last().y() == 59, 10000);
        // Every message from the one plotting began, in order: seq, and the time it carries.
        const QList<double> seqs = values(plotter->series()[0]);
        const QList<double> times = values(plotter->series()[1]);
        QVERIFY2(seqs.size() >= 20, qPrintable(shown(seqs)));
        QCOMPARE(times.size(), seqs.size());
        for (int i = 0; i < seqs.size(); ++i) {
            const int seq = 60 - int(seqs.size()) + i;
            QCOMPARE(seqs[i], double(seq));
            QCOMPARE(times[i], rosTimeText(1700000000LL + seq / 20, (seq % 20) * 50000000LL).toDouble());
        }
    }

    // ROS 2: a Cyclone DDS node's PoseStamped (sample N carries position (N, 2N, 0.5)) plotted from
    // the detail pane: every sample from the first plotted one to the last sent, as sent, also
    // after Mon is unticked (the plot keeps its own subscription). A type without a definition
    // counts each sample as a message without a value and says why.
    void plotsRos2FieldsOfALivePeer()
    {
        const int domain = Ros2Peer::freeDomain(181, 199);
        LiveSession session;
        DiscoverPage page(PageParts::discover(&session));
        page.show();
        page.setRos2Options({domain, true});
        page.setRosGraphs(DiscoverPage::RosGraphs::Ros2);
        QVERIFY(session.isRos2Running());
        constexpr int kSamples = 200; // 10 s at 20 Hz: time to discover, monitor and pick fields
        Ros2Peer peer(domain,
                      {u"--node"_s, u"/plot_peer"_s, u"--count"_s, QString::number(kSamples), u"--pub"_s,
                       u"/plot/pose:geometry_msgs/msg/PoseStamped:20"_s, u"--pub"_s,
                       u"/plot/blob:bridgescope_test/msg/Opaque:20"_s});
        QVERIFY2(peer.waitFor(u"ready"_s), qPrintable(peer.errors()));

        TopicTableModel* model = session.ros2Topics();
        QTRY_VERIFY_WITH_TIMEOUT(model->rowOf(u"/plot/pose"_s) >= 0, 15000);
        const QModelIndex monitor = model->index(model->rowOf(u"/plot/pose"_s), TopicTableModel::MonitorColumn);
        QVERIFY(model->setData(monitor, Qt::Checked, Qt::CheckStateRole));
        DetailPane* detail = only<DetailPane>(page);
        QListWidget* plotList = named<QListWidget>(*detail, u"plotList"_s);
        detail->showRos2Topic(u"/plot/pose"_s);
        const QStringList x {u"pose"_s, u"position"_s, u"x"_s};
        const QStringList y {u"pose"_s, u"position"_s, u"y"_s};
        QTRY_VERIFY_WITH_TIMEOUT(fieldAt(detail, y).isValid(), 15000);
        QVERIFY(plotFromView(detail, x));
        QVERIFY(plotFromView(detail, y));
        QVERIFY(named<QLabel>(*detail, u"plotNote"_s)->text().isEmpty());
        // no Ctrl+L on an unknown type's fields (it has none), so straight to the plotter
        QVERIFY(named<FieldPlotter>(*detail, u"fieldPlotter"_s)
                    ->add({PlotField::Source::Ros2, u"/plot/blob"_s, {u"n"_s}}));

        const FieldPlotter* plotter = named<FieldPlotter>(*detail, u"fieldPlotter"_s);
        QTRY_VERIFY_WITH_TIMEOUT(plotter->series()[1].points.size() >= 3, 10000);
        QVERIFY(model->setData(monitor, Qt::Unchecked, Qt::CheckStateRole));
        QVERIFY(!session.ros2()->isMonitored(u"/plot/pose"_s));
        QVERIFY(peer.waitFor(u"sent /plot/pose %1"_s.arg(kSamples), 30000));
        QTRY_VERIFY_WITH_TIMEOUT(!plotter->series()[0].points.isEmpty()
                                     && plotter->series()[0].points.last().y() == kSamples,
                                 10000);

        const QList<double> xs = values(plotter->series()[0]);
        const QList<double> ys = values(plotter->series()[1]);
        QVERIFY2(xs.size() >= 20, qPrintable(shown(xs)));
        QCOMPARE(ys.size(), xs.size());
        for (int i = 0; i < xs.size(); ++i) {
            QCOMPARE(xs[i], double(kSamples - xs.size() + 1 + i)); // none lost, none twice
            QCOMPARE(ys[i], 2 * xs[i]);
            QCOMPARE(plotter->series()[1].points[i].x(), plotter->series()[0].points[i].x());
        }
        QCOMPARE(plotter->series()[0].errors, 0u);
        QCOMPARE(plotter->series()[1].errors, 0u);
        QVERIFY(plotter->mostDecodedInATick() <= FieldPlotter::kMessagesPerTick);

        const PlotSeries& blob = plotter->series()[2];
        QVERIFY(blob.points.isEmpty());
        QVERIFY2(blob.errors >= 20, qPrintable(QString::number(blob.errors)));
        QCOMPARE(blob.lastError, u"no ROS 2 definition of bridgescope_test/msg/Opaque is known"_s);
        QVERIFY2(plotList->item(2)->text().contains(u"no ROS 2 definition"_s),
                 qPrintable(plotList->item(2)->text()));

        // the last field of a topic gone: its subscription ends with it
        named<FieldPlotter>(*detail, u"fieldPlotter"_s)->clear();
        QVERIFY(!session.ros2()->isWatched(u"/plot/pose"_s));
        QVERIFY(!session.ros2()->isWatched(u"/plot/blob"_s));
    }

    // Hostile: a payload too large to plot and a burst of malformed ones are counted, each
    // tick decodes a bounded number, and the plot goes on with the next good value.
    void hostilePayloadsOnAPlottedTopicStayBounded()
    {
        mosquittoPub({u"-t"_s, u"plot/hostile"_s, u"-r"_s, u"-m"_s, u"{\"a\": 1}"_s});
        Page p(m_servers.brokerUrl());
        DetailPane* detail = only<DetailPane>(p.page);
        QListWidget* plotList = named<QListWidget>(*detail, u"plotList"_s);
        select(p.page, u"plot/hostile"_s);
        QTRY_VERIFY(fieldAt(detail, {u"a"_s}).isValid());
        QVERIFY(plotFromView(detail, {u"a"_s}));
        MqttConnection publisher;
        publisher.open(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QTRY_VERIFY(publisher.state() == MqttConnection::State::Connected);
        QByteArray huge(6 * 1024 * 1024, '[');
        QVERIFY(publisher.publish(u"plot/hostile"_s, huge));
        for (int i = 0; i < 2000; ++i)
            QVERIFY(publisher.publish(u"plot/hostile"_s, "{\"a\": [[[" + QByteArray::number(i)));
        QVERIFY(publisher.publish(u"plot/hostile"_s, "{\"a\": 7}"));
        const FieldPlotter* plotter = named<FieldPlotter>(*detail, u"fieldPlotter"_s);
        QTRY_VERIFY_WITH_TIMEOUT(!plotter->series()[0].points.isEmpty(), 20000);
        QCOMPARE(values(plotter->series()[0]), QList<double> {7});
        // Each of the 2001 bad payloads was counted as an error or skipped, never decoded at length.
        QCOMPARE(plotter->series()[0].errors + plotter->skippedMessages(), 2001u);
        QVERIFY(plotter->mostDecodedInATick() <= FieldPlotter::kMessagesPerTick);
        QVERIFY2(plotList->item(0)->text().contains(u"messages without a value"_s),
                 qPrintable(plotList->item(0)->text()));
    }
};

QTEST_MAIN(TestPublishAndPlot)
#include "tst_publishandplot.moc"
