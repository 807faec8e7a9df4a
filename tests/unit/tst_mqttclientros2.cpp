// SPDX-License-Identifier: MIT
// mqtt_client for ROS 2 on the broker: its CDR type announcement and its CDR payloads, stamped
// with a separately serialized builtin_interfaces/msg/Time. The bytes come from Fast CDR exactly
// as mqtt_client's RMW writes them (tests/support/mqttclientros2.h says how), and two fixtures
// are written out by hand, byte by byte, from mqtt_client's source (MqttClient.cpp, v2.5.0):
// the two agree, and both decode in MqttClientWire, the topic tree and the stamp decoder.
#include "mqtt/mqttstampdecoder.h"
#include "models/mqtttopictree.h"
#include "mqttclientros2.h"
#include "resulttext.h"
#include "wire/mqttclientwire.h"
#include "wire/ros2definitions.h"
#include "wire/stampcodec.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

using namespace Qt::StringLiterals;
using eprosima::fastcdr::Cdr;
using Dialect = RosTypeRegistry::Dialect;

namespace {

// The announcement of a stamped std_msgs/msg/String, as mqtt_client v2.5.0 sends it from a
// little-endian host (ros2mqtt(): RosMsgType with name and stamped set, md5 and definition left
// empty, serialized by rclcpp::Serialization, published retained as it is).
const QByteArray kStringAnnouncement
    = QByteArray::fromHex("00010000" // encapsulation: 00 01 = CDR little-endian, 00 00 = options
                          "01000000" // md5: uint32 length 1 (the empty string's terminating NUL)
                          "00" // md5: the NUL
                          "000000" // padding: the next uint32 sits at a multiple of 4 counted from byte 4
                          "14000000" // name: length 20 = 19 characters + NUL
                          "7374645f6d7367732f6d73672f537472696e67" // "std_msgs/msg/String"
                          "00" // name: NUL (byte 35)
                          "01000000" // definition: length 1, at byte 36 (36 - 4 = 32: aligned, no padding)
                          "00" // definition: NUL
                          "01"); // stamped: bool, one byte, true; no padding after the last member (42 bytes)

// A stamped std_msgs/msg/String "hello" sent at 1700000000.25 s: mqtt_client serializes the
// builtin_interfaces/msg/Time on its own (its stamp_length_ is that size: 12) and copies it in
// front of the serialized message; nothing separates them, nothing says their lengths.
const QByteArray kStampedHello = QByteArray::fromHex(
    "00010000" // the stamp's own encapsulation: CDR little-endian
    "00f15365" // sec: int32 1700000000 = 0x6553f100, little-endian
    "80b2e60e" // nanosec: uint32 250000000 = 0x0ee6b280, little-endian
    "00010000" // the message's own encapsulation (byte 12): alignment counts from byte 16
    "06000000" // data: length 6 = "hello" + NUL
    "68656c6c6f00"); // "hello", NUL (26 bytes)

constexpr qint64 kHelloStampNs = 1'700'000'000'250'000'000LL;

MqttMessage msg(const QString& topic, const QByteArray& payload, qint64 ns = 1'000'000'000,
                bool retained = false)
{
    MqttMessage m;
    m.topic = topic;
    m.payload = payload;
    m.retained = retained;
    m.receivedNs = ns;
    return m;
}

QString typeTopic(const QString& data)
{
    return MqttClientWire::typeTopicPrefix() + data;
}

/// A geometry_msgs/msg/PoseStamped, member by member as rmw_fastrtps writes it.
QByteArray poseStamped(Cdr::Endianness e, double x)
{
    return MqttClientRos2::serialize(
        [&](Cdr& cdr) {
            cdr << int32_t(12) << uint32_t(34) << std::string("map"); // header
            cdr << x << 2.5 << -1.0; // position
            cdr << 0.0 << 0.0 << 0.0 << 1.0; // orientation
        },
        e);
}

QString field(const RosValue& v, const QString& path)
{
    const RosValue* f = v.find(path);
    return f ? f->value.toString() : u"<missing %1>"_s.arg(path);
}

} // namespace

