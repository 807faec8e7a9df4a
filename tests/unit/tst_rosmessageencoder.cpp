// SPDX-License-Identifier: MIT
// The ROS 1 encoder against roscpp's own serialization (what mqtt_client sends), round trips
// through the decoder and the YAML a user edits, and values that do not fit.
#include "yaml/yamlvariant.h"
#include "fixtures.h"
#include "resulttext.h"
#include "rosserialize.h"
#include "wire/mqttclientwire.h"
#include "wire/publishpayload.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <QTest>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Duration.h>
#include <std_msgs/Int8MultiArray.h>
#include <std_msgs/String.h>
#include <std_msgs/Time.h>
#include <std_msgs/UInt64.h>

using namespace Qt::StringLiterals;

namespace {
template<typename M> QString typeOf()
{
    return QString::fromLatin1(ros::message_traits::datatype<M>());
}

template<typename M> RosTypeRegistry registryOf()
{
    RosTypeRegistry reg;
    QString error;
    if (!noted(reg.addDefinition(typeOf<M>(), QString::fromLatin1(ros::message_traits::definition<M>())),
               &error))
        qFatal("definition: %s", qPrintable(error));
    return reg;
}

/// roscpp's bytes → decoder → YAML → YamlVariant → encoder: the same bytes again.
template<typename M> void roundTrips(const M& msg)
{
    const RosTypeRegistry reg = registryOf<M>();
    const QByteArray bytes = rosSerialize(msg);
    QString error;
    RosDecodeLimits limits;
    limits.maxArrayElements = 4096;
    const auto value = noted(RosMessageDecoder::decode(reg, typeOf<M>(), bytes, limits), &error);
    QVERIFY2(value, qPrintable(error));
    const auto yaml = RosMessageEncoder::toYaml(*value);
    QVERIFY(yaml);
    const auto tree = noted(YamlVariant::read(yaml->toUtf8()), &error);
    QVERIFY2(tree, qPrintable(error + u'\n' + *yaml));
    const auto encoded = noted(RosMessageEncoder::encode(reg, typeOf<M>(), *tree), &error);
    QVERIFY2(encoded, qPrintable(error + u'\n' + *yaml));
    QCOMPARE(encoded->toHex(), bytes.toHex());
}

QString encodeError(const RosTypeRegistry& reg, const QString& type, const QVariant& value,
                    const RosEncodeLimits& limits = {})
{
    QString error;
    const auto bytes = noted(RosMessageEncoder::encode(reg, type, value, limits), &error);
    return bytes ? u"<encoded %1 bytes>"_s.arg(bytes->size()) : error;
}

QVariant yaml(const char* text)
{
    return YamlVariant::read(QByteArray(text)).valueOr(QVariant());
}
} // namespace

class TestRosMessageEncoder : public QObject
{
    Q_OBJECT
private slots:
    void encodesAsRoscppDoes()
    {
        geometry_msgs::PoseStamped p;
        p.header.seq = 42;
        p.header.stamp = ros::Time(1700000000, 123456789);
        p.header.frame_id = "base_link";
        p.pose.position.x = 4.25;
        p.pose.position.y = -1e-300;
        p.pose.orientation.w = 1;
        const RosTypeRegistry reg = registryOf<geometry_msgs::PoseStamped>();
        QString error;
        const auto bytes
            = noted(RosMessageEncoder::encode(
                        reg, typeOf<geometry_msgs::PoseStamped>(),
                        yaml("header: {seq: 42, stamp: '1700000000.123456789', frame_id: base_link}\n"
                             "pose: {position: {x: 4.25, y: -1e-300}, orientation: {w: 1}}")),
                    &error);
        QVERIFY2(bytes, qPrintable(error));
        QCOMPARE(bytes->toHex(), rosSerialize(p).toHex());

        // JSON is YAML too; a time as {secs, nsecs} as rostopic writes it.
        const auto json
            = noted(RosMessageEncoder::encode(
                        reg, typeOf<geometry_msgs::PoseStamped>(),
                        yaml(R"({"header": {"seq": 42, "stamp": {"secs": 1700000000, "nsecs": 123456789},)"
                             R"( "frame_id": "base_link"}, "pose": {"position": {"x": 4.25, "y": -1e-300},)"
                             R"( "orientation": {"w": 1.0}}})")),
                    &error);
        QVERIFY2(json, qPrintable(error));
        QCOMPARE(json->toHex(), rosSerialize(p).toHex());
    }

