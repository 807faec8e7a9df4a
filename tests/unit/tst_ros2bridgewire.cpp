// SPDX-License-Identifier: MIT
// What the ROS 2 reference bridge writes besides whole messages, against Fast CDR as the RMW
// serializes (tests/support/mqttclientros2.h): the suite's ROS 2 TimeStamped, the Float64 of
// ~/latencies, std_msgs primitives from and to text as mqtt_client v2.5 converts them
// (mqtt2primitive(), fixedMqtt2PrimitiveRos(), primitiveRosMessageToString()), JSON to CDR.
#include "mqttclientros2.h"
#include "resulttext.h"
#include "wire/primitivetext.h"
#include "wire/ros2bridgewire.h"
#include "wire/ros2definitions.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace Qt::StringLiterals;
using MqttClientRos2::Cdr;
using namespace Ros2BridgeWire;

class TestRos2BridgeWire : public QObject
{
    Q_OBJECT
    RosTypeRegistry m_types = Ros2Definitions::registry();

private slots:
    void timeStampedAndFloat64AsRclcppSerializes()
    {
        StampCodec::Decoded d;
        d.sampleNs = 1'700'000'000'123'456'789;
        d.timeNs = 1'700'000'001'000'000'005;
        d.seq = 42; // a ROS 2 Header has none: not written
        d.frameId = u"lidar"_s;
        QCOMPARE(encodeTimeStamped(d), MqttClientRos2::serialize([](Cdr& cdr) {
                     cdr << int32_t(1'700'000'000) << uint32_t(123'456'789) << std::string("lidar")
                         << int32_t(1'700'000'001) << uint32_t(5);
                 }));
        d.frameId.clear();
        QCOMPARE(encodeTimeStamped(d), MqttClientRos2::serialize([](Cdr& cdr) {
                     cdr << int32_t(1'700'000'000) << uint32_t(123'456'789) << std::string()
                         << int32_t(1'700'000'001) << uint32_t(5);
                 }));
        QCOMPARE(encodeFloat64(0.0125), MqttClientRos2::serialize([](Cdr& cdr) { cdr << 0.0125; }));
        QCOMPARE(headerStampNs(encodeTimeStamped(d)), std::optional<qint64>(d.sampleNs));
        QCOMPARE(headerStampNs(MqttClientRos2::serialize([](Cdr& cdr) { cdr << int32_t(3) << uint32_t(4); },
                                                         Cdr::BIG_ENDIANNESS)),
                 std::optional<qint64>(3'000'000'004));
        QVERIFY(!headerStampNs(QByteArray::fromHex("0001000001000000"))); // cut
        QVERIFY(startsWithHeader(m_types, u"geometry_msgs/msg/PoseStamped"_s));
        QVERIFY(!startsWithHeader(m_types, u"std_msgs/msg/String"_s));
        QVERIFY(!startsWithHeader(m_types, u"unknown_msgs/msg/X"_s));
    }

    void primitivesAsV25Converts()
    {
        // MQTT text to ROS: Bool, Int32, Float32, else String
        const auto check = [](const QByteArray& text, const char* type, const QByteArray& cdr) {
            const Typed t = primitiveFromText(text);
            QCOMPARE(t.type, QString::fromLatin1(type));
            QCOMPARE(t.cdr, cdr);
        };
        check("TRUE", "std_msgs/msg/Bool", MqttClientRos2::serialize([](Cdr& cdr) { cdr << true; }));
        check("-42", "std_msgs/msg/Int32", MqttClientRos2::serialize([](Cdr& cdr) { cdr << int32_t(-42); }));
        check("2.5", "std_msgs/msg/Float32", MqttClientRos2::serialize([](Cdr& cdr) { cdr << 2.5f; }));
        check("99999999999", "std_msgs/msg/Float32",
              MqttClientRos2::serialize([](Cdr& cdr) { cdr << 99999999999.0f; })); // stoi: out of range
        check("hello", "std_msgs/msg/String", MqttClientRos2::string("hello"));
        // fixed types
        QCOMPARE(fixedPrimitive(m_types, u"std_msgs/msg/Bool"_s, "1"),
                 std::optional<QByteArray>(MqttClientRos2::serialize([](Cdr& cdr) { cdr << true; })));
        QCOMPARE(fixedPrimitive(m_types, u"std_msgs/msg/UInt16"_s, "513"),
                 std::optional<QByteArray>(MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint16_t(513); })));
        QCOMPARE(fixedPrimitive(m_types, u"std_msgs/msg/Float64"_s, "0.5"),
                 std::optional<QByteArray>(MqttClientRos2::serialize([](Cdr& cdr) { cdr << 0.5; })));
        QVERIFY(!fixedPrimitive(m_types, u"std_msgs/msg/UInt8"_s, "256"));
        QVERIFY(!fixedPrimitive(m_types, u"std_msgs/msg/Bool"_s, "yes"));
        QVERIFY(!fixedPrimitive(m_types, u"std_msgs/msg/Int32"_s, "12abc"));
        // ROS to MQTT text
        QCOMPARE(primitiveText(m_types, u"std_msgs/msg/String"_s, MqttClientRos2::string("hi there")),
                 std::optional<QByteArray>("hi there"));
        QCOMPARE(primitiveText(m_types, u"std_msgs/msg/Float32"_s,
                               MqttClientRos2::serialize([](Cdr& cdr) { cdr << 2.5f; })),
                 std::optional<QByteArray>("2.500000")); // std::to_string
        QCOMPARE(primitiveText(m_types, u"std_msgs/msg/Int64"_s,
                               MqttClientRos2::serialize([](Cdr& cdr) { cdr << int64_t(-7); })),
                 std::optional<QByteArray>("-7"));
        QCOMPARE(primitiveText(m_types, u"std_msgs/msg/Bool"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << false; })),
                 std::optional<QByteArray>("false"));
        // UInt8MultiArray: its bytes (layout: no dims, data_offset 0)
        QCOMPARE(primitiveText(m_types, u"std_msgs/msg/UInt8MultiArray"_s, MqttClientRos2::serialize([](Cdr& cdr) {
                                   cdr << uint32_t(0) << uint32_t(0) << std::vector<uint8_t> {'a', 0, 0xff};
                               })),
                 std::optional<QByteArray>(QByteArray("a\0\xff", 3)));
        QVERIFY(!primitiveText(m_types, u"geometry_msgs/msg/Point"_s, QByteArray(28, '\0')));
        QVERIFY(!primitiveText(m_types, u"std_msgs/msg/Int32"_s, QByteArray::fromHex("000100")));
    }

    // Issue 45: the text a primitive link is matched by (PrimitiveText, which needs no type registry
    // and runs in the DDS child) is the text the bridge sends, in either byte order; what a payload
    // reads back as is what the bridge makes of it.
    void primitiveTextAsTheBridgeWritesIt()
    {
        const auto big = Cdr::BIG_ENDIANNESS;
        const QList<std::pair<QString, QByteArray>> messages {
            {u"std_msgs/msg/String"_s, MqttClientRos2::string("hi there")},
            {u"std_msgs/msg/String"_s, MqttClientRos2::string("", big)},
            {u"std_msgs/msg/Bool"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << true; })},
            {u"std_msgs/msg/Int8"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << int8_t(-5); })},
            {u"std_msgs/msg/UInt8"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint8_t(200); })},
            {u"std_msgs/msg/Char"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint8_t(65); })},
            {u"std_msgs/msg/Byte"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint8_t(7); })},
            {u"std_msgs/msg/Int16"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << int16_t(-300); }, big)},
            {u"std_msgs/msg/UInt16"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint16_t(65000); })},
            {u"std_msgs/msg/Int32"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << int32_t(-42); })},
            {u"std_msgs/msg/UInt32"_s,
             MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint32_t(4000000000U); })},
            {u"std_msgs/msg/Int64"_s,
             MqttClientRos2::serialize([](Cdr& cdr) { cdr << int64_t(-7000000000000LL); }, big)},
            {u"std_msgs/msg/UInt64"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << uint64_t(~0ULL); })},
            {u"std_msgs/msg/Float32"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << 2.5f; })},
            {u"std_msgs/msg/Float32"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << 0.1f; }, big)},
            {u"std_msgs/msg/Float64"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << -0.125; })},
            {u"std_msgs/msg/Float64"_s, MqttClientRos2::serialize([](Cdr& cdr) { cdr << 1e20; })},
            {u"std_msgs/msg/UInt8MultiArray"_s, MqttClientRos2::serialize([](Cdr& cdr) {
                 cdr << uint32_t(1) << std::string("x") << uint32_t(3) << uint32_t(3) << uint32_t(0)
                     << std::vector<uint8_t> {'a', 0, 0xff};
             })},
        };
        for (const auto& [type, cdr] : messages) {
            const std::optional<QByteArray> text = PrimitiveText::ofCdr(type, cdr);
            QVERIFY2(text, qPrintable(type));
            QCOMPARE(*text, *primitiveText(m_types, type, cdr));
        }
        QCOMPARE(*PrimitiveText::ofCdr(u"std_msgs/msg/UInt8MultiArray"_s, messages.last().second),
                 QByteArray("a\0\xff", 3));
        QVERIFY(!PrimitiveText::ofCdr(u"geometry_msgs/msg/Point"_s, QByteArray(28, '\0')));
        QVERIFY(!PrimitiveText::ofCdr(u"std_msgs/msg/Int32"_s, QByteArray::fromHex("000100")));
        QVERIFY(
            !PrimitiveText::ofCdr(u"std_msgs/msg/String"_s, MqttClientRos2::string("hi there").chopped(4)));
        QVERIFY(!PrimitiveText::ofCdr(u"std_msgs/msg/Int32"_s, QByteArray::fromHex("0201000007000000")));
        QVERIFY(!PrimitiveText::ofCdr(u"std_msgs/msg/UInt8MultiArray"_s, messages.last().second.chopped(2)));
        // A million dimensions claimed in 12 bytes: refused at the first that is not there.
        QVERIFY(!PrimitiveText::ofCdr(u"std_msgs/msg/UInt8MultiArray"_s,
                                      QByteArray::fromHex("0001000040420f00")));

        for (const QByteArray& text :
             {QByteArray("TRUE"), QByteArray("false"), QByteArray("-42"), QByteArray(" 7"), QByteArray("7 "),
              QByteArray("2.5"), QByteArray("0.8444218515250481"), QByteArray("99999999999"),
              QByteArray("1e3"), QByteArray("hello"), QByteArray(), QByteArray("12abc"), QByteArray("inf"),
              QByteArray("3\0", 2), QByteArray("\t -12"), QByteArray(100, '1'),
              QByteArray(QByteArray(70, ' ') + "5"), QByteArray("x")}) {
            const Typed typed = primitiveFromText(text);
            if (text.size() <= PrimitiveText::kMaxRoundTripBytes)
                QCOMPARE(PrimitiveText::roundTrip(text), *PrimitiveText::ofCdr(typed.type, typed.cdr));
            QCOMPARE(PrimitiveText::roundTripChanged(text).value_or(text), PrimitiveText::roundTrip(text));
        }
    }

    void jsonToCdr()
    {
        QString error;
        QCOMPARE(noted(fromJson(m_types, u"geometry_msgs/msg/Point"_s, "{\"x\": 1.5, \"y\": -2, \"z\": 0}"),
                       &error),
                 std::optional<QByteArray>(
                     MqttClientRos2::serialize([](Cdr& cdr) { cdr << 1.5 << -2.0 << 0.0; })));
        QVERIFY(!noted(fromJson(m_types, u"geometry_msgs/msg/Point"_s, "[1, 2]"), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(
            !noted(fromJson(m_types, u"geometry_msgs/msg/Point"_s, "{\"w\": 1}"), &error)); // no such field
        // towards MQTT: field by field, byte arrays as numbers
        const QByteArray image = MqttClientRos2::serialize([](Cdr& cdr) {
            cdr << int32_t(5) << uint32_t(6) << std::string("cam") << uint32_t(1) << uint32_t(2)
                << std::string("mono8") << uint8_t(0) << uint32_t(2) << std::vector<uint8_t> {7, 0xff};
        });
        const auto json = noted(toJson(m_types, u"sensor_msgs/msg/Image"_s, image), &error);
        QVERIFY2(json, qPrintable(error));
        const QJsonObject o = QJsonDocument::fromJson(*json).object();
        QCOMPARE(o.value(u"header"_s).toObject().value(u"stamp"_s).toObject().value(u"nanosec"_s).toInt(), 6);
        QCOMPARE(o.value(u"header"_s).toObject().value(u"frame_id"_s).toString(), u"cam"_s);
        QCOMPARE(o.value(u"encoding"_s).toString(), u"mono8"_s);
        QCOMPARE(o.value(u"width"_s).toInt(), 2);
        QCOMPARE(o.value(u"data"_s).toArray(), (QJsonArray {7, 255}));
        QVERIFY(!noted(toJson(m_types, u"sensor_msgs/msg/Image"_s, image.left(20)), &error));
    }
};

QTEST_GUILESS_MAIN(TestRos2BridgeWire)
#include "tst_ros2bridgewire.moc"