class TestMqttClientRos2 : public QObject
{
    Q_OBJECT
    std::shared_ptr<const RosTypeRegistry> m_ros2;

private slots:
    void initTestCase()
    {
        QStringList errors;
        m_ros2 = std::make_shared<const RosTypeRegistry>(Ros2Definitions::registry({}, &errors));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(u'\n')));
    }

    // The hand-written bytes and Fast CDR's agree: the reading of the source and the serializer.
    void handWrittenFixturesAreWhatFastCdrWrites()
    {
        QCOMPARE(kStringAnnouncement.size(), 42);
        QCOMPARE(MqttClientRos2::announcement("std_msgs/msg/String", true).toHex(' '),
                 kStringAnnouncement.toHex(' '));
        QCOMPARE(kStampedHello.size(), 26);
        QCOMPARE(MqttClientRos2::stamped(1700000000, 250000000, MqttClientRos2::string("hello")).toHex(' '),
                 kStampedHello.toHex(' '));
        // And Bridgescope writes the same.
        RosMsgTypeInfo info;
        info.name = u"std_msgs/msg/String"_s;
        info.stamped = true;
        info.dialect = Dialect::Ros2;
        QCOMPARE(MqttClientWire::encodeType(info).toHex(' '), kStringAnnouncement.toHex(' '));
        QCOMPARE(
            MqttClientWire::stamped(kHelloStampNs, MqttClientRos2::string("hello"), Dialect::Ros2).toHex(' '),
            kStampedHello.toHex(' '));
    }

    void handWrittenFixturesDecode()
    {
        QString error;
        const auto info = noted(MqttClientWire::decodeType(kStringAnnouncement), &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->dialect, Dialect::Ros2);
        QCOMPARE(info->name, u"std_msgs/msg/String"_s);
        QVERIFY(info->stamped);
        QVERIFY(info->md5.isEmpty());
        QVERIFY(info->definition.isEmpty());

        const auto split = noted(MqttClientWire::splitStamped(kStampedHello, Dialect::Ros2), &error);
        QVERIFY2(split, qPrintable(error));
        QCOMPARE(split->stampNs, kHelloStampNs);
        QCOMPARE(split->message, kStampedHello.mid(12));
        const auto value = noted(MqttClientWire::decodePayload(*m_ros2, *info, kStampedHello), &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->toLines(), QStringList {u"data: \"hello\""_s});
    }

    void announcementsFromFastCdrDecode_data()
    {
        QTest::addColumn<int>("endianness");
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("stamped");
        QTest::addColumn<QString>("md5");
        QTest::addColumn<QString>("definition");
        for (Cdr::Endianness e : {Cdr::LITTLE_ENDIANNESS, Cdr::BIG_ENDIANNESS}) {
            const char* order = e == Cdr::LITTLE_ENDIANNESS ? "le" : "be";
            QTest::addRow("%s string stamped", order)
                << int(e) << u"std_msgs/msg/String"_s << true << QString() << QString();
            QTest::addRow("%s pose", order)
                << int(e) << u"geometry_msgs/msg/PoseStamped"_s << false << QString() << QString();
            // Names of every length modulo 4 move the padding around.
            for (int extra = 0; extra < 4; ++extra)
                QTest::addRow("%s name +%d", order, extra) << int(e) << u"pkg/msg/T"_s + QString(extra, u'x')
                                                           << bool(extra % 2) << QString() << QString();
            // mqtt_client leaves md5 and definition empty; filled ones read as well.
            QTest::addRow("%s md5 and definition", order) << int(e) << u"sensor_msgs/msg/Image"_s << true
                                                          << u"abc"_s << u"uint32 height\nuint32 width"_s;
            QTest::addRow("%s long name", order)
                << int(e) << u"a/"_s + QString(3000, u'n') << false << QString() << QString();
            QTest::addRow("%s utf-8", order)
                << int(e) << u"pkg/msg/Größe"_s << true << QString() << QString();
        }
    }

    void announcementsFromFastCdrDecode()
    {
        QFETCH(int, endianness);
        QFETCH(QString, name);
        QFETCH(bool, stamped);
        QFETCH(QString, md5);
        QFETCH(QString, definition);
        const auto e = Cdr::Endianness(endianness);
        const QByteArray bytes = MqttClientRos2::announcement(name.toStdString(), stamped, e,
                                                              md5.toStdString(), definition.toStdString());
        QCOMPARE(MqttClientWire::dialectOf(bytes), Dialect::Ros2);
        QString error;
        const auto info = noted(MqttClientWire::decodeType(bytes), &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->name, name);
        QCOMPARE(info->stamped, stamped);
        QCOMPARE(info->md5, md5);
        QCOMPARE(info->definition, definition);
        QCOMPARE(info->dialect, Dialect::Ros2);
        // Encoding writes little-endian CDR, byte for byte what Fast CDR writes.
        QCOMPARE(MqttClientWire::encodeType(*info),
                 MqttClientRos2::announcement(name.toStdString(), stamped, Cdr::LITTLE_ENDIANNESS,
                                              md5.toStdString(), definition.toStdString()));
        // Up to 3 bytes of padding after the last member are read past (Cyclone DDS pads to 4).
        for (int pad = 1; pad <= 3; ++pad)
            QVERIFY(MqttClientWire::decodeType(bytes + QByteArray(pad, '\0')).valueOr({}) == *info);
        // Padding is not written by Fast CDR: whatever the buffer held reads the same.
        const QByteArray dirty = MqttClientRos2::announcement(
            name.toStdString(), stamped, e, md5.toStdString(), definition.toStdString(), '\xa5');
        QVERIFY(MqttClientWire::decodeType(dirty).valueOr({}) == *info);
    }

    void stampsFromFastCdrSplit_data()
    {
        QTest::addColumn<int>("endianness");
        QTest::addColumn<int>("sec");
        QTest::addColumn<uint>("nanosec");
        for (Cdr::Endianness e : {Cdr::LITTLE_ENDIANNESS, Cdr::BIG_ENDIANNESS}) {
            const char* order = e == Cdr::LITTLE_ENDIANNESS ? "le" : "be";
            QTest::addRow("%s now", order) << int(e) << 1700000000 << 250000000u;
            QTest::addRow("%s zero", order) << int(e) << 0 << 0u;
            QTest::addRow("%s last nanosecond", order) << int(e) << 2147483647 << 999999999u;
            QTest::addRow("%s before 1970", order) << int(e) << -2 << 500000000u; // int32 sec
        }
    }

    void stampsFromFastCdrSplit()
    {
        QFETCH(int, endianness);
        QFETCH(int, sec);
        QFETCH(uint, nanosec);
        const auto e = Cdr::Endianness(endianness);
        const QByteArray message = poseStamped(e, 4.25);
        const QByteArray payload = MqttClientRos2::stamped(sec, nanosec, message, e);
        QString error;
        const auto split = noted(MqttClientWire::splitStamped(payload, Dialect::Ros2), &error);
        QVERIFY2(split, qPrintable(error));
        const qint64 ns = qint64(sec) * 1'000'000'000 + nanosec;
        QCOMPARE(split->stampNs, ns);
        QCOMPARE(split->message, message);
        QCOMPARE(MqttClientWire::stamped(ns, message, Dialect::Ros2),
                 MqttClientRos2::stamped(sec, nanosec, message, Cdr::LITTLE_ENDIANNESS));

        RosMsgTypeInfo info {QString(), u"geometry_msgs/msg/PoseStamped"_s, QString(), true, Dialect::Ros2};
        const auto value = noted(MqttClientWire::decodePayload(*m_ros2, info, payload), &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(field(*value, u"pose.position.x"_s), u"4.25"_s);
        QCOMPARE(field(*value, u"header.frame_id"_s), u"map"_s);
        QCOMPARE(field(*value, u"header.stamp.nanosec"_s), u"34"_s);
    }

    // The rule: a zero first byte is a CDR encapsulation header (ROS 2); a ROS 1 announcement
    // starts with its md5's length, 32 or 1, which decodeType() insists on.
    void dialectIsToldByTheFirstByte()
    {
        RosMsgTypeInfo ros1 {u"*"_s, u"std_msgs/String"_s, u"string data\n"_s, true};
        QCOMPARE(MqttClientWire::dialectOf(MqttClientWire::encodeType(ros1)), Dialect::Ros1);
        ros1.md5 = QString(32, u'f');
        QCOMPARE(MqttClientWire::encodeType(ros1).at(0), '\x20');
        QCOMPARE(MqttClientWire::decodeType(MqttClientWire::encodeType(ros1))->dialect, Dialect::Ros1);
        QCOMPARE(MqttClientWire::dialectOf(kStringAnnouncement), Dialect::Ros2);
        QCOMPARE(MqttClientWire::dialectOf(MqttClientRos2::announcement("a/b", false, Cdr::BIG_ENDIANNESS)),
                 Dialect::Ros2);
        QCOMPARE(MqttClientWire::dialectOf(QByteArray()), Dialect::Ros1);
        // A ROS 1 announcement whose md5 has another length is refused, so none starts with 0.
        QByteArray zeroMd5 = MqttClientWire::encodeType({QString(), u"a/b"_s, QString(), false});
        QVERIFY(!MqttClientWire::decodeType(zeroMd5.mid(0, 0)));
        QString error;
        QVERIFY(!noted(MqttClientWire::decodeType(zeroMd5), &error)); // 00 00 00 00: read as big-endian CDR
        QVERIFY2(!error.isEmpty(), "no reason given");
    }

    void hostileAnnouncementsAreRefusedWithAReason_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("reason");
        const QByteArray good = kStringAnnouncement;
        QTest::addRow("header only") << good.left(4) << u"ends before the length of 'md5'"_s;
        QTest::addRow("half a header") << good.left(2) << u"inside its CDR encapsulation header"_s;
        QTest::addRow("parameter list")
            << QByteArray::fromHex("00030000") + good.mid(4) << u"not plain CDR"_s;
        QTest::addRow("xcdr2") << QByteArray::fromHex("00070000") + good.mid(4)
                               << u"not plain CDR (encapsulation 00 07)"_s;
        QTest::addRow("no stamped") << good.left(41) << u"ends before 'stamped'"_s;
        QTest::addRow("too much after stamped") << good + QByteArray(4, '\0') << u"4 bytes after 'stamped'"_s;
        QByteArray huge = good;
        huge.replace(12, 4, QByteArray::fromHex("ffffffff"));
        QTest::addRow("name of 4 GB") << huge << u"'name' claims 4294967295 bytes"_s;
        huge.replace(12, 4, QByteArray::fromHex("1b000000"));
        QTest::addRow("name one byte too long") << huge << u"'name' claims 27 bytes but only 26 follow"_s;
        QByteArray md5 = good;
        md5.replace(4, 4, QByteArray::fromHex("00000080"));
        QTest::addRow("md5 of 2 GB") << md5 << u"'md5' claims 2147483648 bytes"_s;
        QTest::addRow("no type name")
            << MqttClientRos2::announcement("String", false) << u"'String' is not a ROS type name"_s;
        QTest::addRow("over the size budget")
            << MqttClientRos2::announcement(std::string(MqttClientWire::kMaxTypeBytes, 'n'), false)
            << u"more than the 1048576 one may have"_s;
    }

    void hostileAnnouncementsAreRefusedWithAReason()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, reason);
        QString error;
        QVERIFY(!noted(MqttClientWire::decodeType(bytes), &error));
        QVERIFY2(error.contains(reason), qPrintable(error));
    }

    // Every cut of a good announcement fails, with a reason, and never reads past the bytes.
    void everyTruncationFails()
    {
        for (qsizetype n = 0; n < kStringAnnouncement.size(); ++n) {
            const QByteArray cut = kStringAnnouncement.left(n);
            QString error;
            QVERIFY2(!noted(MqttClientWire::decodeType(cut), &error),
                     qPrintable(u"%1 bytes decoded"_s.arg(n)));
            QVERIFY2(!error.isEmpty(), qPrintable(u"%1 bytes: no reason"_s.arg(n)));
        }
    }

    void hostileStampedPayloadsAreRefusedWithAReason_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QString>("reason");
        QTest::addRow("empty") << QByteArray() << u"payload of 0 bytes, shorter than its 12-byte stamp"_s;
        QTest::addRow("a ROS 1 stamp") << kStampedHello.left(8) << u"shorter than its 12-byte stamp"_s;
        QTest::addRow("stamp cut") << kStampedHello.left(11) << u"shorter than its 12-byte stamp"_s;
        QTest::addRow("no header") << QByteArray::fromHex("00f1536580b2e60e") + kStampedHello.mid(12)
                                   << u"does not start with a CDR encapsulation header (00 f1)"_s;
        QByteArray wrong = kStampedHello;
        wrong[1] = 2;
        QTest::addRow("parameter list") << wrong << u"(00 02)"_s;
        QTest::addRow("nanoseconds over")
            << MqttClientRos2::stamped(1, 1000000000, MqttClientRos2::string("x"))
            << u"1000000000 nanoseconds"_s;
    }

    void hostileStampedPayloadsAreRefusedWithAReason()
    {
        QFETCH(QByteArray, payload);
        QFETCH(QString, reason);
        QString error;
        QVERIFY(!noted(MqttClientWire::splitStamped(payload, Dialect::Ros2), &error));
        QVERIFY2(error.contains(reason), qPrintable(error));
        const RosMsgTypeInfo info {QString(), u"std_msgs/msg/String"_s, QString(), true, Dialect::Ros2};
        error.clear();
        QVERIFY(!noted(MqttClientWire::decodePayload(*m_ros2, info, payload), &error));
        QVERIFY2(error.contains(reason), qPrintable(error));
    }

    // A stamp and no message: the stamp splits off, the empty message does not decode.
    void aStampOnlyPayloadSplitsButDoesNotDecode()
    {
        const QByteArray stampOnly = kStampedHello.left(12);
        const auto split = MqttClientWire::splitStamped(stampOnly, Dialect::Ros2);
        QVERIFY(split);
        QCOMPARE(split->stampNs, kHelloStampNs);
        QVERIFY(split->message.isEmpty());
        const RosMsgTypeInfo info {QString(), u"std_msgs/msg/String"_s, QString(), true, Dialect::Ros2};
        QString error;
        QVERIFY(!noted(MqttClientWire::decodePayload(*m_ros2, info, stampOnly), &error));
        QVERIFY2(error.contains(u"encapsulation header"_s), qPrintable(error));
    }

    // The topic tree: type, decoded fields, latency, with the bundled definitions shared.
    void topicTreeDecodesRos2Topics()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(typeTopic(u"car/hello"_s), kStringAnnouncement, 1'000'000'000, true));
        batch.push_back(msg(u"car/hello"_s, kStampedHello, kHelloStampNs + 12'500'000));
        batch.push_back(msg(typeTopic(u"car/pose"_s),
                            MqttClientRos2::announcement("geometry_msgs/msg/PoseStamped", false),
                            1'000'000'000, true));
        batch.push_back(msg(u"car/pose"_s, poseStamped(Cdr::LITTLE_ENDIANNESS, -3.5)));
        tree.apply(std::move(batch));

        const auto hello = tree.topicData().info(u"car/hello"_s);
        QVERIFY(hello->rosType);
        QCOMPARE(hello->rosType->name, u"std_msgs/msg/String"_s);
        QCOMPARE(hello->rosType->dialect, Dialect::Ros2);
        QVERIFY(hello->rosType->stamped);
        QCOMPARE(hello->lastLatencyMs, 12.5);
        QCOMPARE(hello->latencySamples, 1u);
        QCOMPARE(hello->malformedPayloads, 0u);
        QVERIFY(hello->typeNote.isEmpty());
        QCOMPARE(tree.indexOf(u"car/hello"_s, MqttTopicTree::RosTypeColumn).data().toString(),
                 u"std_msgs/msg/String (stamped)"_s);
        QCOMPARE(tree.indexOf(u"car/hello"_s, MqttTopicTree::LatencyColumn).data().toString(), u"12.5 ms"_s);
        const auto registry = tree.topicData().registryFor(u"car/hello"_s);
        QVERIFY(registry);
        QCOMPARE(registry->dialect(), Dialect::Ros2);
        QString error;
        const auto value
            = noted(MqttClientWire::decodePayload(*registry, *hello->rosType,
                                                  tree.topicData().history(u"car/hello"_s)->back().payload),
                    &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(field(*value, u"data"_s), u"hello"_s);

        const auto pose = tree.topicData().info(u"car/pose"_s);
        QCOMPARE(pose->rosType->name, u"geometry_msgs/msg/PoseStamped"_s);
        QCOMPARE(pose->malformedPayloads, 0u);
        QCOMPARE(pose->latencySamples, 0u);
        // One registry for every ROS 2 topic of every tree: parsed once, not per message.
        QCOMPARE(tree.topicData().registryFor(u"car/pose"_s).get(), registry.get());
        MqttTopicTree other;
        batch.clear();
        batch.push_back(msg(typeTopic(u"x"_s), kStringAnnouncement));
        other.apply(std::move(batch));
        QCOMPARE(other.topicData().registryFor(u"x"_s).get(), registry.get());
        QCOMPARE(tree.topicData().checks().unknownTypeTopics(), 0);
    }

    // mqtt_client announces with every message: the same announcement changes nothing; a ROS 1
    // announcement after a ROS 2 one (another bridge on the topic) is a change.
    void announcementsRepeatedOrReplaced()
    {
        MqttTopicTree tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        std::vector<MqttMessage> batch;
        batch.push_back(msg(u"t"_s, MqttClientRos2::string("first")));
        tree.apply(std::move(batch));
        QSignalSpy changed(&tree, &QAbstractItemModel::dataChanged);
        for (int i = 0; i < 3; ++i) {
            batch.clear();
            batch.push_back(
                msg(typeTopic(u"t"_s), MqttClientRos2::announcement("std_msgs/msg/String", false)));
            tree.apply(std::move(batch));
        }
        QCOMPARE(tree.topicData().info(u"t"_s)->rosType->dialect, Dialect::Ros2);
        // The data topic's row was told of its type, once.
        int rowChanges = 0;
        for (const auto& args : changed) {
            const QModelIndex from = args[0].toModelIndex();
            const QModelIndex to = args[1].toModelIndex();
            if (!from.parent().isValid() && from.row() <= tree.indexOf(u"t"_s).row()
                && to.row() >= tree.indexOf(u"t"_s).row() && to.column() >= MqttTopicTree::RosTypeColumn)
                ++rowChanges;
        }
        QCOMPARE(rowChanges, 1);
        batch.clear();
        batch.push_back(
            msg(typeTopic(u"t"_s),
                MqttClientWire::encodeType({u"*"_s, u"std_msgs/String"_s, u"string data\n"_s, false})));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"t"_s)->rosType->dialect, Dialect::Ros1);
        QCOMPARE(tree.topicData().info(u"t"_s)->rosType->name, u"std_msgs/String"_s);
    }

    void unknownRos2TypesShowRawAndSaySo()
    {
        MqttTopicTree tree;
        std::vector<MqttMessage> batch;
        batch.push_back(
            msg(typeTopic(u"robot/state"_s), MqttClientRos2::announcement("my_pkg/msg/State", true)));
        batch.push_back(msg(u"robot/state"_s,
                            MqttClientRos2::stamped(100, 0, MqttClientRos2::serialize([](Cdr& cdr) {
                                                        cdr << uint8_t(7) << int32_t(-1);
                                                    })),
                            100'020'000'000LL));
        tree.apply(std::move(batch));
        const auto info = tree.topicData().info(u"robot/state"_s);
        QCOMPARE(info->rosType->name, u"my_pkg/msg/State"_s);
        QVERIFY(!tree.topicData().registryFor(u"robot/state"_s));
        QVERIFY2(info->typeNote.contains(u"No ROS 2 definition of my_pkg/msg/State"_s),
                 qPrintable(info->typeNote));
        QCOMPARE(info->malformedPayloads, 0u); // not malformed, only unknown
        QCOMPARE(tree.topicData().checks().malformedTypeAnnouncements(), 0u);
        QCOMPARE(info->lastLatencyMs, 20.0); // the stamp needs no definition
        QCOMPARE(tree.topicData().checks().unknownTypeTopics(), 1);
        const QString tip = tree.indexOf(u"robot/state"_s).data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains(u"No ROS 2 definition"_s), qPrintable(tip));

        // Given definitions that know it (the user's .msg folders), the topic decodes.
        auto withState = std::make_shared<RosTypeRegistry>(*m_ros2);
        QVERIFY(withState->addDefinition(u"my_pkg/msg/State"_s, u"uint8 mode\nint32 level\n"_s));
        QSignalSpy changed(&tree, &QAbstractItemModel::dataChanged);
        tree.setRos2Registry(withState);
        QCOMPARE(changed.size(), 1);
        QCOMPARE(tree.topicData().checks().unknownTypeTopics(), 0);
        const auto registry = tree.topicData().registryFor(u"robot/state"_s);
        QVERIFY(registry);
        QVERIFY(tree.topicData().info(u"robot/state"_s)->typeNote.isEmpty());
        QString error;
        const auto value = noted(
            MqttClientWire::decodePayload(*registry, *tree.topicData().info(u"robot/state"_s)->rosType,
                                          tree.topicData().history(u"robot/state"_s)->back().payload),
            &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->toLines(), (QStringList {u"mode: 7"_s, u"level: -1"_s}));
    }

    void malformedRos2PayloadsAreCounted()
    {
        MqttTopicTree tree;
        std::vector<MqttMessage> batch;
        batch.push_back(msg(typeTopic(u"s"_s), kStringAnnouncement));
        batch.push_back(msg(typeTopic(u"u"_s), MqttClientRos2::announcement("std_msgs/msg/String", false)));
        batch.push_back(msg(u"s"_s, kStampedHello.left(8))); // a ROS 1-sized stamp
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"s"_s)->malformedPayloads, 1u);
        QVERIFY2(tree.topicData().info(u"s"_s)->payloadError.contains(u"shorter than its 12-byte stamp"_s),
                 qPrintable(tree.topicData().info(u"s"_s)->payloadError));
        QCOMPARE(tree.topicData().info(u"s"_s)->latencySamples, 0u);

        batch.clear();
        batch.push_back(msg(u"s"_s, kStampedHello.left(12), kHelloStampNs)); // the stamp alone
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"s"_s)->malformedPayloads, 2u);
        QCOMPARE(tree.topicData().info(u"s"_s)->latencySamples, 1u);
        QVERIFY2(tree.topicData().info(u"s"_s)->payloadError.contains(u"encapsulation header"_s),
                 qPrintable(tree.topicData().info(u"s"_s)->payloadError));

        batch.clear();
        batch.push_back(msg(u"u"_s, "plain text")); // not CDR
        batch.push_back(msg(u"u"_s, MqttClientRos2::string("ok")));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"u"_s)->malformedPayloads,
                 0u); // only the newest of a batch is checked
        batch.clear();
        batch.push_back(msg(u"u"_s, MqttClientRos2::string("cut").left(9)));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().info(u"u"_s)->malformedPayloads, 1u);
        QCOMPARE(tree.topicData().checks().malformedPayloads(), 3u);

        // A broken ROS 2 announcement is a malformed announcement.
        batch.clear();
        batch.push_back(msg(typeTopic(u"b"_s), kStringAnnouncement.left(30)));
        tree.apply(std::move(batch));
        QCOMPARE(tree.topicData().checks().malformedTypeAnnouncements(), 1u);
        QVERIFY(!tree.topicData().info(typeTopic(u"b"_s))->typeError.isEmpty());
    }

    // Measure and Watch: the stamp of a ROS 2 payload is a latency, a bad one is counted.
    void stampDecoderReadsRos2Stamps()
    {
        MqttStampDecoder decoder;
        std::vector<MqttMessage> batch;
        batch.push_back(msg(typeTopic(u"car/hello"_s), kStringAnnouncement));
        batch.push_back(msg(u"car/hello"_s, kStampedHello, kHelloStampNs + 7'000'000));
        batch.push_back(msg(u"car/hello"_s, kStampedHello.left(8), kHelloStampNs + 8'000'000));
        std::vector<StampEvent> stamps;
        std::vector<LatencyValue> latencies;
        decoder.decode(batch, stamps, latencies);
        QCOMPARE(latencies.size(), std::size_t(1));
        QCOMPARE(latencies[0].series, MqttStampDecoder::latencySeries(u"car/hello"_s));
        QCOMPARE(latencies[0].valueNs, 7'000'000);
        QVERIFY(stamps.empty());
        QCOMPARE(decoder.malformed(), 1u);
        QVERIFY2(decoder.lastError().contains(u"12-byte stamp"_s), qPrintable(decoder.lastError()));
    }

    // Issue 34: the suite's stamp in its ROS 2 form, bridged by mqtt_client for ROS 2: announced by
    // name (no md5), CDR as Fast CDR writes it in either byte order, the 12-byte stamp in front.
    void stampDecoderReadsRos2TimeStamped()
    {
        const auto timeStamped = [](Cdr::Endianness e) {
            return MqttClientRos2::serialize(
                [](Cdr& cdr) {
                    cdr << int32_t(1'700'000'000) << uint32_t(5) << std::string("lidar"); // header
                    cdr << int32_t(1'700'000'000) << uint32_t(20'000'005); // time
                },
                e);
        };
        StampCodec::Decoded mine;
        mine.sampleNs = 1'700'000'000'000'000'005LL;
        mine.timeNs = 1'700'000'000'020'000'005LL;
        mine.frameId = u"lidar"_s;
        QCOMPARE(StampCodec::encodeTimeStampedCdr(mine), timeStamped(Cdr::LITTLE_ENDIANNESS));
        RosMsgTypeInfo type;
        type.name = u"benchmarking_suite/msg/TimeStamped"_s;
        type.stamped = true;
        type.dialect = Dialect::Ros2;
        MqttStampDecoder decoder;
        std::vector<MqttMessage> batch {msg(typeTopic(u"car/stamp"_s), MqttClientWire::encodeType(type))};
        for (Cdr::Endianness e : {Cdr::LITTLE_ENDIANNESS, Cdr::BIG_ENDIANNESS})
            batch.push_back(msg(u"car/stamp"_s, MqttClientWire::stamped(kHelloStampNs, timeStamped(e), Dialect::Ros2),
                                kHelloStampNs + 3'000'000));
        decoder.collect(batch);
        std::vector<StampEvent> stamps;
        std::vector<LatencyValue> latencies;
        decoder.takeStamps(stamps, latencies);
        QCOMPARE(stamps.size(), std::size_t(2));
        for (const StampEvent& s : stamps) {
            QCOMPARE(s.topic, u"car/stamp"_s);
            QCOMPARE(s.sampleNs, mine.sampleNs);
            QCOMPARE(s.timeNs, mine.timeNs);
        }
        QCOMPARE(latencies.size(), std::size_t(2));
        QCOMPARE(latencies[0].valueNs, 3'000'000);
        QCOMPARE(decoder.malformedStamps(), 0u);
        // Taken once.
        stamps.clear();
        decoder.takeStamps(stamps, latencies);
        QVERIFY(stamps.empty());
    }
};

QTEST_GUILESS_MAIN(TestMqttClientRos2)
#include "tst_mqttclientros2.moc"
