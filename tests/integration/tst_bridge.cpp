// SPDX-License-Identifier: MIT
// The reference bridge (`bridgescope bridge`) against a real mosquitto and rosmaster: mqtt_client
// v2.2.1's wire format byte for byte (the captured fixtures), announced types and latency topics
// on the receiving side, two bridges carrying std_msgs and sensor_msgs both ways, and the
// suite's timestamp_topic_prefix stamps joining into complete samples.
#include "base/wallclock.h"
#include "bridge/referencebridge.h"
#include "bridgelog.h"
#include "config/configreader.h"
#include "fixtures.h"
#include "latency/latencyengine.h"
#include "messageinbox.h"
#include "mqtt/mqttlink.h"
#include "peakrss.h"
#include "resulttext.h"
#include "ros/rosbytes.h"
#include "ros/rosendpoint.h"
#include "ros/rosmasterapi.h"
#include "signalprocess.h"
#include "testservers.h"
#include "wire/mqttclientwire.h"
#include "wire/stampcodec.h"

#include <atomic>
#include <csignal>
#include <mutex>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <sensor_msgs/PointCloud2.h>

using namespace Qt::StringLiterals;

namespace {
/// Everything that arrives on one side, by topic, newest last, and the types ROS said.
struct Inbox : MessageInbox
{
    QHash<QString, RosRawMessage> rosTypes;
};

template<typename M> RosRawMessage rosMessage(const M& message)
{
    return {RosBytes::of(message), QString::fromLatin1(ros::message_traits::DataType<M>::value()),
            QString::fromLatin1(ros::message_traits::MD5Sum<M>::value()),
            QString::fromLatin1(ros::message_traits::Definition<M>::value())};
}

RosRawMessage fixtureMessage(const QString& name)
{
    const Result<RosMsgTypeInfo> type
        = MqttClientWire::decodeType(Fixtures::read(u"mqtt_client/wire/"_s + name + u".type.bin"_s));
    RosRawMessage m;
    if (!type)
        return m;
    m.type = type->name;
    m.md5 = type->md5;
    m.definition = type->definition;
    m.bytes = Fixtures::read(u"mqtt_client/wire/"_s + name + u".payload.bin"_s);
    if (type->stamped)
        m.bytes = m.bytes.mid(8);
    return m;
}
} // namespace

/// The flood tests' messages, and what a bridge may hold beyond its bound (a message on its way
/// in each library, allocation slack).
constexpr int kFloodBytes = 2 * 1024 * 1024;
constexpr qint64 kSlackBytes = 32LL * 1024 * 1024;

class TestBridge : public QObject
{
    Q_OBJECT
private:
    TestServers m_servers;
    QTemporaryDir m_dir;
    RosEndpoint m_ros; ///< the test's own node: publishes and listens on ROS
    std::unique_ptr<MqttLink> m_mqtt; ///< the test's MQTT client, subscribed to everything
    Inbox m_fromMqtt;
    Inbox m_fromRos;
    std::atomic<int> m_floodArrived {0}; ///< messages on flood/... (counted, not kept)

    /// Starts `bridgescope bridge` on `config`; its log goes to our stderr unless `captureLog`.
    std::unique_ptr<QProcess> bridge(const QByteArray& config, const QString& name, bool captureLog = false,
                                     const QStringList& options = {})
    {
        const QString path = m_dir.filePath(name + u".yaml"_s);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(config);
        f.close();
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(m_servers.rosEnvironment());
        if (!captureLog)
            p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p->start(QStringLiteral(BRIDGESCOPE_BINARY),
                 QStringList {u"bridge"_s, path, u"--broker"_s, m_servers.brokerUrl(), u"--name"_s, name}
                     + options);
        return p;
    }

    void listenRos(const QString& topic)
    {
        QString error;
        Inbox* inbox = &m_fromRos;
        QVERIFY2(noted(m_ros.subscribe(topic, 100,
                                       [inbox, topic](const RosRawMessage& m, qint64) {
                                           std::lock_guard<std::mutex> lock(inbox->mutex);
                                           inbox->messages[topic].append(m.bytes);
                                           inbox->rosTypes[topic] = m;
                                       }),
                       &error),
                 qPrintable(error));
    }

