// SPDX-License-Identifier: MIT
// The MQTT topic tree: exact counts, subtree sums, bounded history, mqtt_client awareness, and
// batched, consistent model signals.
#include "fixtures.h"
#include "models/mqtttopictree.h"
#include "wire/mqttclientwire.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QtEndian>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
MqttMessage msg(const QString& topic, const QByteArray& payload, bool retained = false,
                qint64 ns = 1'000'000'000, quint8 qos = 0)
{
    MqttMessage m;
    m.topic = topic;
    m.payload = payload;
    m.retained = retained;
    m.receivedNs = ns;
    m.qos = qos;
    return m;
}

// The tree as "path messages" lines, depth first, children in model order.
QStringList dump(const QAbstractItemModel& model, const QModelIndex& parent = {}, int depth = 0)
{
    QStringList out;
    for (int r = 0; r < model.rowCount(parent); ++r) {
        const QModelIndex i = model.index(r, 0, parent);
        out << QString(depth * 2, u' ') + i.data().toString() + u' '
                + model.index(r, MqttTopicTree::MessagesColumn, parent).data().toString();
        out += dump(model, i, depth + 1);
    }
    return out;
}
} // namespace

class TestMqttTopicTree : public QObject
{
    Q_OBJECT
private slots:
    void countsAndSumsAreExact()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"vehicle/lidar/points"_s, QByteArray(100, 'x')));
        batch.push_back(msg(u"vehicle/lidar/points"_s, QByteArray(50, 'x')));
        batch.push_back(msg(u"vehicle/status"_s, "ok", true));
        batch.push_back(msg(u"cloud/objects"_s, "[]", false, 2, 1));
        batch.push_back(msg(u"vehicle"_s, "itself a topic"));
        tree.apply(std::move(batch));
        QCOMPARE(dump(tree),
                 (QStringList {u"vehicle 4"_s, u"  lidar 2"_s, u"    points 2"_s, u"  status 1"_s,
                               u"cloud 1"_s, u"  objects 1"_s}));
        QCOMPARE(tree.topicData().store().topicCount(), 4);
        QCOMPARE(tree.topicData().store().totalMessages(), 5u);
        const auto points = tree.topicData().info(u"vehicle/lidar/points"_s);
        QCOMPARE(points->messages, 2u);
        QCOMPARE(points->bytes, 150u);
        QCOMPARE(points->lastSize, 50);
        QCOMPARE(tree.topicData().info(u"vehicle/status"_s)->retained, true);
        QCOMPARE(tree.topicData().info(u"cloud/objects"_s)->qos, 1);
        QCOMPARE(tree.index(0, MqttTopicTree::BytesColumn).data(MqttTopicTree::SortRole).toULongLong(), 166u);
        QVERIFY(!tree.topicData().info(u"vehicle/lidar"_s)); // a level, not a topic
    }

    void oneInsertPerParentPerBatch()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy inserted(&tree, &QAbstractItemModel::rowsInserted);
        QSignalSpy changed(&tree, &QAbstractItemModel::dataChanged);
        std::vector<MqttMessage> batch;
        for (int i = 0; i < 1000; ++i)
            batch.push_back(msg(u"fleet/car%1/speed"_s.arg(i % 100), QByteArray::number(i)));
        tree.apply(std::move(batch));
        QCOMPARE(inserted.size(), 1); // "fleet" (with its new subtree) under the root
        QCOMPARE(tree.topicData().store().topicCount(), 100);
        inserted.clear();
        changed.clear();
        batch.clear();
        for (int i = 0; i < 1000; ++i)
            batch.push_back(msg(u"fleet/car%1/%2"_s.arg(i % 100).arg(i < 500 ? u"speed"_s : u"fuel"_s), "1"));
        tree.apply(std::move(batch));
        // New "fuel" children: one insert under each car that got one; figures: one signal per parent.
        QCOMPARE(inserted.size(), 100);
        QVERIFY(changed.size() <= 102);
        QCOMPARE(tree.topicData().info(u"fleet/car7/speed"_s)->messages, 15u);
    }

    // MQTT Explorer's habit (issue 33): each topic's last value on its row, one short line; a
    // topic keeps at most kPreviewBytes of it, whatever the payload's size and however long the
    // history is kept.
    void theLastValueShowsAsOneShortLine()
    {
        MqttTopicTree tree;
        tree.setHistoryDepth(1);
        QByteArray json = "{\n  \"speed\": 3.5,\n  \"name\":   \"rover\"\n}";
        QByteArray big = "{\"points\": [" + QByteArray(100000, '1') + "]}";
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"rover/state"_s, json));
        batch.push_back(msg(u"rover/cloud"_s, big));
        batch.push_back(msg(u"rover/raw"_s, QByteArray("\x00\x01\xfe\xff", 4)));
        batch.push_back(msg(u"rover/cleared"_s, QByteArray()));
        tree.apply(std::move(batch));
        const auto value = [&](const QString& topic) {
            return tree.indexOf(topic, MqttTopicTree::ValueColumn).data().toString();
        };
        QCOMPARE(value(u"rover/state"_s), u"{ \"speed\": 3.5, \"name\": \"rover\" }"_s);
        const QString cloud = value(u"rover/cloud"_s);
        QVERIFY2(cloud.size() == MqttTopicTree::kPreviewChars + 1 && cloud.startsWith(u"{\"points\": [111"_s)
                     && cloud.endsWith(u'…'),
                 qPrintable(cloud));
        QCOMPARE(value(u"rover/raw"_s), u"00 01 fe ff"_s);
        QCOMPARE(value(u"rover/cleared"_s), u"(empty)"_s);
        QCOMPARE(tree.indexOf(u"rover"_s, MqttTopicTree::ValueColumn).data().toString(), QString());
        QCOMPARE(tree.headerData(MqttTopicTree::ValueColumn, Qt::Horizontal).toString(), u"Value"_s);
        // The tooltip shows more of it, still bounded.
        const QString tip
            = tree.indexOf(u"rover/cloud"_s, MqttTopicTree::ValueColumn).data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.size() <= MqttTopicTree::kPreviewBytes + 1 && tip.size() > cloud.size(),
                 qPrintable(tip));
        // A new value replaces the last.
        std::vector<MqttMessage> next;
        next.push_back(msg(u"rover/state"_s, "parked"));
        tree.apply(std::move(next));
        QCOMPARE(value(u"rover/state"_s), u"parked"_s);
    }

    void historyIsBoundedAndKeepsPayloadsIntact()
    {
        MqttTopicTree tree;
        tree.setHistoryDepth(5);
        std::vector<MqttMessage> batch;
        for (int i = 0; i < 12; ++i)
            batch.push_back(msg(u"t"_s, QByteArray::number(i), false, i));
        QByteArray big(2 * 1024 * 1024, '\0');
        for (int i = 0; i < big.size(); ++i)
            big[i] = char(i * 7);
        batch.push_back(msg(u"blob"_s, big));
        tree.apply(std::move(batch));
        const auto* h = tree.topicData().history(u"t"_s);
        QCOMPARE(int(h->size()), 5);
        QCOMPARE(h->front().payload, QByteArray("7"));
        QCOMPARE(h->back().payload, QByteArray("11"));
        QCOMPARE(tree.topicData().history(u"blob"_s)->back().payload, big);
        QCOMPARE(tree.topicData().info(u"blob"_s)->lastSize, 2 * 1024 * 1024);
        QCOMPARE(tree.indexOf(u"blob"_s).data(MqttTopicTree::SearchTextRole).toString(), QString());
        QCOMPARE(tree.indexOf(u"t"_s).data(MqttTopicTree::SearchTextRole).toString(), u"11"_s);
    }

    /// 500 topics × 20 payloads of 200 kB passed 2 GB when each topic was bounded alone: the history of
    /// all topics stays within one budget, the oldest payloads of any topic go first, and each is counted.
    void historyOfAllTopicsStaysWithinItsBudget()
    {
        MqttTopicTree tree;
        QCOMPARE(tree.topicData().store().historyBudget(), qint64(64) * 1024 * 1024);
        const QByteArray payload(200 * 1000, 'p'); // shared: the test itself stays small
        qint64 ns = 1;
        for (int round = 0; round < 20; ++round) {
            std::vector<MqttMessage> batch;
            for (int t = 0; t < 500; ++t)
                batch.push_back(msg(u"fleet/v%1/cloud"_s.arg(t), payload, false, ns++));
            tree.apply(std::move(batch));
            QVERIFY2(tree.topicData().store().historyBytes() <= tree.topicData().store().historyBudget(),
                     qPrintable(QString::number(tree.topicData().store().historyBytes())));
        }
        qint64 kept = 0;
        for (int t = 0; t < 500; ++t)
            kept += qint64(tree.topicData().history(u"fleet/v%1/cloud"_s.arg(t))->size());
        const qint64 cost = payload.size() + MqttTopicTree::kHistoryEntryOverhead;
        QCOMPARE(kept, tree.topicData().store().historyBudget() / cost);
        QCOMPARE(tree.topicData().store().evictedPayloads(), quint64(500 * 20 - kept));
        QCOMPARE(tree.topicData().store().historyBytes(), kept * cost);
        // The newest are kept, oldest first gone: the last topics of the last round have theirs.
        QCOMPARE(tree.topicData().history(u"fleet/v499/cloud"_s)->back().receivedNs, ns - 1);
        QVERIFY(tree.topicData().history(u"fleet/v0/cloud"_s)->size() <= 1);
        QCOMPARE(tree.topicData().info(u"fleet/v0/cloud"_s)->messages, quint64(20)); // the counts are whole

        // A smaller budget takes effect with the next message; tiny payloads pay their bookkeeping.
        tree.setHistoryBudget(1024 * 1024);
        std::vector<MqttMessage> many;
        for (int i = 0; i < 100000; ++i)
            many.push_back(msg(u"tiny/%1"_s.arg(i % 5000), "x", false, ns++));
        tree.apply(std::move(many));
        QVERIFY(tree.topicData().store().historyBytes() <= 1024 * 1024);
        QVERIFY(tree.topicData().store().evictedPayloads() > quint64(500 * 20 - kept));
        tree.clear();
        QCOMPARE(tree.topicData().store().historyBytes(), qint64(0));
        QCOMPARE(tree.topicData().store().evictedPayloads(), quint64(0));
    }

    /// A client publishing to 10,000 made-up topics cost a watch 180 MiB, with long names 460 MiB:
    /// the tree keeps at most 20,000 topics and 64 MiB of levels; past them a new topic is not
    /// added, its messages are counted, and the topics kept go on updating.
    void topicsStayWithinTheirBudgets()
    {
        MqttTopicTree tree;
        QCOMPARE(tree.topicData().store().topicBudget(), 20000);
        QCOMPARE(tree.topicData().store().structureBudget(), qint64(64) * 1024 * 1024);
        qint64 ns = 1;
        for (int round = 0; round < 5; ++round) {
            std::vector<MqttMessage> batch;
            for (int t = 0; t < 5000; ++t)
                batch.push_back(msg(u"made/up/%1"_s.arg(round * 5000 + t), "x", false, ns++));
            tree.apply(std::move(batch));
        }
        QCOMPARE(tree.topicData().store().topicCount(), 20000);
        QCOMPARE(tree.topicData().store().untrackedMessages(), quint64(5000));
        QVERIFY(tree.topicData().store().structureBytes() <= tree.topicData().store().structureBudget());
        std::vector<MqttMessage> more;
        more.push_back(msg(u"made/up/0"_s, "y", false, ns++)); // kept: updates
        more.push_back(msg(u"made/up/new"_s, "z", false, ns++)); // not kept
        more.push_back(msg(u"$SYS/broker/uptime"_s, "1 s", false, ns++)); // a topic too
        tree.apply(std::move(more));
        QCOMPARE(tree.topicData().info(u"made/up/0"_s)->messages, quint64(2));
        QVERIFY(!tree.topicData().info(u"made/up/new"_s));
        QVERIFY(tree.topicData().store().statistics().isEmpty());
        QCOMPARE(tree.topicData().store().untrackedMessages(), quint64(5002));
        QCOMPARE(tree.topicData().store().totalMessages(), quint64(25003));
        tree.clear();
        QCOMPARE(tree.topicData().store().untrackedMessages(), quint64(0));
        QCOMPARE(tree.topicData().store().structureBytes(), qint64(0));

        // Names as long as MQTT allows are kept, and paid for: 600 of 60,000 characters do not fit.
        for (int round = 0; round < 12; ++round) {
            std::vector<MqttMessage> batch;
            for (int t = 0; t < 50; ++t)
                batch.push_back(msg(u"%1/"_s.arg(round * 50 + t) + QString(60000, u'n'), "x", false, ns++));
            tree.apply(std::move(batch));
        }
        QVERIFY2(tree.topicData().store().topicCount() > 100 && tree.topicData().store().topicCount() < 300,
                 qPrintable(QString::number(tree.topicData().store().topicCount())));
        QCOMPARE(tree.topicData().store().untrackedMessages(),
                 quint64(600 - tree.topicData().store().topicCount()));
        QVERIFY(tree.topicData().store().structureBytes() <= tree.topicData().store().structureBudget());
    }

    /// A deep topic keeps every prefix as a level's path: it pays for all of them, counted before
    /// anything is made; a model viewing the tree sees only the topics that fit.
    void deepTopicsPayForEveryLevel()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        tree.setStructureBudget(1024 * 1024);
        tree.setTopicBudget(10);
        QString deep;
        for (int i = 0; i < 2000; ++i)
            deep += u"l/"_s;
        std::vector<MqttMessage> batch;
        batch.push_back(msg(deep + u"end"_s, "x"));
        for (int t = 0; t < 20; ++t)
            batch.push_back(msg(u"a/%1"_s.arg(t), "x"));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().store().topicCount(), 10);
        QCOMPARE(tree.topicData().store().untrackedMessages(), quint64(11));
        QCOMPARE(tree.rowCount(), 1); // "a" only
        QCOMPARE(tree.rowCount(tree.index(0, 0)), 10);
        QVERIFY(tree.topicData().store().structureBytes() <= 1024 * 1024);
    }

    void learnsTypesFromMqttClientAnnouncements()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"mqtt_client/ros_msg_type/cap/pose"_s,
                            Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s), true));
        batch.push_back(msg(u"cap/pose"_s, Fixtures::read(u"mqtt_client/wire/pose.payload.bin"_s)));
        tree.apply(std::move(batch));
        const auto pose = tree.topicData().info(u"cap/pose"_s);
        QVERIFY(pose->rosType);
        QCOMPARE(pose->rosType->name, u"geometry_msgs/PoseStamped"_s);
        QCOMPARE(pose->malformedPayloads, 0u);
        QVERIFY(tree.topicData().registryFor(u"cap/pose"_s));
        QCOMPARE(tree.indexOf(u"cap/pose"_s, MqttTopicTree::RosTypeColumn).data().toString(),
                 u"geometry_msgs/PoseStamped"_s);

        // Stamped: the latency is receive time minus the injected stamp.
        const QByteArray payload = Fixtures::read(u"mqtt_client/wire/string_stamped.payload.bin"_s);
        const qint64 stamp = MqttClientWire::splitStamped(payload)->stampNs;
        batch.clear();
        batch.push_back(msg(u"mqtt_client/ros_msg_type/cap/string_stamped"_s,
                            Fixtures::read(u"mqtt_client/wire/string_stamped.type.bin"_s), true));
        batch.push_back(msg(u"cap/string_stamped"_s, payload, false, stamp + 12'500'000));
        tree.apply(std::move(batch));
        const auto s = tree.topicData().info(u"cap/string_stamped"_s);
        QCOMPARE(s->rosType->stamped, true);
        QCOMPARE(s->lastLatencyMs, 12.5);
        QCOMPARE(s->latencySamples, 1u);
    }

    // Regression: an announcement for a topic that already had messages marked the topic's row
    // changed without reporting it, and a row so marked was never reported again: its later
    // messages changed the figures without a dataChanged, so views showed stale ones.
    void aLateAnnouncementKeepsTheTopicRowLive()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QByteArray payload = Fixtures::read(u"mqtt_client/wire/pose.payload.bin"_s);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"cap/pose"_s, payload));
        tree.apply(std::move(batch));
        QSignalSpy changed(&tree, &QAbstractItemModel::dataChanged);
        const auto rowReported = [&] {
            const QModelIndex row = tree.indexOf(u"cap/pose"_s);
            for (const QList<QVariant>& args : std::as_const(changed)) {
                const QModelIndex from = args[0].toModelIndex();
                const QModelIndex to = args[1].toModelIndex();
                if (from.parent() == row.parent() && from.row() <= row.row() && to.row() >= row.row())
                    return true;
            }
            return false;
        };
        batch.clear();
        batch.push_back(
            msg(u"mqtt_client/ros_msg_type/cap/pose"_s, Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s)));
        tree.apply(std::move(batch));
        QVERIFY(rowReported()); // the type column changed
        for (int i = 0; i < 2; ++i) {
            changed.clear();
            batch.clear();
            batch.push_back(msg(u"cap/pose"_s, payload));
            tree.apply(std::move(batch));
            QVERIFY2(rowReported(), qPrintable(u"message %1 after the announcement"_s.arg(i + 1)));
        }
    }

    void malformedAnnouncementsAndPayloadsAreCounted()
    {
        MqttTopicTree tree;
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"mqtt_client/ros_msg_type/bad"_s, "garbage", true));
        batch.push_back(
            msg(u"mqtt_client/ros_msg_type/cap/pose"_s, Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s)));
        batch.push_back(msg(u"cap/pose"_s, "not a pose"));
        batch.push_back(msg(u"mqtt_client/ros_msg_type/cap/s"_s,
                            Fixtures::read(u"mqtt_client/wire/string_stamped.type.bin"_s)));
        batch.push_back(msg(u"cap/s"_s, "short"));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().checks().malformedTypeAnnouncements(), 1u);
        QVERIFY(!tree.topicData().info(u"mqtt_client/ros_msg_type/bad"_s)->typeError.isEmpty());
        QCOMPARE(tree.topicData().info(u"cap/pose"_s)->malformedPayloads, 1u);
        QCOMPARE(tree.topicData().info(u"cap/s"_s)->malformedPayloads, 1u);
        QCOMPARE(tree.topicData().checks().malformedPayloads(), 2u);
    }

    void sysTopicsAreBrokerStatistics()
    {
        MqttTopicTree tree;
        QSignalSpy stats(&tree, &MqttTopicTree::brokerStatisticsChanged);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"$SYS/broker/version"_s, "mosquitto version 2.0.11", true));
        batch.push_back(msg(u"a"_s, "1"));
        tree.apply(std::move(batch));
        QCOMPARE(stats.size(), 1);
        QCOMPARE(tree.topicData().store().statistics().value(u"$SYS/broker/version"_s),
                 u"mosquitto version 2.0.11"_s);
        QCOMPARE(tree.topicData().store().topicCount(), 1);
    }

    void ratesComeFromTicks()
    {
        MqttTopicTree tree;
        tree.tick(1'000'000'000);
        std::vector<MqttMessage> batch;
        for (int i = 0; i < 40; ++i)
            batch.push_back(msg(u"a/b"_s, "x"));
        tree.apply(std::move(batch));
        tree.tick(3'000'000'000); // two seconds later
        QCOMPARE(tree.topicData().info(u"a/b"_s)->rate, 20.0);
        QCOMPARE(tree.index(0, MqttTopicTree::RateColumn).data(MqttTopicTree::SortRole).toDouble(), 20.0);
        QCOMPARE(tree.topicData().info(u"a/b"_s)->rateHistory, QList<double> {20.0});
    }

    void recursiveFilterFindsDeepTopics()
    {
        MqttTopicTree tree;
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"a/b/needle"_s, "hay"));
        batch.push_back(msg(u"a/c"_s, "payload with needle"));
        batch.push_back(msg(u"d"_s, "x"));
        tree.apply(std::move(batch));
        QSortFilterProxyModel proxy;
        proxy.setSourceModel(&tree);
        proxy.setRecursiveFilteringEnabled(true);
        QAbstractItemModelTester tester(&proxy, QAbstractItemModelTester::FailureReportingMode::QtTest);
        proxy.setFilterFixedString(u"needle"_s);
        QCOMPARE(dump(proxy), (QStringList {u"a 2"_s, u"  b 1"_s, u"    needle 1"_s}));
        proxy.setFilterRole(MqttTopicTree::SearchTextRole);
        QCOMPARE(dump(proxy), (QStringList {u"a 2"_s, u"  c 1"_s}));
    }
    // Regression (issue 11, item 4): this retained pair hung discovery and the GUI (4.3e9 empty
    // elements stepped over one by one), at every start. Over a budget, a payload is counted.
    void hostileAnnouncementsCostBoundedWork()
    {
        MqttTopicTree tree;
        const auto announce = [](const QString& definition) {
            RosMsgTypeInfo info;
            info.md5 = u"*"_s;
            info.name = u"pkg/Outer"_s;
            info.definition = definition;
            return MqttClientWire::encodeType(info);
        };
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"mqtt_client/ros_msg_type/evil/empty"_s,
                            announce(u"Inner[] items\n===\nMSG: pkg/Inner\nstring[0] s\n"_s), true));
        batch.push_back(msg(u"evil/empty"_s, QByteArray(4, '\xff'), true));
        // A million and one elements of five bytes: more steps than one message may take.
        QByteArray many(4, '\0');
        qToLittleEndian<quint32>(1000001, many.data());
        many += QByteArray(1000001 * 5, '\0');
        batch.push_back(msg(u"mqtt_client/ros_msg_type/evil/many"_s,
                            announce(u"Item[] items\n===\nMSG: pkg/Item\nuint8 a\nuint8[] b\n"_s), true));
        batch.push_back(msg(u"evil/many"_s, many, true));
        // A definition that does not read, and an announcement over its size budget.
        batch.push_back(msg(u"mqtt_client/ros_msg_type/evil/def"_s, announce(u"int32[-1] x\n"_s), true));
        batch.push_back(msg(u"mqtt_client/ros_msg_type/evil/big"_s,
                            announce(QString(MqttClientWire::kMaxTypeBytes, u'#')), true));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"evil/empty"_s)->malformedPayloads, 0u);
        QCOMPARE(tree.topicData().info(u"evil/many"_s)->malformedPayloads, 1u);
        QVERIFY2(tree.topicData().info(u"evil/many"_s)->payloadError.contains(u"more than 1000000 steps"_s),
                 qPrintable(tree.topicData().info(u"evil/many"_s)->payloadError));
        QVERIFY(tree.data(tree.indexOf(u"evil/many"_s), Qt::ToolTipRole).toString().contains(u"more than"_s));
        for (const QString& t :
             {u"mqtt_client/ros_msg_type/evil/def"_s, u"mqtt_client/ros_msg_type/evil/big"_s}) {
            QCOMPARE(tree.topicData().info(t)->malformedPayloads, 1u);
            QVERIFY(!tree.topicData().info(t)->typeError.isEmpty());
        }
        QCOMPARE(tree.topicData().checks().malformedTypeAnnouncements(), 2u);
    }
};

QTEST_GUILESS_MAIN(TestMqttTopicTree)
#include "tst_mqtttopictree.moc"
