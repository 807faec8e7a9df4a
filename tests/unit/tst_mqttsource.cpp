// SPDX-License-Identifier: MIT
// The broker's topics as a MessageSource: counted monitoring, figures of monitored topics only,
// bounded heads and watched queues that count what they drop, and types from mqtt_client's
// announcements, fed as the live session feeds it (the batch, then the topic tree).
#include "latency/subscriptions.h"
#include "models/mqtttopictree.h"
#include "mqtt/mqttsource.h"
#include "wire/mqttclientwire.h"
#include "wire/ros2definitions.h"
#include "wire/rosmessageencoder.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kStart = 1'700'000'000'000'000'000LL;
constexpr qint64 kMs = 1'000'000;

MqttMessage message(const QString& topic, const QByteArray& payload, qint64 ns, bool retained = false)
{
    MqttMessage m;
    m.topic = topic;
    m.payload = payload;
    m.receivedNs = ns;
    m.retained = retained;
    return m;
}

/// One drain: the source has the batch before the tree, as in LiveSession::drainNow().
void drain(MqttSource& source, MqttTopicTree& tree, std::vector<MqttMessage> batch, qint64 nowNs)
{
    source.add(batch);
    tree.apply(std::move(batch));
    tree.tick(nowNs);
}

const RosMsgTypeInfo kPoint {u"938fa65709584ad8e77d238529be13b8"_s, u"geometry_msgs/PointStamped"_s,
                             u"Header header\ngeometry_msgs/Point point\n"_s, true};
} // namespace

class TestMqttSource : public QObject
{
    Q_OBJECT

private slots:
    void monitoringIsCountedAndGivesFiguresOfMonitoredTopicsOnly()
    {
        MqttTopicTree tree;
        MqttSource source(&tree.topicData());
        QCOMPARE(source.sourceGraph(), SourceGraph::Mqtt);
        source.monitor(u"lab/pose"_s);
        source.monitor(u"lab/pose"_s); // Map health and Watch both
        source.monitor(u"lab/never"_s);
        drain(source, tree,
              {message(MqttClientWire::typeTopicPrefix() + u"lab/pose"_s, MqttClientWire::encodeType(kPoint),
                       kStart, true),
               message(u"lab/other"_s, "x", kStart)},
              kStart);
        std::vector<MqttMessage> batch;
        for (int i = 0; i < 20; ++i)
            batch.push_back(message(u"lab/pose"_s, MqttClientWire::stamped(kStart + i * 100 * kMs, QByteArray(40, 'p')),
                                    kStart + i * 100 * kMs + 3 * kMs));
        drain(source, tree, std::move(batch), kStart + 2000 * kMs);

        QHash<QString, TopicFigures> f = source.figures(kStart + 2000 * kMs);
        QCOMPARE(f.size(), 1); // lab/other is not monitored, lab/never was never seen
        const TopicFigures& pose = f.value(u"lab/pose"_s);
        QCOMPARE(pose.messages, quint64(20));
        QCOMPARE(pose.bytes, quint64(20 * (8 + 40)));
        QCOMPARE(pose.lastSize, 48);
        QCOMPARE(pose.lastNs, kStart + 1903 * kMs);
        QCOMPARE(pose.type, u"geometry_msgs/PointStamped"_s);
        QVERIFY(pose.lastLatencyMs.has_value());
        QVERIFY2(qAbs(*pose.lastLatencyMs - 3) < 0.01, qPrintable(QString::number(*pose.lastLatencyMs)));

        source.unmonitor(u"lab/pose"_s);
        QVERIFY(source.isMonitored(u"lab/pose"_s)); // one user left
        source.unmonitor(u"lab/pose"_s);
        QVERIFY(!source.isMonitored(u"lab/pose"_s));
        source.unmonitor(u"lab/pose"_s); // one too many: nothing to balance, no harm
        QVERIFY(!source.figures(kStart).contains(u"lab/pose"_s));
    }