    void roundTripsThroughYaml()
    {
        geometry_msgs::PoseStamped p;
        p.header.frame_id = "map \"quoted\"\nsecond line: {x}";
        p.header.stamp = ros::Time(5, 7);
        p.pose.orientation.z = 0.7071067811865476;
        roundTrips(p);

        sensor_msgs::JointState j; // arrays of strings and float64
        j.name = {"shoulder", "elbow", ""};
        j.position = {0.1, -2.5, 1e308};
        j.velocity = {};
        roundTrips(j);

        sensor_msgs::Imu imu; // fixed-length float64[9]
        imu.linear_acceleration_covariance[4] = -0.001;
        imu.orientation_covariance[0] = -1;
        roundTrips(imu);

        sensor_msgs::PointCloud2 cloud; // an array of messages, uint8[] data, bools
        cloud.height = 1;
        cloud.width = 2;
        cloud.fields.resize(2);
        cloud.fields[0].name = "x";
        cloud.fields[0].datatype = 7;
        cloud.fields[0].count = 1;
        cloud.fields[1].name = "intensity";
        cloud.fields[1].offset = 4;
        cloud.is_dense = true;
        cloud.data = {0, 1, 127, 128, 255, 3, 4, 5};
        roundTrips(cloud);

        std_msgs::Int8MultiArray bytes; // signed bytes
        bytes.data = {-128, -1, 0, 127};
        roundTrips(bytes);

        geometry_msgs::PoseArray poses; // nested messages in an array
        poses.poses.resize(3);
        poses.poses[2].position.y = 3.5;
        roundTrips(poses);

        std_msgs::Duration d;
        d.data = ros::Duration(-1, -500000000);
        roundTrips(d);
        std_msgs::Time t;
        t.data = ros::Time(4294967295u, 999999999);
        roundTrips(t);
        std_msgs::UInt64 big;
        big.data = 18446744073709551615ULL;
        roundTrips(big);
        std_msgs::Bool b;
        b.data = true;
        roundTrips(b);
    }

    void missingFieldsAreZero()
    {
        const RosTypeRegistry reg = registryOf<sensor_msgs::Imu>();
        QString error;
        const auto bytes
            = noted(RosMessageEncoder::encode(reg, typeOf<sensor_msgs::Imu>(), QVariant()), &error);
        QVERIFY2(bytes, qPrintable(error));
        QCOMPARE(bytes->toHex(), rosSerialize(sensor_msgs::Imu()).toHex());
        const auto zero = RosMessageEncoder::zeroValue(reg, typeOf<sensor_msgs::Imu>());
        QVERIFY(zero);
        QCOMPARE(zero->find(u"orientation_covariance"_s)->arrayLength, 9u);
    }