    int advertise(const QString& topic, const RosRawMessage& m)
    {
        QString error;
        const int id
            = noted(m_ros.advertise(topic, m.type, m.md5, m.definition, 10, false), &error).value_or(-1);
        if (id < 0)
            qWarning("%s", qPrintable(error));
        return id;
    }

    /// Publishes until `arrived` holds (connections take a moment), at most 15 s.
    bool publishUntil(const std::function<void()>& publish, const std::function<bool()>& arrived)
    {
        for (int i = 0; i < 150; ++i) {
            publish();
            if (QTest::qWaitFor(arrived, 100))
                return true;
        }
        return false;
    }

    /// Calls `send` for kFloodSeconds (a ms apart), with the broker or a ROS subscriber stopped
    /// (SIGSTOP) meanwhile; the growth of the bridge's peak RSS.
    static qint64 floodWhileStopped(QProcess& bridge, qint64 stoppedPid, const std::function<void()>& send)
    {
        constexpr int kFloodSeconds = 3;
        const qint64 baseline = PeakRss::of(bridge.processId());
        signalProcess(stoppedPid, SIGSTOP);
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < kFloodSeconds * 1000) {
            send();
            QTest::qWait(1);
        }
        const qint64 peak = PeakRss::of(bridge.processId());
        signalProcess(stoppedPid, SIGCONT);
        qInfo("bridge peak RSS %.1f MiB over its baseline of %.1f MiB", double(peak - baseline) / (1 << 20),
              double(baseline) / (1 << 20));
        return peak - baseline;
    }

    /// Stops `p`, which grew by `grown`: within its bound, and it dropped messages one way only.
    static void expectBoundHeld(QProcess& p, qint64 grown, bool towardsMqtt)
    {
        const auto [toMqtt, toRos] = BridgeLog::droppedOf(p);
        QVERIFY2(grown < ReferenceBridge::kDefaultMaxQueuedBytes + kSlackBytes + PeakRss::kSanitizerSlack,
                 qPrintable(u"the bridge grew by %1 MiB"_s.arg(grown >> 20)));
        QVERIFY((towardsMqtt ? toMqtt : toRos) > 0);
        QCOMPARE(towardsMqtt ? toRos : toMqtt, qint64(0));
    }

    static void stopBridge(QProcess& p)
    {
        p.terminate(); // SIGTERM: a clean stop
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(m_servers.startMosquitto(), qPrintable(m_servers.errorString()));
        QVERIFY2(m_servers.startRosMaster(), qPrintable(m_servers.errorString()));
        QString error;
        QVERIFY2(noted(m_ros.start(u"bridge_test"_s, m_servers.rosMasterUri(), {}), &error),
                 qPrintable(error));
        m_mqtt = std::make_unique<MqttLink>(MqttProfile::fromUrl(m_servers.brokerUrl()));
        Inbox* inbox = &m_fromMqtt;
        std::atomic<int>* flood = &m_floodArrived;
        m_mqtt->setMessageHandler([inbox, flood](const QString& t, const QByteArray& p, qint64) {
            if (t.startsWith(u"flood/"_s))
                ++*flood;
            else
                inbox->add(t, p);
        });
        m_mqtt->addSubscription(u"#"_s, 0);
        QVERIFY2(noted(m_mqtt->connect(5000), &error), qPrintable(error));
    }

    void cleanupTestCase()
    {
        m_mqtt.reset();
        m_ros.shutdown();
    }

    // ROS -> MQTT: the bytes mqtt_client v2.2.1 put on the broker, from the same ROS messages.
    void ros2mqttSpeaksMqttClientsWireFormat()
    {
        auto p = bridge(
            "bridge:\n  ros2mqtt:\n"
            "    - {ros_topic: /cap/string_stamped, mqtt_topic: cap/string_stamped, inject_timestamp: true}\n"
            "    - {ros_topic: /cap/header, mqtt_topic: cap/header}\n"
            "    - {ros_topic: /cap/pose, mqtt_topic: cap/pose}\n"
            "    - {ros_topic: /cap/int_primitive, mqtt_topic: cap/int_primitive, primitive: true}\n",
            u"wire_out"_s);
        for (const QString& name : {u"string_stamped"_s, u"header"_s, u"pose"_s}) {
            const RosRawMessage m = fixtureMessage(name);
            QVERIFY(!m.type.isEmpty());
            const int pub = advertise(u"/cap/"_s + name, m);
            const QString topic = u"cap/"_s + name;
            QVERIFY2(publishUntil([&] { m_ros.publish(pub, m.bytes); },
                                  [&] { return !m_fromMqtt.on(topic).isEmpty(); }),
                     qPrintable(name));
            // The retained type announcement, byte for byte.
            const QList<QByteArray> types = m_fromMqtt.on(MqttClientWire::typeTopicPrefix() + topic);
            QVERIFY(!types.isEmpty());
            QCOMPARE(types.last(), Fixtures::read(u"mqtt_client/wire/"_s + name + u".type.bin"_s));
            const QByteArray payload = m_fromMqtt.on(topic).last();
            const QByteArray expected = Fixtures::read(u"mqtt_client/wire/"_s + name + u".payload.bin"_s);
            if (name == u"string_stamped"_s) {
                // Eight bytes of send time (uint32 sec, uint32 nsec LE), then the message.
                QCOMPARE(payload.size(), expected.size());
                QCOMPARE(payload.mid(8), expected.mid(8));
                const Result<MqttClientWire::Stamped> s = MqttClientWire::splitStamped(payload);
                QVERIFY(s);
                QVERIFY(std::abs(s->stampNs - wallClockNs()) < 5'000'000'000LL);
            } else {
                QCOMPARE(payload, expected);
            }
        }
        const RosRawMessage count = PrimitiveText::fromText("42");
        QCOMPARE(count.type, u"std_msgs/Int32"_s);
        const int pub = advertise(u"/cap/int_primitive"_s, count);
        QVERIFY(publishUntil([&] { m_ros.publish(pub, count.bytes); },
                             [&] { return !m_fromMqtt.on(u"cap/int_primitive"_s).isEmpty(); }));
        QCOMPARE(m_fromMqtt.on(u"cap/int_primitive"_s).last(),
                 Fixtures::read(u"mqtt_client/wire/int_primitive.payload.bin"_s));
        QVERIFY(m_fromMqtt.on(MqttClientWire::typeTopicPrefix() + u"cap/int_primitive"_s).isEmpty());
        stopBridge(*p);
    }

    // MQTT -> ROS: the announced type is what the ROS topic carries; stamped topics get latencies.
    void mqtt2rosPublishesTheAnnouncedTypeAndLatencies()
    {
        auto p = bridge("bridge:\n  mqtt2ros:\n"
                        "    - {mqtt_topic: in/pose, ros_topic: /back/pose}\n"
                        "    - {mqtt_topic: in/string, ros_topic: /back/string}\n"
                        "    - {mqtt_topic: in/count, ros_topic: /back/count, primitive: true}\n",
                        u"wire_in"_s);
        listenRos(u"/back/pose"_s);
        listenRos(u"/back/string"_s);
        listenRos(u"/back/count"_s);
        listenRos(u"/wire_in/latencies/back/string"_s);
        const RosRawMessage pose = fixtureMessage(u"pose"_s);
        const RosRawMessage text = fixtureMessage(u"string_stamped"_s);
        m_mqtt->publish(u"mqtt_client/ros_msg_type/in/pose"_s,
                        Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s), 0, true);
        m_mqtt->publish(u"mqtt_client/ros_msg_type/in/string"_s,
                        Fixtures::read(u"mqtt_client/wire/string_stamped.type.bin"_s), 0, true);
        QVERIFY(publishUntil(
            [&] {
                m_mqtt->publish(u"in/pose"_s, pose.bytes, 0, false);
                m_mqtt->publish(u"in/string"_s, MqttClientWire::stamped(wallClockNs(), text.bytes), 0, false);
                m_mqtt->publish(u"in/count"_s, "42", 0, false);
            },
            [&] {
                return !m_fromRos.on(u"/back/pose"_s).isEmpty() && !m_fromRos.on(u"/back/string"_s).isEmpty()
                    && !m_fromRos.on(u"/back/count"_s).isEmpty()
                    && !m_fromRos.on(u"/wire_in/latencies/back/string"_s).isEmpty();
            }));
        QCOMPARE(m_fromRos.on(u"/back/pose"_s).last(), pose.bytes);
        QCOMPARE(m_fromRos.on(u"/back/string"_s).last(), text.bytes); // the stamp is taken off
        {
            std::lock_guard<std::mutex> lock(m_fromRos.mutex);
            QCOMPARE(m_fromRos.rosTypes[u"/back/pose"_s].type, u"geometry_msgs/PoseStamped"_s);
            QCOMPARE(m_fromRos.rosTypes[u"/back/pose"_s].md5, pose.md5);
            QCOMPARE(m_fromRos.rosTypes[u"/back/string"_s].type, u"std_msgs/String"_s);
            QCOMPARE(m_fromRos.rosTypes[u"/back/count"_s].type, u"std_msgs/Int32"_s);
            QCOMPARE(m_fromRos.rosTypes[u"/wire_in/latencies/back/string"_s].type, u"std_msgs/Float64"_s);
        }
        const std::optional<qint64> latency
            = StampCodec::decodeFloat64Seconds(m_fromRos.on(u"/wire_in/latencies/back/string"_s).last());
        QVERIFY(latency);
        QVERIFY2(*latency >= 0 && *latency < 5'000'000'000LL, qPrintable(QString::number(*latency)));
        stopBridge(*p);
    }

    // Two bridges through the broker, both ways, with the suite's stamps at every bridge.
    void twoBridgesCarryBothWaysAndStampEveryHop()
    {
        const QByteArray vehicle = "bridge:\n  ros2mqtt:\n"
                                   "    - ros_topic: /vehicle/cloud\n      mqtt_topic: lab/cloud\n"
                                   "      inject_timestamp: true\n"
                                   "      timestamp_topic_prefix: /ts/vehicle_bridge/cloud\n"
                                   "  mqtt2ros:\n"
                                   "    - {mqtt_topic: lab/reply, ros_topic: /vehicle/reply}\n";
        const QByteArray cloud = "bridge:\n  mqtt2ros:\n"
                                 "    - mqtt_topic: lab/cloud\n      ros_topic: /cloud/cloud\n"
                                 "      timestamp_topic_prefix: /ts/cloud_bridge/cloud\n"
                                 "  ros2mqtt:\n"
                                 "    - {ros_topic: /cloud/reply, mqtt_topic: lab/reply}\n";
        auto v = bridge(vehicle, u"vehicle_bridge"_s);
        auto c = bridge(cloud, u"cloud_bridge"_s);
        const QStringList stampTopics {u"/ts/vehicle_bridge/cloud/in"_s, u"/ts/vehicle_bridge/cloud/out"_s,
                                       u"/ts/cloud_bridge/cloud/in"_s, u"/ts/cloud_bridge/cloud/out"_s};
        LatencyEngine engine(Pipeline(stampTopics, 0));
        std::mutex engineMutex;
        for (const QString& t : stampTopics) {
            QString error;
            QVERIFY2(
                noted(m_ros.subscribe(t, 1000,
                                      [&engine, &engineMutex, t](const RosRawMessage& m, qint64 received) {
                                          const Result<StampCodec::Decoded> d
                                              = StampCodec::decodeTimeStamped(m.bytes);
                                          if (!d)
                                              return;
                                          std::lock_guard<std::mutex> lock(engineMutex);
                                          engine.ingest(StampEvent {t, d->sampleNs, d->timeNs, received});
                                      }),
                      &error),
                qPrintable(error));
        }
        listenRos(u"/cloud/cloud"_s);
        listenRos(u"/vehicle/reply"_s);
        listenRos(u"/cloud_bridge/latencies/cloud/cloud"_s);

        // sensor_msgs/PointCloud2 out, std_msgs/String back.
        sensor_msgs::PointCloud2 scan;
        scan.header.frame_id = "velodyne";
        scan.height = 1;
        scan.width = 1000;
        scan.point_step = 16;
        scan.row_step = 16000;
        scan.data.assign(16000, 7);
        const RosRawMessage reply = PrimitiveText::fromText("objects: 3");
        const int scanPub = advertise(u"/vehicle/cloud"_s, rosMessage(scan));
        const int replyPub = advertise(u"/cloud/reply"_s, reply);
        quint32 seq = 0;
        const auto sendScan = [&] {
            scan.header.seq = ++seq;
            scan.header.stamp = ros::Time(1'700'000'000 + seq, 1000);
            m_ros.publish(scanPub, rosMessage(scan).bytes);
        };
        QVERIFY(publishUntil(
            [&] {
                sendScan();
                m_ros.publish(replyPub, reply.bytes);
            },
            [&] {
                return !m_fromRos.on(u"/cloud/cloud"_s).isEmpty()
                    && !m_fromRos.on(u"/vehicle/reply"_s).isEmpty();
            }));
        // Now 30 more samples at 50 Hz, every hop stamped.
        for (int i = 0; i < 30; ++i) {
            sendScan();
            QTest::qWait(20);
        }
        QVERIFY(QTest::qWaitFor(
            [&] {
                std::lock_guard<std::mutex> lock(engineMutex);
                return engine.samples() >= 30;
            },
            10000));
        {
            std::lock_guard<std::mutex> lock(m_fromRos.mutex);
            QCOMPARE(m_fromRos.rosTypes[u"/cloud/cloud"_s].type, u"sensor_msgs/PointCloud2"_s);
            QCOMPARE(m_fromRos.rosTypes[u"/cloud/cloud"_s].md5,
                     QString::fromLatin1(ros::message_traits::MD5Sum<sensor_msgs::PointCloud2>::value()));
            QCOMPARE(m_fromRos.rosTypes[u"/vehicle/reply"_s].type, u"std_msgs/String"_s);
        }
        scan.header.seq = seq;
        scan.header.stamp = ros::Time(1'700'000'000 + seq, 1000);
        QCOMPARE(m_fromRos.on(u"/cloud/cloud"_s).last(), rosMessage(scan).bytes);
        QCOMPARE(m_fromRos.on(u"/vehicle/reply"_s).last(), reply.bytes);
        QVERIFY(!m_fromRos.on(u"/cloud_bridge/latencies/cloud/cloud"_s).isEmpty());
        {
            std::lock_guard<std::mutex> lock(engineMutex);
            // Samples are keyed by the scan's header stamp at every hop; each stage is a real,
            // positive and small duration on one machine.
            const LatencyStats total = engine.series(engine.totalSeries()).stats();
            QVERIFY(total.count >= 30);
            QVERIFY2(total.min >= 0 && total.max < 2000, qPrintable(QString::number(total.max)));
            QCOMPARE(engine.counters().dropped(), quint64(0));
        }
        stopBridge(*v);
        stopBridge(*c);
    }

    // The config's client settings reach the broker: a bridge that dies leaves its last will.
    void aDeadBridgeLeavesItsLastWill()
    {
        auto p = bridge("client:\n  id: will_bridge\n  last_will:\n    topic: lab/status/will_bridge\n"
                        "    message: gone\n    retained: true\n"
                        "bridge:\n  ros2mqtt:\n    - {ros_topic: /will/x, mqtt_topic: will/x}\n",
                        u"will_bridge"_s, true);
        QString log;
        QVERIFY(QTest::qWaitFor(
            [&] {
                log += QString::fromUtf8(p->readAllStandardError());
                return log.contains(u"bridging 1 mapping"_s);
            },
            10000));
        QVERIFY2(log.contains(u"connected to "_s), qPrintable(log));
        QVERIFY(m_fromMqtt.on(u"lab/status/will_bridge"_s).isEmpty());
        p->kill();
        QVERIFY(p->waitForFinished(5000));
        QVERIFY(
            QTest::qWaitFor([&] { return !m_fromMqtt.on(u"lab/status/will_bridge"_s).isEmpty(); }, 10000));
        QCOMPARE(m_fromMqtt.on(u"lab/status/will_bridge"_s).last(), QByteArray("gone"));
    }

    // Every real config loads (the suite's with its roslaunch argument given), in any layout.
    void loadsEveryFixtureConfig()
    {
        for (const QString& file : Fixtures::bridgeConfigs()) {
            ReferenceBridge b([](const QString&) {});
            ReferenceBridge::Options options;
            options.args.insert(u"qos"_s, u"1"_s);
            QString error;
            const QByteArray yaml = Fixtures::read(file);
            if (ConfigReader::read(yaml).config.mappings.isEmpty()) { // settings only: nothing to run
                QVERIFY(!noted(b.load(yaml, options), &error));
                QVERIFY2(error.contains(u"no mapping"_s), qPrintable(error));
                continue;
            }
            QVERIFY2(noted(b.load(yaml, options), &error), qPrintable(file + u": "_s + error));
            QVERIFY(b.mappingCount() > 0);
        }
    }

    void badConfigsAreRefusedWithAMessage()
    {
        QProcess p;
        const QString path = m_dir.filePath(u"qos.yaml"_s);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("bridge:\n  ros2mqtt:\n    - {ros_topic: /a, mqtt_topic: a, advanced: {mqtt: {qos: $(arg "
                "qos)}}}\n");
        f.close();
        p.start(QStringLiteral(BRIDGESCOPE_BINARY),
                {u"bridge"_s, path, u"--broker"_s, m_servers.brokerUrl()});
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains(u"--arg qos=VALUE"_s));
        p.start(QStringLiteral(BRIDGESCOPE_BINARY), {u"bridge"_s, m_dir.filePath(u"missing.yaml"_s)});
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitCode(), 2);
    }

    /// The type the master lists for `topic`, and who publishes it.
    TopicInfo masterTopic(const QString& topic)
    {
        const Result<TopicGraph> g = RosMasterApi(m_servers.rosMasterUri()).graph(3000);
        const TopicInfo* t = g ? g->topic(topic) : nullptr;
        return t ? *t : TopicInfo();
    }

    // Issue 31: a ROS flood towards a broker that does not read grew the bridge by 80 MB/s to
    // 4.8 GB: Paho queues 100 messages of any size, and keeps two copies of each. Now what Paho
    // holds and what waits for it stay within half the bound, the oldest waiting dropped, counted
    // and logged.
    void aFloodTowardsAStalledBrokerHoldsTheMemoryBound()
    {
        auto p = bridge("bridge:\n  ros2mqtt:\n    - {ros_topic: /flood/out, mqtt_topic: flood/out}\n",
                        u"flood_out"_s, true);
        const RosRawMessage big = PrimitiveText::fromText(QByteArray(kFloodBytes, 'x'));
        const int pub = advertise(u"/flood/out"_s, big);
        m_floodArrived = 0;
        QVERIFY(publishUntil([&] { m_ros.publish(pub, big.bytes); }, [&] { return m_floodArrived > 0; }));
        const qint64 grown
            = floodWhileStopped(*p, m_servers.mosquittoPid(), [&] { m_ros.publish(pub, big.bytes); });
        m_ros.retire(pub);
        expectBoundHeld(*p, grown, true);
    }

    // Issue 31: an MQTT flood towards a ROS subscriber that does not read grew the bridge by
    // queue_size messages of any size (roscpp's queue towards that subscriber). Now what roscpp
    // holds stays within half the bound; the messages beyond are dropped, counted and logged.
    void aFloodTowardsAStalledRosSubscriberHoldsTheMemoryBound()
    {
        auto p = bridge("bridge:\n  mqtt2ros:\n    - mqtt_topic: flood/in\n      ros_topic: /flood/in\n"
                        "      primitive: true\n      advanced: {ros: {queue_size: 1000}}\n",
                        u"flood_in"_s, true);
        QProcess hz; // a real subscriber, stopped while the flood lasts
        QProcessEnvironment env = m_servers.rosEnvironment();
        env.insert(u"PYTHONUNBUFFERED"_s, u"1"_s); // its rates as they come
        hz.setProcessEnvironment(env);
        hz.start(u"/usr/bin/python3"_s, {u"/usr/bin/rostopic"_s, u"hz"_s, u"/flood/in"_s});
        QVERIFY(hz.waitForStarted());
        QByteArray rates;
        QVERIFY(publishUntil([&] { m_mqtt->publish(u"flood/in"_s, "x", 0, false); },
                             [&] { return (rates += hz.readAllStandardOutput()).contains("average rate"); }));
        // The test's own client holds little: a bound of its own, the oldest dropped.
        MqttLink::Options options;
        options.maxQueuedBytes = 16 * 1024 * 1024;
        MqttLink flooder(MqttProfile::fromUrl(m_servers.brokerUrl()), options);
        QString error;
        QVERIFY2(noted(flooder.connect(5000), &error), qPrintable(error));
        const QByteArray big(kFloodBytes, 'x');
        const qint64 grown
            = floodWhileStopped(*p, hz.processId(), [&] { flooder.send(u"flood/in"_s, big, 0, false); });
        hz.kill();
        hz.waitForFinished();
        expectBoundHeld(*p, grown, false);
    }

    // The bound counts what roscpp queues, not the last message a latched topic keeps: one larger
    // than the bound's half would otherwise refuse every message after it.
    void aLatchedBigMessageDoesNotStopTheOnesAfterIt()
    {
        auto p = bridge("bridge:\n  mqtt2ros:\n    - mqtt_topic: latch/in\n      ros_topic: /latch/in\n"
                        "      primitive: true\n      advanced: {ros: {latched: true}}\n",
                        u"latch_in"_s, true, {u"--max-queued-mib"_s, u"8"_s});
        listenRos(u"/latch/in"_s);
        const QByteArray big(6 * 1024 * 1024, 'x');
        const auto arrived = [&](qsizetype size) {
            const QList<QByteArray> got = m_fromRos.on(u"/latch/in"_s);
            return !got.isEmpty() && got.last().size() == size + 4; // a std_msgs/String
        };
        QVERIFY(publishUntil([&] { m_mqtt->publish(u"latch/in"_s, big, 0, false); },
                             [&] { return arrived(big.size()); }));
        QVERIFY(publishUntil([&] { m_mqtt->publish(u"latch/in"_s, "small", 0, false); },
                             [&] { return arrived(5); }));
        stopBridge(*p);
    }

    // Regression (issue 11, crashes 1 and 2): any client on the broker could kill a bridge by
    // announcing another type for a mapped topic, or by sending "hello" after "42" on a primitive
    // one: roscpp refused the second advertisement and the bridge published on the invalid
    // publisher (an abort in a Debug build). Now the old publisher is retired first and the topic
    // is advertised with the new type. (A subscriber keeps the type it first saw, as in roscpp:
    // the new type is checked at the master.)
    void typeChangesFromTheBrokerAreFollowedNotFatal()
    {
        auto p = bridge("bridge:\n  mqtt2ros:\n"
                        "    - {mqtt_topic: evil/in, ros_topic: /evil_in}\n"
                        "    - {mqtt_topic: evil/prim, ros_topic: /evil_prim, primitive: true}\n",
                        u"evil"_s, true);
        listenRos(u"/evil_in"_s);
        const RosRawMessage header = fixtureMessage(u"header"_s);
        m_mqtt->publish(u"mqtt_client/ros_msg_type/evil/in"_s,
                        Fixtures::read(u"mqtt_client/wire/header.type.bin"_s), 0, true);
        QVERIFY(publishUntil([&] { m_mqtt->publish(u"evil/in"_s, header.bytes, 0, false); },
                             [&] { return !m_fromRos.on(u"/evil_in"_s).isEmpty(); }));
        QCOMPARE(m_fromRos.on(u"/evil_in"_s).last(), header.bytes);
        for (const QString& name : {u"pose"_s, u"header"_s, u"pose"_s}) {
            const RosRawMessage m = fixtureMessage(name);
            m_mqtt->publish(u"mqtt_client/ros_msg_type/evil/in"_s,
                            Fixtures::read(u"mqtt_client/wire/"_s + name + u".type.bin"_s), 0, true);
            QVERIFY2(publishUntil([&] { m_mqtt->publish(u"evil/in"_s, m.bytes, 0, false); },
                                  [&] { return masterTopic(u"/evil_in"_s).type == m.type; }),
                     qPrintable(name));
        }
        for (const auto& [text, type] : {std::pair {QByteArray("42"), u"std_msgs/Int32"_s},
                                         {QByteArray("hello"), u"std_msgs/String"_s},
                                         // std::stof: a Float32, as mqtt_client 2.3 makes it
                                         {QByteArray("2.5"), u"std_msgs/Float32"_s},
                                         {QByteArray("TRUE"), u"std_msgs/Bool"_s},
                                         {QByteArray("7"), u"std_msgs/Int32"_s}}) {
            QVERIFY2(publishUntil([&] { m_mqtt->publish(u"evil/prim"_s, text, 0, false); },
                                  [&] { return masterTopic(u"/evil_prim"_s).type == type; }),
                     text.constData());
        }
        QCOMPARE(p->state(), QProcess::Running);
        m_mqtt->publish(u"mqtt_client/ros_msg_type/evil/in"_s, QByteArray(), 0,
                        true); // clears the retained one
        p->terminate();
        QVERIFY(p->waitForFinished(10000));
        QCOMPARE(p->exitStatus(), QProcess::NormalExit);
        QCOMPARE(p->exitCode(), 0);
        const QString log = QString::fromUtf8(p->readAllStandardError());
        QVERIFY2(log.contains(u"the type changed to std_msgs/String"_s), qPrintable(log));
    }

    // Regression (issue 11): after a ROS master restart the bridge never registered again: nodes
    // started (or restarted) after it never found it, 0 messages either way, while it kept
    // counting. Each round restarts the master and then connects anew on both ROS sides, as a
    // restarted node would: a new publisher for the bridge to subscribe to, and a new subscriber
    // process (rostopic) that must learn of the bridge's publication from the new master.
    void aRestartedMasterIsToldAboutTheBridgeAgain()
    {
        auto p
            = bridge("bridge:\n  ros2mqtt:\n    - {ros_topic: /mr/out, mqtt_topic: mr/out, primitive: true}\n"
                     "  mqtt2ros:\n    - {mqtt_topic: mr/in, ros_topic: /mr/in, primitive: true}\n",
                     u"restart"_s, true);
        QString log;
        const auto readLog = [&] { log += QString::fromUtf8(p->readAllStandardError()); };
        const RosRawMessage text = PrimitiveText::fromText("through");
        for (int round = 0; round < 3; ++round) {
            if (round > 0) {
                const quint16 port = m_servers.rosMasterPort();
                m_servers.stopRosMaster();
                QVERIFY2(m_servers.startRosMasterOnPort(port), qPrintable(m_servers.errorString()));
            }
            // ROS -> MQTT through a publisher that did not exist before the restart.
            const int pub = advertise(u"/mr/out"_s, text);
            {
                std::lock_guard<std::mutex> lock(m_fromMqtt.mutex);
                m_fromMqtt.messages.remove(u"mr/out"_s);
            }
            QVERIFY2(publishUntil([&] { m_ros.publish(pub, text.bytes); },
                                  [&] { return !m_fromMqtt.on(u"mr/out"_s).isEmpty(); }),
                     qPrintable(u"round %1 ROS -> MQTT; bridge log:\n"_s.arg(round) + (readLog(), log)));
            m_ros.retire(pub);
            // MQTT -> ROS into a subscriber that did not exist before the restart.
            QProcess echo;
            echo.setProcessEnvironment(m_servers.rosEnvironment());
            echo.start(u"/usr/bin/python3"_s,
                       {u"/usr/bin/rostopic"_s, u"echo"_s, u"-n"_s, u"1"_s, u"/mr/in"_s});
            QVERIFY(echo.waitForStarted());
            const bool arrived = publishUntil([&] { m_mqtt->publish(u"mr/in"_s, "back", 0, false); },
                                              [&] { return echo.state() == QProcess::NotRunning; });
            const QString echoed
                = QString::fromUtf8(echo.readAllStandardOutput() + echo.readAllStandardError());
            if (!arrived) {
                echo.kill();
                echo.waitForFinished();
            }
            readLog();
            QVERIFY2(
                arrived && echoed.contains(u"data: \"back\""_s),
                qPrintable(u"round %1 MQTT -> ROS: "_s.arg(round) + echoed + u"\nbridge log:\n"_s + log));
        }
        QCOMPARE(p->state(), QProcess::Running);
        p->terminate();
        QVERIFY(p->waitForFinished(10000));
        readLog();
        QVERIFY2(log.contains(u"the ROS master was restarted"_s), qPrintable(log));
        QCOMPARE(p->exitCode(), 0);
    }
};

QTEST_GUILESS_MAIN(TestBridge)
#include "tst_bridge.moc"
