// SPDX-License-Identifier: MIT
// Names and options proposed for new mappings, and health from synthetic discovery data.
#include "config/mappingfactory.h"
#include "models/mqtttopictree.h"
#include "mqtt/mqttsource.h"
#include "ros/rosmasterapi.h"
#include "ros/rosmonitor.h"
#include "ros2/ros2graph.h"
#include "session/discoverylints.h"
#include "session/flowrates.h"
#include "session/mappinghealthevaluator.h"
#include "text/topicnames.h"
#include "wire/mqttclientwire.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
/// The MQTT figures as the Map page takes them: the mappings' topics monitored on the MQTT source,
/// which the live session hands a drain's batch before the topic tree applies it.
QHash<QString, TopicFigures> mqttFigures(MqttTopicTree& tree, const BridgeConfig& cfg,
                                         std::vector<MqttMessage> batch, qint64 nowNs)
{
    MqttSource source(&tree.topicData());
    for (const Mapping& m : cfg.mappings)
        source.monitor(m.mqttTopic());
    source.add(batch);
    tree.apply(std::move(batch));
    return source.figures(nowNs);
}
} // namespace

class TestMappingFactory : public QObject
{
    Q_OBJECT
private slots:
    void mqttNames_data()
    {
        QTest::addColumn<QString>("ros");
        QTest::addColumn<QString>("prefix");
        QTest::addColumn<QString>("mqtt");
        QTest::newRow("leading slash dropped") << u"/lidar/points"_s << QString() << u"lidar/points"_s;
        QTest::newRow("under a prefix") << u"/lidar/points"_s << u"vehicle"_s << u"vehicle/lidar/points"_s;
        QTest::newRow("prefix with slashes") << u"/a"_s << u"/fleet/car1/"_s << u"fleet/car1/a"_s;
        QTest::newRow("private name") << u"~/status"_s << u"car"_s << u"car/status"_s;
    }
    void mqttNames()
    {
        QFETCH(QString, ros);
        QFETCH(QString, prefix);
        QFETCH(QString, mqtt);
        QCOMPARE(MappingFactory::mqttTopicFor(ros, prefix), mqtt);
    }

    void rosNames_data()
    {
        QTest::addColumn<QString>("mqtt");
        QTest::addColumn<QString>("ns");
        QTest::addColumn<QString>("ros");
        QTest::newRow("plain") << u"cloud/objects"_s << QString() << u"/cloud/objects"_s;
        QTest::newRow("namespace") << u"objects"_s << u"/cloud"_s << u"/cloud/objects"_s;
        QTest::newRow("invalid characters")
            << u"plant/temp-sensor 1"_s << u"/"_s << u"/plant/temp_sensor_1"_s;
        QTest::newRow("digit level") << u"fleet/2/speed"_s << QString() << u"/fleet/_2/speed"_s;
        QTest::newRow("empty levels") << u"/a//b"_s << QString() << u"/a/b"_s;
    }
    void rosNames()
    {
        QFETCH(QString, mqtt);
        QFETCH(QString, ns);
        QFETCH(QString, ros);
        const QString name = MappingFactory::rosTopicFor(mqtt, ns);
        QCOMPARE(name, ros);
        QVERIFY(TopicNames::isValidRosName(name, true));
    }

