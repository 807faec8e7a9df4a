// SPDX-License-Identifier: MIT
// Both reference bridges (`bridgescope bridge`, ROS 1 on a real rosmaster and ROS 2 on a DDS
// domain), one config and the same traffic through one mosquitto, each in its ROS's wire: a
// primitive and a stamped PoseStamped towards MQTT (with the suite's stamps), a primitive whose
// type flips past the limit, a stamped PoseStamped with stamps and latencies, a stamped payload too
// short for its stamp, and a mapping whose ROS topic cannot be advertised towards ROS. Every
// counter of the two must be the same (BridgeHop forwards for both), and so must the point at
// which the latency is taken: the arrival of the MQTT message, as mqtt_client does.
#include "base/wallclock.h"
#include "messageinbox.h"
#include "mqtt/mqttlink.h"
#include "mqttclientros2.h"
#include "resulttext.h"
#include "ros/rosendpoint.h"
#include "ros/rosmasterapi.h"
#include "ros2/ros2participant.h"
#include "ros2peer.h"
#include "testservers.h"
#include "wire/mqttclientwire.h"
#include "wire/stampcodec.h"

#include <cmath>
#include <cstring>
#include <geometry_msgs/PoseStamped.h>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QtEndian>
#include <QTest>

using namespace Qt::StringLiterals;
using MqttClientRos2::Cdr;

namespace {
/// The mapping config both bridges run (ROS 1 layout; the ROS 2 bridge converts it), its MQTT
/// topics below `prefix` so that each bridge gets its own ROS's wire.
QByteArray config(const QString& prefix)
{
    return QStringLiteral("bridge:\n"
                          "  ros2mqtt:\n"
                          "    - {ros_topic: /hop/words, mqtt_topic: P/words, primitive: true,"
                          " advanced: {ros: {queue_size: 100}}}\n"
                          "    - ros_topic: /hop/pose\n"
                          "      mqtt_topic: P/pose\n"
                          "      inject_timestamp: true\n"
                          "      timestamp_topic_prefix: /ts/hop/pose\n"
                          "      advanced: {ros: {queue_size: 100}}\n"
                          "  mqtt2ros:\n"
                          "    - {mqtt_topic: P/count, ros_topic: /hop/count, primitive: true}\n"
                          "    - mqtt_topic: P/pose_back\n"
                          "      ros_topic: /hop/pose_back\n"
                          "      timestamp_topic_prefix: /ts/hop/pose_back\n"
                          "      advanced: {ros: {queue_size: 100}}\n"
                          "    - {mqtt_topic: P/bad, ros_topic: \"/hop/bad name\", primitive: true}\n")
        .replace(u"P/"_s, prefix + u'/')
        .toUtf8();
}

constexpr int kToMqtt = 5; ///< messages of each ros2mqtt mapping
constexpr qint64 kBaseSeconds = 1'700'000'000; ///< a round's pose has header.stamp kBaseSeconds + round

QByteArray ros1Pose(int round)
{
    geometry_msgs::PoseStamped p;
    p.header.stamp = ros::Time(uint32_t(kBaseSeconds + round), 0);
    p.header.frame_id = "map";
    p.pose.position.x = round;
    p.pose.orientation.w = 1;
    const uint32_t n = ros::serialization::serializationLength(p);
    QByteArray out(qsizetype(n), Qt::Uninitialized);
    ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(out.data()), n);
    ros::serialization::serialize(stream, p);
    return out;
}

RosMsgTypeInfo ros1PoseType()
{
    using M = geometry_msgs::PoseStamped;
    return {QString::fromLatin1(ros::message_traits::MD5Sum<M>::value()),
            QString::fromLatin1(ros::message_traits::DataType<M>::value()),
            QString::fromLatin1(ros::message_traits::Definition<M>::value()), true};
}

QByteArray ros2Pose(int round)
{
    return MqttClientRos2::serialize([&](Cdr& cdr) {
        cdr << int32_t(kBaseSeconds + round) << uint32_t(0) << std::string("map") << double(round) << 0.0
            << 0.0 << 0.0 << 0.0 << 0.0 << 1.0;
    });
}

/// What one bridge let through towards ROS, as its ROS side saw it, by round.
struct Seen
{
    QSet<int> poses; ///< rounds whose pose arrived
    QHash<int, qint64> in; ///< round -> time of its `<prefix>/in` stamp
    QList<double> latencies; ///< seconds, as published on ~/latencies/<topic>

