// SPDX-License-Identifier: MIT
// Issue 45's check end to end: "a link that drops every tenth message shows 10 % loss", through a
// real mosquitto and rosmaster and the `bridgescope watch` process. The test is the bridge here,
// one that loses every tenth message in each direction: it publishes each ROS message of the
// ROS → MQTT link and its copy on MQTT (as mqtt_client forwards it: the ROS serialization), and
// each MQTT message of the MQTT → ROS link and its copy on ROS, skipping one copy in ten. Nothing
// is stamped: the watch has only the two ends' contents to match, and its /metrics must say 10 %.
#include "mqtt/mqttlink.h"
#include "resulttext.h"
#include "ros/rosbytes.h"
#include "ros/rosendpoint.h"
#include "testservers.h"
#include "wire/mqttclientwire.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>
#include <QTimer>
#include <std_msgs/String.h>

using namespace Qt::StringLiterals;

namespace {
const QString kConfig = u"broker:\n  host: 127.0.0.1\n  port: %1\n"
                        u"client:\n  id: lossy_bridge\n"
                        u"bridge:\n  ros2mqtt:\n"
                        u"    - {ros_topic: /l/out, mqtt_topic: l/out}\n"
                        u"  mqtt2ros:\n"
                        u"    - {mqtt_topic: l/in, ros_topic: /l/in}\n"_s;
} // namespace