    void optionsFollowWhatDiscoveryKnows()
    {
        MappingFactory::MqttFacts plain {true, QString(), "21.5"};
        MappingFactory::MqttFacts json {true, QString(), "{\"speed\": 3}"};
        MappingFactory::MqttFacts announced {true, u"sensor_msgs/PointCloud2"_s, "\x01\x02"};
        MappingFactory::MqttFacts unseen;

        // A std_msgs primitive to a topic that non-ROS devices read: plain text.
        Mapping m = MappingFactory::ros2mqtt(u"/speed"_s, u"std_msgs/Float64"_s, u"plant/speed"_s, plain,
                                             ConfigLayout::Ros1);
        QCOMPARE(m.value(u"primitive"_s), u"true"_s);
        QVERIFY(!m.isSet(u"ros_type"_s));
        m = MappingFactory::ros2mqtt(u"/speed"_s, u"std_msgs/Float64"_s, u"plant/speed"_s, plain,
                                     ConfigLayout::Ros2);
        QCOMPARE(m.value(u"ros_type"_s), u"std_msgs/msg/Float64"_s);
        // Not primitive: unknown destination, or a message type.
        QVERIFY(
            !MappingFactory::ros2mqtt(u"/speed"_s, u"std_msgs/Float64"_s, u"x"_s, unseen, ConfigLayout::Ros1)
                 .isSet(u"primitive"_s));
        QVERIFY(!MappingFactory::ros2mqtt(u"/p"_s, u"geometry_msgs/Pose"_s, u"x"_s, plain, ConfigLayout::Ros1)
                     .isSet(u"primitive"_s));

        // MQTT to ROS: primitives and JSON from devices; announced types need nothing.
        m = MappingFactory::mqtt2ros(u"plant/temp"_s, plain, u"/temp"_s, ConfigLayout::Ros2);
        QCOMPARE(m.value(u"primitive"_s), u"true"_s);
        QCOMPARE(m.value(u"ros_type"_s), u"std_msgs/msg/Float64"_s);
        m = MappingFactory::mqtt2ros(u"car/status"_s, json, u"/status"_s, ConfigLayout::Ros2);
        QCOMPARE(m.value(u"json"_s), u"true"_s);
        m = MappingFactory::mqtt2ros(u"points"_s, announced, u"/points"_s, ConfigLayout::Ros1);
        QVERIFY(m.block.values.paths() == (QStringList {u"mqtt_topic"_s, u"ros_topic"_s}));
        QCOMPARE(MappingFactory::primitiveTypeOf("true"), u"std_msgs/Bool"_s);
        QCOMPARE(MappingFactory::primitiveTypeOf("42"), u"std_msgs/Int64"_s);
        QCOMPARE(MappingFactory::primitiveTypeOf("hello world"), u"std_msgs/String"_s);
        QCOMPARE(MappingFactory::primitiveTypeOf(QByteArray("\x00\x01", 2)), QString());
    }

    void healthFromDiscovery()
    {
        BridgeConfig cfg;
        const Mapping flowing = Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s);
        const Mapping noBridge = Mapping::create(Direction::Ros2Mqtt, u"/b"_s, u"b"_s);
        const Mapping missing = Mapping::create(Direction::Ros2Mqtt, u"/nothere"_s, u"n"_s);
        const Mapping idle = Mapping::create(Direction::Ros2Mqtt, u"/subonly"_s, u"s"_s);
        const Mapping inFlowing = Mapping::create(Direction::Mqtt2Ros, u"/c"_s, u"c"_s);
        const Mapping inNoBridge = Mapping::create(Direction::Mqtt2Ros, u"/d"_s, u"d"_s);
        const Mapping mismatch = Mapping::create(Direction::Ros2Mqtt, u"/e"_s, u"e"_s);
        cfg.mappings = {flowing, noBridge, missing, idle, inFlowing, inNoBridge, mismatch};