    void pose(qint64 stampSeconds) { poses.insert(int(stampSeconds - kBaseSeconds)); }
    void stampIn(const StampCodec::Decoded& d)
    {
        in.insert(int(d.sampleNs / 1'000'000'000 - kBaseSeconds), d.timeNs);
    }
    bool has(int round) const
    {
        if (!poses.contains(round) || !in.contains(round))
            return false;
        for (const double l : latencies)
            if (std::llround(l) == round)
                return true;
        return false;
    }
};

double float64At(const QByteArray& bytes, qsizetype at)
{
    double v = 0;
    if (bytes.size() >= at + 8)
        std::memcpy(&v, bytes.constData() + at, 8);
    return v;
}

/// The counters `bridge --verbose` prints when it stops: name=value, in its order.
QStringList countersOf(const QString& log)
{
    static const QRegularExpression line(u"counters: (.*)$"_s, QRegularExpression::MultilineOption);
    QString last;
    for (QRegularExpressionMatchIterator it = line.globalMatch(log); it.hasNext();)
        last = it.next().captured(1).trimmed();
    return last.split(u' ', Qt::SkipEmptyParts);
}

qint64 counter(const QStringList& counters, const QString& name)
{
    for (const QString& c : counters)
        if (c.startsWith(name + u'='))
            return c.mid(name.size() + 1).toLongLong();
    return -1;
}
} // namespace

class TestBridgeHop : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    QTemporaryDir m_dir;
    int m_domain = 0;
    std::unique_ptr<MqttLink> m_mqtt;
    MessageInbox m_fromMqtt;
    RosEndpoint m_ros; ///< the test's ROS 1 node
    MessageInbox m_fromRos1;

    std::unique_ptr<QProcess> bridge(int ros, const QStringList& options)
    {
        const QString path = m_dir.filePath(u"ros%1.yaml"_s.arg(ros));
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(config(u"r%1"_s.arg(ros)));
        f.close();
        auto p = std::make_unique<QProcess>();
        QProcessEnvironment env = m_servers.rosEnvironment();
        env.insert(u"QT_LOGGING_RULES"_s, u"bridgescope.bridge.debug=true"_s); // the counters when it stops
        p->setProcessEnvironment(env);
        p->start(QStringLiteral(BRIDGESCOPE_BINARY),
                 QStringList {u"bridge"_s, path, u"--ros"_s, QString::number(ros), u"--broker"_s,
                              m_servers.brokerUrl(), u"--name"_s, u"hop_bridge"_s}
                     + options);
        return p;
    }