class TestObservedLoss : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    RosEndpoint m_ros;
    std::unique_ptr<MqttLink> m_mqtt;
    QProcess m_watch;
    quint16 m_metricsPort = 0;
    int m_outPub = -1; ///< the ROS → MQTT link's source
    int m_inPub = -1; ///< the MQTT → ROS link's destination: the "bridge's" copies
    int m_tick = 0;
    QTimer m_timer;

    QByteArray metrics() { return TestServers::httpGet(m_metricsPort, u"/metrics"_s); }

    static double value(const QByteArray& text, const QString& name, const QString& link,
                        const QString& side = {})
    {
        QStringList labels {u"link=\"%1\""_s.arg(link)};
        if (!side.isEmpty())
            labels << u"side=\"%1\""_s.arg(side);
        const double v = TestServers::metricSample(text, name, labels);
        return qIsNaN(v) ? 0 : v; // a counter is made on its first count
    }

    /// One message each way; every tenth copy is not made (a different tenth each way).
    void publish()
    {
        const int i = m_tick++;
        std_msgs::String out;
        out.data = "out " + std::to_string(i);
        const QByteArray outBytes = RosBytes::of(out);
        m_ros.publish(m_outPub, outBytes);
        if (i % 10 != 9)
            m_mqtt->publish(u"l/out"_s, outBytes, 0, false);
        std_msgs::String in;
        in.data = "in " + std::to_string(i);
        const QByteArray inBytes = RosBytes::of(in);
        m_mqtt->publish(u"l/in"_s, inBytes, 0, false);
        if (i % 10 != 4)
            m_ros.publish(m_inPub, inBytes);
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
        QString error;
        QVERIFY2(noted(m_ros.start(u"lossy_bridge"_s, m_servers.rosMasterUri(), {}), &error),
                 qPrintable(error));
        m_mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(m_servers.brokerUrl()));
        QVERIFY2(noted(m_mqtt->connect(5000), &error), qPrintable(error));
        const QString type = QString::fromLatin1(ros::message_traits::DataType<std_msgs::String>::value());
        const QString md5 = QString::fromLatin1(ros::message_traits::MD5Sum<std_msgs::String>::value());
        const QString definition
            = QString::fromLatin1(ros::message_traits::Definition<std_msgs::String>::value());
        m_outPub = noted(m_ros.advertise(u"/l/out"_s, type, md5, definition, 10, false), &error).value_or(-1);
        QVERIFY2(m_outPub >= 0, qPrintable(error));
        m_inPub = noted(m_ros.advertise(u"/l/in"_s, type, md5, definition, 10, false), &error).value_or(-1);
        QVERIFY2(m_inPub >= 0, qPrintable(error));
        // As a sending mqtt_client announces its ROS type, retained.
        QVERIFY(m_mqtt->publish(u"mqtt_client/ros_msg_type/l/in"_s,
                                MqttClientWire::encodeType({md5, type, definition, false}), 0, true));

        const QString config = m_servers.tempPath() + u"/lossy.yaml"_s;
        QFile f(config);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kConfig.arg(m_servers.mosquittoPort()).toUtf8());
        f.close();
        m_metricsPort = TestServers::freePort();
        m_watch.setProcessEnvironment(m_servers.rosEnvironment());
        m_watch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                      {u"watch"_s, config, u"--ros-master"_s, m_servers.rosMasterUri(), u"--metrics"_s,
                       u"127.0.0.1:%1"_s.arg(m_metricsPort)});
        QVERIFY(m_watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(m_metricsPort, 10000));
        connect(&m_timer, &QTimer::timeout, this, &TestObservedLoss::publish);
        m_timer.start(50); // 20 Hz each way
    }

    void cleanupTestCase()
    {
        m_timer.stop();
        if (m_watch.state() != QProcess::NotRunning) {
            m_watch.terminate();
            QVERIFY(m_watch.waitForFinished(10000));
            QCOMPARE(m_watch.exitCode(), 0);
        }
        m_mqtt.reset();
        m_ros.shutdown();
    }

    void everyTenthDroppedIsTenPercentLost()
    {
        const QString out = u"/l/out → l/out"_s;
        const QString in = u"l/in → /l/in"_s;
        // Both ends of both links seen, and the first losses judged (a copy waits 2 s at most).
        const auto flowing = [&] {
            const QByteArray text = metrics();
            for (const QString& link : {out, in})
                if (value(text, u"bridgescope_link_observed_lost_total"_s, link) < 1
                    || value(text, u"bridgescope_link_messages_total"_s, link, u"destination"_s) < 20)
                    return false;
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(flowing(), 30000);
        const QByteArray before = metrics();
        const int from = m_tick;
        QTRY_VERIFY_WITH_TIMEOUT(m_tick - from >= 200, 30000); // 10 s at 20 Hz
        const QByteArray after = metrics();
        for (const QString& link : {out, in}) {
            const auto delta = [&](const QString& name, const QString& side = {}) {
                return value(after, name, link, side) - value(before, name, link, side);
            };
            const double sources = delta(u"bridgescope_link_messages_total"_s, u"source"_s);
            const double lost = delta(u"bridgescope_link_observed_lost_total"_s);
            const QString what = u"%1: %2 lost of %3 gone in; by the counts %4, state %5"_s.arg(link)
                                     .arg(lost)
                                     .arg(sources)
                                     .arg(delta(u"bridgescope_link_lost_total"_s))
                                     .arg(value(after, u"bridgescope_link_state"_s, link));
            qInfo().noquote() << what;
            // Losses are judged 2 s after their message, the counts sampled a quarter second apart:
            // the window's two ends are a message or two out of step, not more.
            QVERIFY2(sources >= 180, qPrintable(what));
            QVERIFY2(qAbs(lost - sources / 10) <= 3, qPrintable(what));
            const double p50 = TestServers::metricSample(after, u"bridgescope_link_observed_seconds"_s,
                                                         {u"link=\"%1\""_s.arg(link), u"quantile=\"0.5\""_s});
            QVERIFY2(!qIsNaN(p50) && qAbs(p50) < 0.1, qPrintable(link + u": p50 "_s + QString::number(p50)));
        }
        // Loss is judged once both ends were heard over a whole window (12 s after the start): then
        // each link is an alert for its 10 % (the Links page's Loss column), an event that says so.
        const auto alerts = [&] {
            const QByteArray text = metrics();
            return value(text, u"bridgescope_link_state"_s, out) == 2
                && value(text, u"bridgescope_link_state"_s, in) == 2;
        };
        QTRY_VERIFY_WITH_TIMEOUT(alerts(), 20000);
        // The watch's summary says the loss by content beside the counts' lower bound.
        m_timer.stop();
        m_watch.terminate();
        QVERIFY(m_watch.waitForFinished(10000));
        QCOMPARE(m_watch.exitCode(), 0);
        const QByteArrayList lines = m_watch.readAllStandardOutput().trimmed().split('\n');
        for (const QString& topic : {u"/l/out"_s, u"/l/in"_s}) {
            QStringList said;
            for (const QByteArray& line : lines) {
                const QJsonObject e = QJsonDocument::fromJson(line).object();
                if (e.value(u"event"_s).toString() == u"start"_s
                    && e.value(u"subject"_s).toString().contains(topic)
                    && e.value(u"reasons"_s).toArray().contains(u"loss"_s))
                    said << QString::number(
                        e.value(u"figures"_s).toObject().value(u"loss_percent"_s).toDouble());
            }
            // One in ten lost of what went in over the window, less the one message its edges may cut.
            QVERIFY2(said.size() == 1 && said[0].toDouble() >= 8 && said[0].toDouble() <= 10.5,
                     qPrintable(topic + u": "_s + said.join(u", "_s)));
        }
        const QJsonObject summary = QJsonDocument::fromJson(lines.last()).object();
        QCOMPARE(summary.value(u"event"_s).toString(), u"summary"_s);
        const double sources = summary.value(u"source_messages"_s).toDouble();
        const double lost = summary.value(u"observed_lost"_s).toDouble();
        // What went in during the last 2 s still waited for its copy when the watch ended: 4 drops
        // each way at 20 Hz, unjudged.
        QVERIFY2(sources > 400 && lost >= sources / 10 - 10 && lost <= sources / 10 + 2,
                 qPrintable(u"%1 lost of %2"_s.arg(lost).arg(sources)));
        QVERIFY(summary.value(u"lost"_s).toDouble() <= lost); // the counts' bound
    }
};

QTEST_GUILESS_MAIN(TestObservedLoss)
#include "tst_observedloss.moc"