        TopicGraph graph;
        graph.topics = {{u"/a"_s, u"std_msgs/String"_s, {u"/talker"_s}, {u"/mqtt_client"_s}},
                        {u"/b"_s, u"std_msgs/String"_s, {u"/talker"_s}, {}},
                        {u"/c"_s, u"std_msgs/String"_s, {u"/mqtt_client"_s}, {}},
                        {u"/e"_s, u"std_msgs/String"_s, {u"/talker"_s}, {}},
                        {u"/subonly"_s, u"std_msgs/String"_s, {}, {u"/listener"_s}}};
        MqttTopicTree tree;
        const qint64 now = 100'000'000'000LL;
        std::vector<MqttMessage> batch;
        for (const QString& t : {u"a"_s, u"c"_s, u"d"_s, u"e"_s})
            batch.push_back({t, "x", now - 1'000'000'000LL, 0, false});
        RosMsgTypeInfo pose {u"d3812c3cbc69362b77dc0b19b345f8f5"_s, u"geometry_msgs/PoseStamped"_s,
                             u"Header header"_s, false};
        batch.push_back({u"mqtt_client/ros_msg_type/e"_s, MqttClientWire::encodeType(pose), now, 0, true});
        const QHash<QString, TopicFigures> mqtt = mqttFigures(tree, cfg, std::move(batch), now);
        QVERIFY(!mqtt.contains(u"b"_s)); // never published
        MappingHealthEvaluator::Inputs in;
        in.graph = &graph;
        in.rosReachable = true;
        in.mqtt = &mqtt;
        in.mqttConnected = true;
        in.nowNs = now;
        const auto h = MappingHealthEvaluator::evaluate(cfg, in);
        QCOMPARE(h[flowing.id].state, MappingHealth::Healthy);
        QCOMPARE(h[noBridge.id].state, MappingHealth::NoBridge);
        QVERIFY(h[noBridge.id].summary.contains(u"no bridge running"_s));
        QVERIFY(h[noBridge.id].detail.contains(u"nothing arrived"_s));
        QCOMPARE(h[missing.id].state, MappingHealth::Missing);
        QCOMPARE(h[idle.id].state, MappingHealth::Idle);
        QCOMPARE(h[inFlowing.id].state, MappingHealth::Healthy);
        QCOMPARE(h[inNoBridge.id].state, MappingHealth::NoBridge);
        QCOMPARE(h[mismatch.id].state, MappingHealth::TypeMismatch);
        QVERIFY(h[mismatch.id].detail.contains(u"geometry_msgs/PoseStamped"_s));

        // A message older than the window is silence.
        in.nowNs = now + 10'000'000'000LL;
        QCOMPARE(MappingHealthEvaluator::evaluate(cfg, in)[flowing.id].state, MappingHealth::NoBridge);
        QCOMPARE(MappingHealthEvaluator::evaluate(cfg, in)[inFlowing.id].state, MappingHealth::Idle);
        // Without the broker, nothing is claimed.
        in.mqttConnected = false;
        QCOMPARE(MappingHealthEvaluator::evaluate(cfg, in)[flowing.id].state, MappingHealth::Unknown);
        QVERIFY(MappingHealthEvaluator::sameType(u"std_msgs/msg/Bool"_s, u"std_msgs/Bool"_s));
    }

    // Issue 40: Map health showed "10.0 → 10.7 Hz", a destination faster than its source, from
    // rates of two windows: the ROS monitor's five seconds up to its last message and the MQTT
    // tree's last one-second tick (11 messages of a bursty bridge in 1.03 s). Both ends are
    // counted over the same interval now; one message in flight at its edge is the count's
    // resolution, not a faster destination, and more than that is said.
    void healthRatesShareOneWindow()
    {
        BridgeConfig cfg;
        const Mapping out = Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s);
        const Mapping in2 = Mapping::create(Direction::Mqtt2Ros, u"/c"_s, u"c"_s);
        const Mapping extra = Mapping::create(Direction::Ros2Mqtt, u"/e"_s, u"e"_s);
        cfg.mappings = {out, in2, extra};
        TopicGraph graph;
        graph.topics = {{u"/a"_s, u"std_msgs/String"_s, {u"/talker"_s}, {u"/mqtt_client"_s}},
                        {u"/c"_s, u"std_msgs/String"_s, {u"/mqtt_client"_s}, {}},
                        {u"/e"_s, u"std_msgs/String"_s, {u"/talker"_s}, {u"/mqtt_client"_s}}};
        const qint64 t0 = 100'000'000'000LL;
        const auto figures = [](quint64 messages, double rateHz, qint64 lastNs) {
            TopicFigures f;
            f.messages = messages;
            f.rateHz = rateHz;
            f.lastNs = lastNs;
            return f;
        };
        // What the sources said at the end: the rates of their own windows.
        const qint64 now = t0 + 5'000'000'000LL;
        QHash<QString, TopicFigures> ros {{u"/a"_s, figures(100, 10.0, now)},
                                          {u"/c"_s, figures(80, 10.0, now)},
                                          {u"/e"_s, figures(100, 10.0, now)}};
        QHash<QString, TopicFigures> mqtt {{u"a"_s, figures(101, 10.7, now)},
                                           {u"c"_s, figures(80, 10.0, now)},
                                           {u"e"_s, figures(110, 12.0, now)}};
        MappingHealthEvaluator::Inputs in;
        in.graph = &graph;
        in.rosReachable = true;
        in.monitored = &ros;
        in.mqtt = &mqtt;
        in.mqttConnected = true;
        in.nowNs = now;
        // The counts of both ends at two instants five seconds apart.
        FlowRates flows;
        flows.sample(
            t0, {{u"/a"_s, figures(50, 0, t0)}, {u"/c"_s, figures(31, 0, t0)}, {u"/e"_s, figures(50, 0, t0)}},
            {{u"a"_s, figures(50, 0, t0)}, {u"c"_s, figures(30, 0, t0)}, {u"e"_s, figures(50, 0, t0)}});
        flows.sample(now, ros, mqtt);
        in.flows = &flows;
        const auto h = MappingHealthEvaluator::evaluate(cfg, in);
        QCOMPARE(h[out.id].state, MappingHealth::Healthy);
        // 50 published, 51 arrived in the same 5 s: one in flight at the edge.
        QCOMPARE(h[out.id].summary, u"10.0 → 10.0 Hz"_s);
        QVERIFY2(h[out.id].detail.contains(u"Over the same 5.0 s, 50 messages were published on '/a' and 51 "
                                           u"arrived on 'a'."_s),
                 qPrintable(h[out.id].detail));
        // MQTT to ROS: the MQTT side is the source; 49 arrived of 50.
        QCOMPARE(h[in2.id].summary, u"10.0 → 10.0 Hz"_s);
        // More than one message more than published: shown as measured, and said.
        QCOMPARE(h[extra.id].summary, u"10.0 → 12.0 Hz"_s);
        QVERIFY2(h[extra.id].detail.contains(u"something else publish on 'e'"_s),
                 qPrintable(h[extra.id].detail));
        // A destination never reads faster than its source within the count's resolution.
        for (const Mapping& m : cfg.mappings) {
            const QStringList rates = h[m.id].summary.section(u' ', 0, 2).split(u" → "_s);
            QCOMPARE(rates.size(), 2);
            if (m.id != extra.id)
                QVERIFY2(rates[1].toDouble() <= rates[0].toDouble(), qPrintable(h[m.id].summary));
        }

        // Before a second sample there is no common interval.
        FlowRates fresh;
        fresh.sample(now, ros, mqtt);
        QVERIFY(!fresh.flow(u"/a"_s, u"a"_s));
        // A count that went back (a subscription made anew) gives no rate rather than a wrong one.
        FlowRates reset;
        reset.sample(t0, ros, mqtt);
        reset.sample(now, {{u"/a"_s, figures(3, 0, now)}}, {{u"a"_s, figures(3, 0, now)}});
        QVERIFY(!reset.flow(u"/a"_s, u"a"_s));
        // Samples are bounded however often health is asked for, and span the window.
        FlowRates often;
        for (qint64 t = 0; t <= 20'000'000'000LL; t += 50'000'000LL)
            often.sample(t0 + t, {{u"/a"_s, figures(quint64(t / 50'000'000LL), 0, t0 + t)}},
                         {{u"a"_s, figures(quint64(t / 50'000'000LL), 0, t0 + t)}});
        const std::optional<FlowRates::Flow> f = often.flow(u"/a"_s, u"a"_s);
        QVERIFY(f);
        QVERIFY2(f->spanNs >= FlowRates::kWindowNs
                     && f->spanNs <= FlowRates::kWindowNs + FlowRates::kMinStepNs,
                 qPrintable(QString::number(f->spanNs)));
        QCOMPARE(f->rosHz(), 20.0);
        QCOMPARE(f->mqttHz(), 20.0);
    }

    // ROS 2: the QoS mqtt_client v2.5 would use against the endpoints DDS discovery announced.
    void healthChecksRos2Qos()
    {
        BridgeConfig cfg;
        cfg.layout = ConfigLayout::Ros2;
        Mapping autoQos
            = Mapping::create(Direction::Ros2Mqtt, u"/a"_s, u"a"_s); // auto: takes the publisher's
        Mapping reliable = Mapping::create(Direction::Ros2Mqtt, u"/b"_s, u"b"_s);
        reliable.set(u"advanced.ros.qos.reliability"_s, u"reliable"_s);
        Mapping latched = Mapping::create(Direction::Ros2Mqtt, u"/c"_s, u"c"_s);
        latched.set(u"advanced.ros.qos.durability"_s, u"transient_local"_s);
        const Mapping toRos = Mapping::create(Direction::Mqtt2Ros, u"/d"_s, u"d"_s); // system default
        Mapping toRosLatched = Mapping::create(Direction::Mqtt2Ros, u"/e"_s, u"e"_s);
        toRosLatched.set(u"advanced.ros.qos.durability"_s, u"transient_local"_s);
        Mapping substituted = Mapping::create(Direction::Ros2Mqtt, u"/b"_s, u"b2"_s);
        substituted.set(u"advanced.ros.qos.reliability"_s, u"$(arg reliability)"_s);
        cfg.mappings = {autoQos, reliable, latched, toRos, toRosLatched, substituted};

        auto endpoint = [](int n, const QString& topic, bool pub, Ros2Qos::Reliability r,
                           Ros2Qos::Durability d, const QString& node) {
            Ros2Endpoint e;
            e.gid = QByteArray(15, '\1') + char(n);
            e.topic = topic;
            e.type = u"std_msgs/msg/String"_s;
            e.publisher = pub;
            e.qos.reliability = r;
            e.qos.durability = d;
            e.node = node;
            return e;
        };
        const QList<Ros2Endpoint> endpoints {
            endpoint(1, u"/a"_s, true, Ros2Qos::BestEffort, Ros2Qos::Volatile, u"/lidar"_s),
            endpoint(2, u"/b"_s, true, Ros2Qos::BestEffort, Ros2Qos::Volatile, u"/lidar"_s),
            endpoint(3, u"/c"_s, true, Ros2Qos::Reliable, Ros2Qos::Volatile, u"/odom"_s),
            endpoint(4, u"/d"_s, true, Ros2Qos::Reliable, Ros2Qos::Volatile, u"/mqtt_client"_s),
            endpoint(5, u"/d"_s, false, Ros2Qos::Reliable, Ros2Qos::TransientLocal, u"/planner"_s),
            endpoint(6, u"/e"_s, true, Ros2Qos::Reliable, Ros2Qos::TransientLocal, u"/mqtt_client"_s),
            endpoint(7, u"/e"_s, false, Ros2Qos::Reliable, Ros2Qos::TransientLocal, u"/planner"_s)};
        const Ros2Graph ros2 = Ros2Graph::build(endpoints, {}, 3);
        TopicGraph graph;
        for (const Ros2Topic& t : ros2.topics)
            graph.topics.append({t.name, t.type(), {u"/x"_s}, {}});

        MqttTopicTree tree;
        const qint64 now = 100'000'000'000LL;
        std::vector<MqttMessage> batch;
        for (const QString& t : {u"a"_s, u"b"_s, u"c"_s, u"d"_s, u"e"_s, u"b2"_s})
            batch.push_back({t, "x", now - 1'000'000'000LL, 0, false});
        const QHash<QString, TopicFigures> mqtt = mqttFigures(tree, cfg, std::move(batch), now);
        MappingHealthEvaluator::Inputs in;
        in.graph = &graph;
        in.ros2 = &ros2;
        in.rosReachable = true;
        in.mqtt = &mqtt;
        in.mqttConnected = true;
        in.nowNs = now;
        const auto h = MappingHealthEvaluator::evaluate(cfg, in);
        QCOMPARE(h[autoQos.id].state, MappingHealth::Healthy);
        QCOMPARE(h[reliable.id].state, MappingHealth::QosMismatch);
        QVERIFY2(h[reliable.id].detail.contains(u"/lidar publishes best effort, volatile"_s),
                 qPrintable(h[reliable.id].detail));
        QCOMPARE(h[latched.id].state, MappingHealth::QosMismatch);
        QVERIFY2(h[latched.id].detail.contains(u"transient local"_s), qPrintable(h[latched.id].detail));
        QCOMPARE(h[toRos.id].state, MappingHealth::QosMismatch);
        QVERIFY2(h[toRos.id].detail.contains(u"/planner subscribes with reliable, transient local"_s),
                 qPrintable(h[toRos.id].detail));
        QCOMPARE(h[toRosLatched.id].state, MappingHealth::Healthy);
        QCOMPARE(h[substituted.id].state, MappingHealth::Healthy); // not known: not judged

        Ros2Qos q;
        QVERIFY(MappingHealthEvaluator::bridgeQos(toRos, {}, &q));
        QCOMPARE(q.reliability, Ros2Qos::Reliable);
        QCOMPARE(q.durability, Ros2Qos::Volatile);
        QVERIFY(!MappingHealthEvaluator::bridgeQos(substituted, {}, &q));
        // Without the ROS 2 domain, nothing is claimed, and the message says which side.
        in.rosReachable = false;
        QCOMPARE(MappingHealthEvaluator::evaluate(cfg, in)[autoQos.id].summary, u"ROS 2 domain not joined"_s);
    }

    // Issue 45: the traps of mqtt_client's tracker that only the lab shows, one case each, with a
    // case beside it that must not be flagged.
    void discoveryLints()
    {
        BridgeConfig cfg;
        cfg.layout = ConfigLayout::Ros2;
        const Mapping plain = Mapping::create(Direction::Mqtt2Ros, u"/plant/temp"_s, u"plant/temp"_s);
        const Mapping announced
            = Mapping::create(Direction::Mqtt2Ros, u"/cloud/objects"_s, u"cloud/objects"_s);
        Mapping primitive = Mapping::create(Direction::Mqtt2Ros, u"/site/hum"_s, u"site/hum"_s);
        primitive.set(u"primitive"_s, u"true"_s);
        const Mapping twoTypes = Mapping::create(Direction::Ros2Mqtt, u"/mixed"_s, u"mixed"_s);
        Mapping fixedTwoTypes = Mapping::create(Direction::Ros2Mqtt, u"/mixed"_s, u"mixed2"_s);
        fixedTwoTypes.set(u"ros_type"_s, u"std_msgs/msg/String"_s);
        Mapping fixedNobody = Mapping::create(Direction::Ros2Mqtt, u"/odom"_s, u"odom"_s);
        fixedNobody.set(u"ros_type"_s, u"nav_msgs/msg/Path"_s);
        Mapping reliable = Mapping::create(Direction::Ros2Mqtt, u"/scan"_s, u"scan"_s);
        reliable.set(u"advanced.ros.qos.reliability"_s, u"reliable"_s);
        const Mapping autoQos = Mapping::create(Direction::Ros2Mqtt, u"/scan"_s, u"scan2"_s);
        cfg.mappings = {plain, announced, primitive, twoTypes, fixedTwoTypes, fixedNobody, reliable, autoQos};

        auto endpoint = [](int n, const QString& topic, const QString& type, Ros2Qos::Reliability r) {
            Ros2Endpoint e;
            e.gid = QByteArray(15, '\2') + char(n);
            e.topic = topic;
            e.type = type;
            e.qos.reliability = r;
            e.node = u"/n%1"_s.arg(n);
            return e;
        };
        const Ros2Graph ros2
            = Ros2Graph::build({endpoint(1, u"/mixed"_s, u"std_msgs/msg/String"_s, Ros2Qos::Reliable),
                                endpoint(2, u"/mixed"_s, u"std_msgs/msg/Float64"_s, Ros2Qos::Reliable),
                                endpoint(3, u"/odom"_s, u"nav_msgs/msg/Odometry"_s, Ros2Qos::Reliable),
                                endpoint(4, u"/scan"_s, u"sensor_msgs/msg/LaserScan"_s, Ros2Qos::BestEffort)},
                               {}, 2);
        TopicGraph graph;
        for (const Ros2Topic& t : ros2.topics)
            graph.topics.append({t.name, t.type(), {u"/x"_s}, {}});

        MqttTopicTree tree;
        const qint64 now = 100'000'000'000LL;
        std::vector<MqttMessage> batch;
        RosMsgTypeInfo pose {u"d3812c3cbc69362b77dc0b19b345f8f5"_s, u"geometry_msgs/PoseStamped"_s,
                             u"Header header"_s, false};
        batch.push_back(
            {u"mqtt_client/ros_msg_type/cloud/objects"_s, MqttClientWire::encodeType(pose), now, 0, true});
        for (const QString& t : {u"plant/temp"_s, u"cloud/objects"_s, u"site/hum"_s})
            batch.push_back({t, "21.5", now - 1'000'000'000LL, 0, false});
        const QHash<QString, TopicFigures> mqtt = mqttFigures(tree, cfg, std::move(batch), now);
        MappingHealthEvaluator::Inputs in;
        in.graph = &graph;
        in.ros2 = &ros2;
        in.rosReachable = true;
        in.mqtt = &mqtt;
        in.mqttConnected = true;
        in.nowNs = now;

        auto codesOf = [](const QList<Problem>& problems, const Mapping& m) {
            QStringList codes;
            for (const Problem& p : problems)
                if (p.mappingId == m.id)
                    codes << p.code;
            return codes;
        };
        auto find = [](const QList<Problem>& problems, const QString& code, quint64 id) {
            for (const Problem& p : problems)
                if (p.code == code && p.mappingId == id)
                    return p;
            return Problem();
        };
        QList<Problem> lints = DiscoveryLints::check(cfg, in, {});
        // #12, #78: text on a topic mqtt_client reads as ROS messages, with no type announced.
        QCOMPARE(codesOf(lints, plain), QStringList {u"non-ros-publisher"_s});
        const Problem nonRos = find(lints, u"non-ros-publisher"_s, plain.id);
        QCOMPARE(nonRos.severity, Severity::Warning);
        QVERIFY2(nonRos.message.contains(u"#12, #78"_s), qPrintable(nonRos.message));
        QVERIFY2(nonRos.fix.contains(u"primitive: true"_s) && nonRos.fix.contains(u"json: true"_s),
                 qPrintable(nonRos.fix));
        QCOMPARE(codesOf(lints, announced), QStringList()); // mqtt_client's own, announced
        QCOMPARE(codesOf(lints, primitive), QStringList()); // read as text
        // #15, #45: two types on one topic, the bridge takes whichever it meets first.
        QCOMPARE(codesOf(lints, twoTypes), QStringList {u"ros-type-changes"_s});
        QVERIFY2(find(lints, u"ros-type-changes"_s, twoTypes.id).message.contains(u"std_msgs/msg/Float64"_s),
                 qPrintable(find(lints, u"ros-type-changes"_s, twoTypes.id).message));
        QCOMPARE(codesOf(lints, fixedTwoTypes), QStringList()); // ros_type decides
        QCOMPARE(codesOf(lints, fixedNobody), QStringList {u"ros-type-changes"_s});
        QVERIFY(find(lints, u"ros-type-changes"_s, fixedNobody.id).fix.contains(u"nav_msgs/msg/Odometry"_s));
        // #48: a reliable subscription to a best-effort publisher never matches; auto takes its QoS.
        QCOMPARE(codesOf(lints, reliable), QStringList {u"qos-incompatible"_s});
        QVERIFY(
            find(lints, u"qos-incompatible"_s, reliable.id).message.contains(u"/n4 publishes best effort"_s));
        QCOMPARE(codesOf(lints, autoQos), QStringList());
        QVERIFY(std::none_of(lints.cbegin(), lints.cend(),
                             [](const Problem& p) { return p.code == u"fastdds-discovery-server"_s; }));

        // Older releases get fixes they can load: no json before 2.5, no ros_type before 2.3.
        DiscoveryLints::Options old;
        old.target = MqttClientRelease::V2_2;
        lints = DiscoveryLints::check(cfg, in, old);
        const Problem oldNonRos = find(lints, u"non-ros-publisher"_s, plain.id);
        QVERIFY2(!oldNonRos.fix.contains(u"json"_s) && !oldNonRos.fix.contains(u"ros_type"_s),
                 qPrintable(oldNonRos.fix));
        QVERIFY(find(lints, u"ros-type-changes"_s, twoTypes.id).fix.contains(u"2.3"_s));

        // #67: a Fast DDS discovery server in the lab, said once for the file.
        DiscoveryLints::Options server;
        server.discoveryServer = u"127.0.0.1:11811"_s;
        lints = DiscoveryLints::check(cfg, in, server);
        const Problem ds = find(lints, u"fastdds-discovery-server"_s, 0);
        QVERIFY2(ds.message.contains(u"ROS_DISCOVERY_SERVER=127.0.0.1:11811"_s)
                     && ds.message.contains(u"#67"_s),
                 qPrintable(ds.message));
        QVERIFY(ds.fix.contains(u"ROS_SUPER_CLIENT=TRUE"_s));
        BridgeConfig ros1 = cfg;
        ros1.layout = ConfigLayout::Ros1; // mqtt_client's ROS 1 node has no DDS
        QCOMPARE(find(DiscoveryLints::check(ros1, in, server), u"fastdds-discovery-server"_s, 0).code,
                 QString());

        // Nothing is claimed about a side that cannot be seen.
        in.mqttConnected = false;
        QCOMPARE(codesOf(DiscoveryLints::check(cfg, in, {}), plain), QStringList());
    }
};

QTEST_GUILESS_MAIN(TestMappingFactory)
#include "tst_mappingfactory.moc"