    void refusesWhatDoesNotFit_data()
    {
        QTest::addColumn<QString>("type");
        QTest::addColumn<QString>("definition");
        QTest::addColumn<QByteArray>("yaml");
        QTest::addColumn<QString>("error");
        const QString numbers = u"uint8 u8\nint8 i8\nuint32 u32\nint64 i64\nfloat32 f\nbool b\n"
                                u"string s\ntime t\nduration d\nfloat64[3] fixed\nP[] points\n"
                                u"===\nMSG: t/P\nfloat64 x\n"_s;
        const auto row = [&](const char* name, const char* text, const QString& error) {
            QTest::newRow(name) << u"t/N"_s << numbers << QByteArray(text) << error;
        };
        row("uint8 256", "u8: 256", u"u8: 256 does not fit uint8 (0 to 255)"_s);
        row("uint8 negative", "u8: -1", u"u8: -1 does not fit uint8 (0 to 255)"_s);
        row("int8 -129", "i8: -129", u"i8: -129 does not fit int8 (-128 to 127)"_s);
        row("uint32 2^32", "u32: 4294967296", u"u32: 4294967296 does not fit uint32 (0 to 4294967295)"_s);
        row("int64 2^63", "i64: 9223372036854775808",
            u"i64: 9223372036854775808 does not fit int64 (-9223372036854775808 to 9223372036854775807)"_s);
        row("fraction for an integer", "u32: 1.5", u"u32: '1.5' is not a whole number"_s);
        row("float32 too large", "f: 1e39", u"f: 1e+39 does not fit float32"_s);
        row("text for a number", "f: fast", u"f: 'fast' is not a number"_s);
        row("bool 2", "b: 2", u"b: '2' is not true or false"_s);
        row("list for a string", "s: [a]", u"s: needs text, not a list"_s);
        row("map for a number", "i8: {a: 1}", u"i8: needs a whole number, not a map"_s);
        row("negative time", "t: '-1.0'", u"t: a time must lie between 0 and 4294967295 seconds"_s);
        row("time past 2106", "t: 4294967296", u"t: a time must lie between 0 and 4294967295 seconds"_s);
        row("ten decimals", "d: '1.0000000001'",
            u"d: '1.0000000001' is not a time in seconds (sec.nsec, at most nine decimals)"_s);
        row("short fixed array", "fixed: [1, 2]", u"fixed: has 2 elements, the type fixes 3"_s);
        row("unknown field", "speed: 3", u"t/N has no field 'speed'"_s);
        row("unknown nested field", "points: [{x: 1}, {y: 2}]", u"points[1]: t/P has no field 'y'"_s);
        row("scalar for a message", "points: [3]",
            u"points[0]: t/P is a message and needs a map of its fields, not the text '3'"_s);
        row("map for an array", "points: {x: 1}", u"points: an array needs a list, not a map"_s);
    }
    void refusesWhatDoesNotFit()
    {
        QFETCH(QString, type);
        QFETCH(QString, definition);
        QFETCH(QByteArray, yaml);
        QFETCH(QString, error);
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(type, definition));
        const Result<QVariant> tree = YamlVariant::read(yaml);
        QVERIFY(tree);
        QCOMPARE(encodeError(reg, type, *tree), error);
    }

    void wrongKindsFromJsonValues()
    {
        // JSON numbers arrive as numbers, not text: a number is no string.
        const RosTypeRegistry reg = registryOf<std_msgs::String>();
        QCOMPARE(encodeError(reg, u"std_msgs/String"_s, QVariantMap {{u"data"_s, 5}}),
                 u"data: needs text, not a number"_s);
        RosTypeRegistry u8;
        QVERIFY(u8.addDefinition(u"t/U"_s, u"uint8 v\n"_s));
        QCOMPARE(encodeError(u8, u"t/U"_s, QVariantMap {{u"v"_s, 255.5}}),
                 u"v: 255.5 is not a whole number"_s);
        QCOMPARE(encodeError(u8, u"t/U"_s, QVariantMap {{u"v"_s, true}}),
                 u"v: needs a whole number, not a bool"_s);
        QCOMPARE(encodeError(u8, u"t/U"_s, QVariantMap {{u"v"_s, 255}}), u"<encoded 1 bytes>"_s);
    }

    void tooLongOrTooMuchIsAnError()
    {
        const RosTypeRegistry reg = registryOf<std_msgs::String>();
        RosEncodeLimits small;
        small.maxBytes = 100;
        QCOMPARE(encodeError(reg, u"std_msgs/String"_s, QVariantMap {{u"data"_s, QString(200, u'x')}}, small),
                 u"data: the message would pass 100 bytes"_s);
        RosTypeRegistry arrays;
        QVERIFY(arrays.addDefinition(u"t/A"_s, u"float64[] v\nfloat64[100000000] huge\n"_s));
        QVariantList many;
        for (int i = 0; i < 2000; ++i)
            many << i;
        RosEncodeLimits steps;
        steps.maxSteps = 1000;
        QVERIFY(encodeError(arrays, u"t/A"_s, QVariantMap {{u"v"_s, many}}, steps)
                    .contains(u"more than 1000 values"_s));
        // A fixed length no one could fill is refused before any work.
        QCOMPARE(encodeError(arrays, u"t/A"_s, QVariant()),
                 u"huge: 100000000 elements: too many for one message"_s);
        // Recursion through a type's own definition stops at the depth limit.
        RosTypeRegistry self;
        QVERIFY(self.addDefinition(u"t/R"_s, u"R[1] again\n"_s));
        QVERIFY(encodeError(self, u"t/R"_s, QVariant()).contains(u"nested deeper than 32 levels"_s));
    }

    void publishPayloadChecksBeforeSending()
    {
        QString error;
        QCOMPARE(noted(PublishPayload::build(PublishPayload::Format::Text, u"héllo"_s), &error)
                     .value_or(QByteArray()),
                 QByteArray("h\xc3\xa9llo"));
        QCOMPARE(noted(PublishPayload::build(PublishPayload::Format::Json, u"{\"a\": 1}"_s), &error)
                     .value_or(QByteArray()),
                 QByteArray("{\"a\": 1}"));
        QVERIFY(!noted(PublishPayload::build(PublishPayload::Format::Json, u"{\"a\": }"_s), &error));
        QVERIFY2(error.startsWith(u"not JSON: "_s), qPrintable(error));

        // A stamped String, as mqtt_client sends it: the stamp, then the message.
        const auto info
            = MqttClientWire::decodeType(Fixtures::read(u"mqtt_client/wire/string_stamped.type.bin"_s));
        QVERIFY(info && info->stamped);
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(info->name, info->definition));
        const qint64 stamp = 1'700'000'000'250'000'000LL;
        const auto bytes = noted(PublishPayload::build(PublishPayload::Format::RosMessage,
                                                       u"data: hello mqtt"_s, &reg, &*info, stamp),
                                 &error);
        QVERIFY2(bytes, qPrintable(error));
        std_msgs::String s;
        s.data = "hello mqtt";
        QCOMPARE(bytes->toHex(), MqttClientWire::stamped(stamp, rosSerialize(s)).toHex());
        QVERIFY(!noted(
            PublishPayload::build(PublishPayload::Format::RosMessage, u"data: [1]"_s, &reg, &*info), &error));
        QCOMPARE(error, u"not a std_msgs/String: data: needs text, not a list"_s);

        // Prefilled from the captured payload.
        const PublishPayload::Prefill pre = PublishPayload::rosMessage(
            reg, *info, Fixtures::read(u"mqtt_client/wire/string_stamped.payload.bin"_s));
        QCOMPARE(pre.text, u"data: \"hello mqtt\"\n"_s);
        const PublishPayload::Prefill none = PublishPayload::rosMessage(reg, *info, QByteArray());
        QCOMPARE(none.text, u"data: \"\"\n"_s);
    }
};

QTEST_MAIN(TestRosMessageEncoder)
#include "tst_rosmessageencoder.moc"