    /// Stops `p` with SIGTERM, the rest of its log read into `log`.
    static void stop(QProcess& p, QString& log)
    {
        p.disconnect();
        p.terminate();
        if (!p.waitForFinished(15000))
            p.kill();
        p.waitForFinished(2000);
        log += QString::fromUtf8(p.readAllStandardError());
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
        m_domain = Ros2Peer::freeDomain(200, 230);
        QString error;
        QVERIFY2(noted(m_ros.start(u"hop_test"_s, m_servers.rosMasterUri(), {}), &error), qPrintable(error));
        m_mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(m_servers.brokerUrl()));
        m_mqtt->setMessageHandler(
            [this](const QString& t, const QByteArray& p, qint64) { m_fromMqtt.add(t, p); });
        m_mqtt->addSubscription(u"#"_s, 1);
        QVERIFY2(noted(m_mqtt->connect(5000), &error), qPrintable(error));
    }

    void cleanupTestCase()
    {
        m_mqtt.reset();
        m_ros.shutdown();
    }

    void theSameTrafficGivesTheSameCounters()
    {
        // The ROS sides: what comes back from MQTT, its stamps and latencies.
        QString error;
        for (const QString& t :
             {u"/hop/pose_back"_s, u"/hop_bridge/latencies/hop/pose_back"_s, u"/ts/hop/pose_back/in"_s}) {
            MessageInbox* inbox = &m_fromRos1;
            QVERIFY2(
                noted(m_ros.subscribe(t, 100,
                                      [inbox, t](const RosRawMessage& m, qint64) { inbox->add(t, m.bytes); }),
                      &error),
                qPrintable(error));
        }
        Seen seen1;
        Seen seen2;
        Ros2Participant dds;
        connect(&dds.node(), &Ros2EndpointLink::received, this, [&seen2](const QString& topic, const Ros2Sample& s) {
            if (topic == u"/hop/pose_back"_s && s.bytes.size() >= 8)
                seen2.pose(qFromLittleEndian<qint32>(s.bytes.constData() + 4));
            else if (topic.endsWith(u"/latencies/hop/pose_back"_s) && s.bytes.size() == 12)
                seen2.latencies.append(float64At(s.bytes, 4));
            else if (const auto d = StampCodec::decodeTimeStampedCdr(s.bytes))
                seen2.stampIn(*d);
        });
        dds.node().subscribe(u"/hop/pose_back"_s, u"geometry_msgs/msg/PoseStamped"_s);
        dds.node().subscribe(u"/hop_bridge/latencies/hop/pose_back"_s, u"std_msgs/msg/Float64"_s);
        dds.node().subscribe(u"/ts/hop/pose_back/in"_s, u"benchmarking_suite/msg/TimeStamped"_s);
        QVERIFY2(noted(dds.start({m_domain, true}), &error), qPrintable(error));

        // The announcement for MQTT -> ROS, retained: each bridge takes it when it subscribes, and
        // advertises the topic (nothing is counted for it).
        const QString typeTopic = MqttClientWire::typeTopicPrefix() + u"r%1/pose_back"_s;
        RosMsgTypeInfo ros2Type {QString(), u"geometry_msgs/msg/PoseStamped"_s, QString(), true,
                                 RosTypeRegistry::Dialect::Ros2};
        m_mqtt->publish(typeTopic.arg(1), MqttClientWire::encodeType(ros1PoseType()), 1, true);
        m_mqtt->publish(typeTopic.arg(2), MqttClientWire::encodeType(ros2Type), 1, true);

        auto b1 = bridge(1, {u"--ros-master"_s, m_servers.rosMasterUri()});
        auto b2 = bridge(2, {u"--ros-domain"_s, QString::number(m_domain), u"--ros-localhost-only"_s});
        QString log1;
        QString log2;
        connect(b1.get(), &QProcess::readyReadStandardError, this,
                [&] { log1 += QString::fromUtf8(b1->readAllStandardError()); });
        connect(b2.get(), &QProcess::readyReadStandardError, this,
                [&] { log2 += QString::fromUtf8(b2->readAllStandardError()); });
        QTRY_VERIFY2_WITH_TIMEOUT(log1.contains(u"bridging 5 mapping"_s), qPrintable(log1), 20000);
        QTRY_VERIFY2_WITH_TIMEOUT(log2.contains(u"bridging 5 mapping"_s), qPrintable(log2), 20000);
        const auto ros1Advertised = [this] {
            const Result<TopicGraph> g = RosMasterApi(m_servers.rosMasterUri()).graph(3000);
            const TopicInfo* t = g ? g->topic(u"/hop/pose_back"_s) : nullptr;
            return t && !t->publishers.isEmpty();
        };
        const auto ros2Advertised = [&dds] {
            const Ros2Topic* t = dds.graph().topic(u"/hop/pose_back"_s);
            return t && !t->publishers.isEmpty();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(ros1Advertised(), qPrintable(log1), 15000);
        QTRY_VERIFY2_WITH_TIMEOUT(ros2Advertised(), qPrintable(log2), 15000);

        // ROS -> MQTT: kToMqtt Strings and stamped PoseStampeds each, every one after the bridge's
        // subscription is connected (ROS 1: the publisher sees it; ROS 2: the peer starts once matched).
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/hop_talker"_s, u"--pub"_s, u"/hop/words:std_msgs/msg/String:20"_s,
                         u"--pub"_s, u"/hop/pose:geometry_msgs/msg/PoseStamped:20"_s, u"--count"_s,
                         QString::number(kToMqtt), u"--start-matched"_s, u"--duration"_s, u"120"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        const RosRawMessage hello {
            {}, u"std_msgs/String"_s, u"992ce8a1687cec8c8bd883ec73ca41d1"_s, u"string data\n"_s};
        const RosMsgTypeInfo pose1 = ros1PoseType();
        const int wordsPub
            = noted(m_ros.advertise(u"/hop/words"_s, hello.type, hello.md5, hello.definition, 10, false),
                    &error)
                  .value_or(-1);
        const int posePub
            = noted(m_ros.advertise(u"/hop/pose"_s, pose1.name, pose1.md5, pose1.definition, 10, false),
                    &error)
                  .value_or(-1);
        QVERIFY2(wordsPub >= 0 && posePub >= 0, qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(m_ros.subscriberCount(wordsPub) > 0 && m_ros.subscriberCount(posePub) > 0,
                                 15000);
        for (int i = 1; i <= kToMqtt; ++i) {
            const QByteArray text = "hello " + QByteArray::number(i);
            QByteArray words(4, Qt::Uninitialized);
            qToLittleEndian(quint32(text.size()), words.data());
            m_ros.publish(wordsPub, words + text);
            m_ros.publish(posePub, ros1Pose(i));
            QTRY_VERIFY_WITH_TIMEOUT(
                m_fromMqtt.on(u"r1/words"_s).size() == i && m_fromMqtt.on(u"r1/pose"_s).size() == i, 10000);
        }
        QTRY_VERIFY2_WITH_TIMEOUT(m_fromMqtt.on(u"r2/words"_s).size() == kToMqtt
                                      && m_fromMqtt.on(u"r2/pose"_s).size() == kToMqtt,
                                  qPrintable(talker.lines().join(u'\n') + log2), 20000);

        // MQTT -> ROS, to both bridges alike: a stamped payload shorter than its stamp; a primitive
        // whose type flips with every message (13 changes: more than 10 a minute are refused);
        // messages for a ROS topic no graph takes ("bad name").
        for (const QString& bridge : {u"r1"_s, u"r2"_s}) {
            m_mqtt->publish(bridge + u"/pose_back"_s, "oops", 1, false);
            for (int i = 0; i < 14; ++i)
                m_mqtt->publish(bridge + u"/count"_s, i % 2 ? QByteArray("a") : QByteArray("1"), 1, false);
            for (int i = 0; i < 3; ++i)
                m_mqtt->publish(bridge + u"/bad"_s, "5", 1, false);
        }
        // Then stamped PoseStampeds, a round at a time to both, until a round came through both
        // with its pose, its `in` stamp and its latency. Round r is stamped as sent r seconds ago,
        // so its latency says which round it is.
        QHash<int, qint64> sent;
        int round = 0;
        const auto readRos1 = [&] {
            for (const QByteArray& b : m_fromRos1.on(u"/hop/pose_back"_s))
                if (b.size() >= 8)
                    seen1.pose(qFromLittleEndian<quint32>(b.constData() + 4));
            seen1.latencies.clear();
            for (const QByteArray& b : m_fromRos1.on(u"/hop_bridge/latencies/hop/pose_back"_s))
                seen1.latencies.append(float64At(b, 0));
            for (const QByteArray& b : m_fromRos1.on(u"/ts/hop/pose_back/in"_s))
                if (const auto d = StampCodec::decodeTimeStamped(b))
                    seen1.stampIn(*d);
        };
        bool through = false;
        while (!through && round < 150) {
            ++round;
            const qint64 stampNs = wallClockNs() - round * 1'000'000'000LL;
            sent.insert(round, stampNs);
            m_mqtt->publish(u"r1/pose_back"_s, MqttClientWire::stamped(stampNs, ros1Pose(round)), 1, false);
            m_mqtt->publish(u"r2/pose_back"_s,
                            MqttClientWire::stamped(stampNs, ros2Pose(round), RosTypeRegistry::Dialect::Ros2),
                            1, false);
            through = QTest::qWaitFor(
                [&] {
                    readRos1();
                    return seen1.has(round) && seen2.has(round);
                },
                200);
        }
        QVERIFY2(through,
                 qPrintable(u"ROS 1: %1 poses, %2 latencies; ROS 2: %3 poses, %4 latencies\n"_s
                                .arg(seen1.poses.size())
                                .arg(seen1.latencies.size())
                                .arg(seen2.poses.size())
                                .arg(seen2.latencies.size())
                            + log1 + log2));

        talker.terminate();
        stop(*b1, log1);
        stop(*b2, log2);
        m_mqtt->publish(typeTopic.arg(1), {}, 1, true); // no retained leftovers
        m_mqtt->publish(typeTopic.arg(2), {}, 1, true);
        const QStringList c1 = countersOf(log1);
        const QStringList c2 = countersOf(log2);
        qInfo("ROS 1: %s", qPrintable(c1.join(u' ')));
        qInfo("ROS 2: %s", qPrintable(c2.join(u' ')));
        QVERIFY2(!c1.isEmpty(), qPrintable(log1.right(3000)));
        QCOMPARE(c1, c2);
        // and they are what the traffic asks for
        QCOMPARE(counter(c1, u"to_mqtt"_s), qint64(2 * kToMqtt));
        QCOMPARE(counter(c1, u"to_ros"_s),
                 qint64(round + 12)); // the rounds and the primitive's changes up to 10
        QCOMPARE(counter(c1, u"failed"_s), qint64(1 + 2 + 3)); // too short, two changes refused, the bad name
        for (const QString& zero :
             {u"too_large"_s, u"dropped_to_mqtt"_s, u"dropped_to_ros"_s, u"failed_waiting"_s})
            QCOMPARE(counter(c1, zero), qint64(0));

        // The latency is taken when the MQTT message arrives, the moment of its `in` stamp.
        for (const auto& [name, seen] : {std::pair {"ROS 1", &seen1}, {"ROS 2", &seen2}}) {
            int checked = 0;
            for (const double l : std::as_const(seen->latencies)) {
                const int r = int(std::llround(l));
                if (!seen->in.contains(r))
                    continue;
                const qint64 expected = seen->in.value(r) - sent.value(r);
                QVERIFY2(std::abs(l * 1e9 - double(expected)) < 1000,
                         qPrintable(u"%1 round %2: latency %3 ns, its in stamp %4 ns after the send"_s
                                        .arg(QLatin1String(name))
                                        .arg(r)
                                        .arg(l * 1e9, 0, 'f', 0)
                                        .arg(expected)));
                ++checked;
            }
            QVERIFY2(checked > 0, name);
        }
    }
};

QTEST_GUILESS_MAIN(TestBridgeHop)
#include "tst_bridgehop.moc"