    void eachUserHoldsItsOwnSubscriptions()
    {
        MqttTopicTree tree;
        MqttSource source(&tree.topicData());
        auto owner = std::make_unique<QObject>(); // what owns the source in a window
        {
            Subscriptions links(&source, owner.get());
            Subscriptions map(&source, owner.get());
            links.holdExactly({u"a"_s, u"b"_s});
            map.holdExactly({u"b"_s});
            QVERIFY(source.isMonitored(u"a"_s) && source.isMonitored(u"b"_s));
            links.holdExactly({u"a"_s}); // the map still wants b
            QVERIFY(source.isMonitored(u"b"_s));
            map.holdExactly({});
            QVERIFY(!source.isMonitored(u"b"_s));
            QVERIFY(source.isMonitored(u"a"_s));
            Subscriptions moved = std::move(links); // the subscriptions go with it
            QCOMPARE(moved.held(), QSet<QString>({u"a"_s}));
            QVERIFY(links.held().isEmpty());
        }
        QVERIFY(!source.isMonitored(u"a"_s)); // destroyed: released
        Subscriptions late(&source, owner.get());
        late.holdExactly({u"c"_s});
        owner.reset(); // the source's owner went first: nothing is asked of it any more
        late.holdExactly({});
        QVERIFY(source.isMonitored(u"c"_s));
    }

    void headsAreBoundedAndCountDropsPerTap()
    {
        MqttTopicTree tree;
        auto source = std::make_unique<MqttSource>(&tree.topicData());
        source->monitor(u"a"_s);
        std::vector<MqttMessage> batch {message(u"a"_s, "short", kStart)};
        source->add(batch); // no tap open: nothing kept
        std::unique_ptr<HeadTap> small = source->openHeadTap(3);
        QVERIFY(small->take().empty());

        std::unique_ptr<HeadTap> large = source->openHeadTap(10);
        batch.clear();
        for (int i = 0; i < 5; ++i)
            batch.push_back(message(u"a"_s, QByteArray(1000, char('0' + i)), kStart + i));
        batch.push_back(message(u"b"_s, "unmonitored", kStart + 9));
        source->add(batch);
        const std::vector<SourceHead> heads = small->take();
        QCOMPARE(heads.size(), std::size_t(3)); // the oldest three: a full buffer drops what comes
        QCOMPARE(small->dropped(), quint64(2));
        for (std::size_t i = 0; i < heads.size(); ++i) {
            QCOMPARE(heads[i].graph, SourceGraph::Mqtt);
            QCOMPARE(heads[i].topic, u"a"_s);
            QCOMPARE(heads[i].size, 1000);
            QCOMPARE(heads[i].head, QByteArray(SourceHead::kHeadBytes, char('0' + i)));
            QCOMPARE(heads[i].receivedNs, kStart + qint64(i));
        }
        // the other consumer got every head: one never takes another's
        QCOMPARE(large->take().size(), std::size_t(5));
        QCOMPARE(large->dropped(), quint64(0));
        QVERIFY(small->take().empty());

        small.reset(); // one consumer closing leaves the other's heads coming
        source->add(batch);
        QCOMPARE(large->take().size(), std::size_t(5));
        source.reset(); // a tap may outlive its source
        QVERIFY(large->take().empty());
        large.reset();
    }

    // Issue 45: a json link's payloads are converted as its ROS 2 type (their key is the CDR's), at
    // most 1 MiB each and 4 MiB of them a drain; what is not converted has no key and is counted.
    void jsonPayloadsAreConvertedWithinTheirBudget()
    {
        MqttTopicTree tree;
        MqttSource source(&tree.topicData());
        const auto types = std::make_shared<const RosTypeRegistry>(Ros2Definitions::registry());
        source.setRos2Registry(types);
        const QString point = u"geometry_msgs/msg/Point"_s;
        source.setJsonTypes({{u"p"_s, point}});
        source.monitor(u"p"_s);
        source.monitor(u"q"_s);
        const std::unique_ptr<HeadTap> heads = source.openHeadTap(100);
        source.add({message(u"p"_s, "{\"x\": 1.5}", kStart), message(u"p"_s, "[1]", kStart + 1),
                    message(u"q"_s, "{\"x\": 1.5}", kStart + 2)});
        std::vector<SourceHead> got = heads->take();
        QCOMPARE(got.size(), std::size_t(3));
        const Result<QByteArray> cdr
            = RosMessageEncoder::encodeCdr(*types, point, QVariantMap {{u"x"_s, 1.5}});
        QVERIFY(cdr.ok());
        QCOMPARE(got[0].jsonKey, std::optional<ContentKey>(ContentKey::of(*cdr)));
        QVERIFY(!got[1].jsonKey); // not an object of the type
        QVERIFY(!got[2].jsonKey); // not a json link's topic
        QCOMPARE(source.jsonUnconverted(), quint64(1));
        // A flood of large JSON: 4 MiB of it converted a drain, the rest skipped and counted.
        QByteArray large = "{\"x\": 2, \"y\": 3, \"z\": 4" + QByteArray(900 * 1024, ' ') + "}";
        std::vector<MqttMessage> flood;
        for (int i = 0; i < 10; ++i)
            flood.push_back(message(u"p"_s, large, kStart + 10 + i));
        source.add(flood);
        got = heads->take();
        QCOMPARE(got.size(), std::size_t(10));
        const auto converted
            = std::count_if(got.cbegin(), got.cend(), [](const SourceHead& h) { return bool(h.jsonKey); });
        QCOMPARE(converted, qint64(MqttSource::kMaxJsonBytesPerBatch / large.size()));
        QCOMPARE(source.jsonOverBudget(), quint64(10 - converted));
        source.add({message(u"p"_s, large, kStart + 30)}); // the next drain has its own budget
        QVERIFY(heads->take().front().jsonKey);
    }

    void watchedTopicsKeepTheNewestWithinTheirBoundsAndTheirType()
    {
        MqttTopicTree tree;
        MqttSource source(&tree.topicData());
        drain(source, tree,
              {message(MqttClientWire::typeTopicPrefix() + u"lab/pose"_s, MqttClientWire::encodeType(kPoint),
                       kStart, true)},
              kStart);
        std::unique_ptr<Tap> tap = source.openTap(u"lab/pose"_s, 4, 100); // four messages, 100 bytes
        std::unique_ptr<Tap> roomy = source.openTap(u"lab/pose"_s, 100, 1000); // another consumer's
        std::vector<MqttMessage> batch;
        for (int i = 0; i < 10; ++i)
            batch.push_back(message(u"lab/pose"_s, QByteArray(30, char('a' + i)), kStart + i));
        source.add(batch);
        const std::vector<SourceArrival> kept = tap->take();
        QCOMPARE(kept.size(), std::size_t(3)); // 4 × 30 bytes is over 100
        QCOMPARE(tap->dropped(), quint64(7));
        // Each tap its own queue and count: the roomier one kept all ten, the bytes shared too.
        const std::vector<SourceArrival> all = roomy->take();
        QCOMPARE(all.size(), std::size_t(10));
        QCOMPARE(roomy->dropped(), quint64(0));
        QCOMPARE(all[9].bytes.constData(), batch[9].payload.constData());
        for (std::size_t i = 0; i < kept.size(); ++i) {
            QCOMPARE(kept[i].graph, SourceGraph::Mqtt);
            QCOMPARE(kept[i].type, u"geometry_msgs/PointStamped"_s);
            QCOMPARE(kept[i].receivedNs, kStart + 7 + qint64(i));
            QCOMPARE(kept[i].bytes, batch[7 + i].payload);
            QCOMPARE(kept[i].bytes.constData(), batch[7 + i].payload.constData()); // shared, not copied
        }
        QVERIFY(tap->take().empty());
        std::unique_ptr<Tap> other = source.openTap(u"lab/other"_s, 4, 100);
        QVERIFY(other->take().empty());
        // Closing one tap leaves the other; a tap that outlives its source takes nothing more.
        tap.reset();
        source.add(batch);
        QCOMPARE(roomy->take().size(), std::size_t(10));
        {
            MqttSource gone(&tree.topicData());
            other = gone.openTap(u"lab/pose"_s, 4, 100);
        }
        QVERIFY(other->take().empty());
        QCOMPARE(other->dropped(), quint64(0));
    }

    // What a peer floods a watched topic with never grows the queue past its bounds.
    void aFloodStaysWithinTheWatchedBounds()
    {
        MqttTopicTree tree;
        MqttSource source(&tree.topicData());
        const std::unique_ptr<Tap> tap = source.openTap(u"flood"_s, 1000, 4 * 1024 * 1024);
        const QByteArray kib(1024, 'x');
        for (int round = 0; round < 20; ++round) {
            std::vector<MqttMessage> batch;
            for (int i = 0; i < 10'000; ++i) {
                QByteArray payload = kib;
                payload[0] = char(i); // each its own bytes, as Paho hands them
                batch.push_back(message(u"flood"_s, payload, kStart + i));
            }
            source.add(batch);
        }
        const std::vector<SourceArrival> kept = tap->take();
        QCOMPARE(kept.size(), std::size_t(1000));
        QCOMPARE(tap->dropped(), quint64(200'000 - 1000));
    }
};

QTEST_GUILESS_MAIN(TestMqttSource)
#include "tst_mqttsource.moc"
