// SPDX-License-Identifier: MIT
// The generic ROS 1 decoder against bytes that roscpp itself serialized and against what the real
// mqtt_client v2.2.1 put on the broker.
#include "fixtures.h"
#include "resulttext.h"
#include "rosserialize.h"
#include "wire/mqttclientwire.h"
#include "wire/primitivetext.h"
#include "wire/rosmessage.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <QtEndian>
#include <QTest>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Char.h>
#include <std_msgs/Duration.h>
#include <std_msgs/Float32.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>
#include <std_msgs/Int64.h>
#include <std_msgs/Int8.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt64.h>

using namespace Qt::StringLiterals;

namespace {
template<typename M> RosValue decode(const M& msg, const RosDecodeLimits& limits = {})
{
    RosTypeRegistry reg;
    const QString type = QString::fromLatin1(ros::message_traits::datatype<M>());
    QString error;
    if (!noted(reg.addDefinition(type, QString::fromLatin1(ros::message_traits::definition<M>())), &error))
        qFatal("definition: %s", qPrintable(error));
    const auto v = noted(RosMessageDecoder::decode(reg, type, rosSerialize(msg), limits), &error);
    if (!v)
        qFatal("decode: %s", qPrintable(error));
    return *v;
}

QString at(const RosValue& v, const QString& path)
{
    const RosValue* f = v.find(path);
    return f ? f->value.toString() : u"<missing %1>"_s.arg(path);
}
} // namespace

class TestRosMessage : public QObject
{
    Q_OBJECT
private slots:
    // Issue 45: a primitive link's ROS 1 end is matched by the text mqtt_client (up to 2.3) sends for
    // the message, std::to_string of its data (String its data, Bool "true"/"false").
    void primitiveTextAsMqttClientWritesIt()
    {
        const auto text = [](const char* type, const QByteArray& bytes) {
            return PrimitiveText::ofRos1(QString::fromLatin1(type), bytes).value_or("(none)");
        };
        std_msgs::String s;
        s.data = "hi there";
        QCOMPARE(text("std_msgs/String", rosSerialize(s)), QByteArray("hi there"));
        std_msgs::Bool b;
        b.data = true;
        QCOMPARE(text("std_msgs/Bool", rosSerialize(b)), QByteArray("true"));
        std_msgs::Int8 i8;
        i8.data = -5;
        QCOMPARE(text("std_msgs/Int8", rosSerialize(i8)), QByteArray(std::to_string(i8.data).c_str()));
        std_msgs::Char c;
        c.data = 200;
        QCOMPARE(text("std_msgs/Char", rosSerialize(c)), QByteArray(std::to_string(c.data).c_str()));
        std_msgs::Int64 i64;
        i64.data = -7000000000000LL;
        QCOMPARE(text("std_msgs/Int64", rosSerialize(i64)), QByteArray(std::to_string(i64.data).c_str()));
        std_msgs::UInt64 u64;
        u64.data = ~0ULL;
        QCOMPARE(text("std_msgs/UInt64", rosSerialize(u64)), QByteArray(std::to_string(u64.data).c_str()));
        for (const float v : {2.5f, 0.1f, -1e10f, 123456.789f}) {
            std_msgs::Float32 f;
            f.data = v;
            QCOMPARE(text("std_msgs/Float32", rosSerialize(f)), QByteArray(std::to_string(f.data).c_str()));
        }
        std_msgs::Float64 d;
        d.data = 0.8444218515250481;
        QCOMPARE(text("std_msgs/Float64", rosSerialize(d)), QByteArray(std::to_string(d.data).c_str()));
        // Not a primitive, a byte array (mqtt_client for ROS 1 has none), too short or too long.
        QCOMPARE(text("std_msgs/Duration", QByteArray(8, '\0')), QByteArray("(none)"));
        QCOMPARE(text("std_msgs/UInt8MultiArray", QByteArray(12, '\0')), QByteArray("(none)"));
        QCOMPARE(text("std_msgs/Int32", QByteArray(3, '\0')), QByteArray("(none)"));
        QCOMPARE(text("std_msgs/Int32", QByteArray(5, '\0')), QByteArray("(none)"));
        QCOMPARE(text("std_msgs/String", rosSerialize(s).chopped(1)), QByteArray("(none)"));
    }

    void decodesWhatMqttClientSent_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("type");
        QTest::addColumn<bool>("stamped");
        QTest::addColumn<QStringList>("lines");
        QTest::newRow("header") << u"header"_s << u"std_msgs/Header"_s << false
                                << QStringList {u"seq: 7"_s, u"stamp: 1700000000.123456789"_s,
                                                u"frame_id: \"lidar\""_s};
        QTest::newRow("pose") << u"pose"_s << u"geometry_msgs/PoseStamped"_s << false
                              << QStringList {u"header:"_s,
                                              // The capture's README says seq 1; the bytes say 3.
                                              u"  seq: 3"_s, u"  stamp: 1700000001.000000005"_s,
                                              u"  frame_id: \"map\""_s, u"pose:"_s, u"  position:"_s,
                                              u"    x: 1.5"_s, u"    y: -2.25"_s, u"    z: 0.125"_s,
                                              u"  orientation:"_s, u"    x: 0"_s, u"    y: 0"_s,
                                              u"    z: 0.7071067811865476"_s, u"    w: 0.7071067811865476"_s};
        QTest::newRow("string, stamped")
            << u"string_stamped"_s << u"std_msgs/String"_s << true << QStringList {u"data: \"hello mqtt\""_s};
    }
    void decodesWhatMqttClientSent()
    {
        QFETCH(QString, name);
        QFETCH(QString, type);
        QFETCH(bool, stamped);
        QFETCH(QStringList, lines);
        const QByteArray typeBytes = Fixtures::read(u"mqtt_client/wire/%1.type.bin"_s.arg(name));
        QString error;
        const auto info = noted(MqttClientWire::decodeType(typeBytes), &error);
        QVERIFY2(info, qPrintable(error));
        QCOMPARE(info->name, type);
        QCOMPARE(info->stamped, stamped);
        QCOMPARE(info->md5.size(), 32);
        // Encoding it again gives the captured bytes.
        QCOMPARE(MqttClientWire::encodeType(*info), typeBytes);

        QByteArray payload = Fixtures::read(u"mqtt_client/wire/%1.payload.bin"_s.arg(name));
        if (stamped) {
            const auto split = MqttClientWire::splitStamped(payload);
            QVERIFY(split);
            QVERIFY(split->stampNs > 1'600'000'000'000'000'000LL); // a wall-clock stamp of our era
            QCOMPARE(MqttClientWire::stamped(split->stampNs, split->message), payload);
            payload = split->message;
        }
        RosTypeRegistry reg;
        QVERIFY2(noted(reg.addDefinition(info->name, info->definition), &error), qPrintable(error));
        const auto value = noted(RosMessageDecoder::decode(reg, info->name, payload), &error);
        QVERIFY2(value, qPrintable(error));
        QCOMPARE(value->toLines(), lines);
    }

    void md5OfKnownTypesMatches()
    {
        // mqtt_client sends the md5 roscpp knows for the type.
        const auto pose = MqttClientWire::decodeType(Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s));
        QCOMPARE(pose->md5, QString::fromLatin1(ros::message_traits::md5sum<geometry_msgs::PoseStamped>()));
        QCOMPARE(pose->definition,
                 QString::fromLatin1(ros::message_traits::definition<geometry_msgs::PoseStamped>()));
    }

    void decodesStdMsgs()
    {
        std_msgs::String s;
        s.data = "grüße";
        QCOMPARE(at(decode(s), u"data"_s), u"grüße"_s);
        // A leading byte-order mark is part of the value (QString::fromUtf8 alone drops it).
        s.data = "\xef\xbb\xbf\xef\xbb\xbfx";
        QCOMPARE(at(decode(s), u"data"_s), u"\ufeff\ufeffx"_s);

        std_msgs::Float64MultiArray a;
        a.layout.dim.resize(1);
        a.layout.dim[0].label = "x";
        a.layout.dim[0].size = 3;
        a.layout.dim[0].stride = 3;
        a.data = {1.0, -2.5, 3.25};
        const RosValue v = decode(a);
        QCOMPARE(at(v, u"layout.dim.[0].label"_s), u"x"_s);
        QCOMPARE(v.find(u"data"_s)->arrayLength, 3u);
        QCOMPARE(at(v, u"data.[1]"_s), u"-2.5"_s);

        std_msgs::Duration d;
        d.data = ros::Duration(-1, -500000000);
        QCOMPARE(at(decode(d), u"data"_s), u"-1.500000000"_s);
    }

    void decodesGeometryMsgs()
    {
        geometry_msgs::PoseWithCovarianceStamped p;
        p.header.seq = 42;
        p.header.stamp = ros::Time(12, 34);
        p.header.frame_id = "odom";
        p.pose.pose.position.x = 3;
        for (int i = 0; i < 36; ++i)
            p.pose.covariance[i] = i * 0.5;
        RosDecodeLimits all;
        all.maxArrayElements = 64;
        const RosValue v = decode(p, all);
        QCOMPARE(at(v, u"header.seq"_s), u"42"_s);
        QCOMPARE(at(v, u"header.stamp"_s), u"12.000000034"_s);
        QCOMPARE(at(v, u"pose.pose.position.x"_s), u"3"_s);
        const RosValue* cov = v.find(u"pose.covariance"_s);
        QCOMPARE(cov->arrayLength, 36u);
        QCOMPARE(cov->type, u"float64[36]"_s);
        QCOMPARE(at(v, u"pose.covariance.[35]"_s), u"17.5"_s);
    }

    void decodesSensorMsgs()
    {
        sensor_msgs::JointState js;
        js.name = {"shoulder", "elbow"};
        js.position = {0.1, 0.2};
        js.velocity = {};
        const RosValue j = decode(js);
        QCOMPARE(at(j, u"name.[1]"_s), u"elbow"_s);
        QCOMPARE(j.find(u"velocity"_s)->arrayLength, 0u);

        sensor_msgs::Imu imu;
        imu.linear_acceleration.z = 9.81;
        imu.orientation_covariance[8] = -1;
        const RosValue i = decode(imu);
        QCOMPARE(at(i, u"linear_acceleration.z"_s), u"9.81"_s);

        // A large point cloud: the blob is summarised, the fields after it still decode.
        sensor_msgs::PointCloud2 pc;
        pc.height = 1;
        pc.width = 62500;
        pc.fields.resize(3);
        pc.fields[0].name = "x";
        pc.fields[0].datatype = sensor_msgs::PointField::FLOAT32;
        pc.fields[0].count = 1;
        pc.fields[1].name = "y";
        pc.fields[2].name = "z";
        pc.point_step = 16;
        pc.row_step = 16 * 62500;
        pc.data.assign(1'000'000, 0xab);
        pc.is_dense = true;
        const RosValue c = decode(pc);
        const RosValue* data = c.find(u"data"_s);
        QCOMPARE(data->arrayLength, 1'000'000u);
        QVERIFY(data->truncated);
        QVERIFY(data->value.toString().startsWith(u"ab ab ab"_s));
        QCOMPARE(at(c, u"is_dense"_s), u"true"_s);
        QCOMPARE(at(c, u"fields.[2].name"_s), u"z"_s);
    }

    void largeArraysOfMessagesAreSkippedNotRead()
    {
        // 100,000 poses: only the first few become values; the rest is stepped over by size.
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(
            u"test/Many"_s,
            u"geometry_msgs/Point[] points\nstring tail\n"
            "================================================================================\n"
            "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n"_s));
        QCOMPARE(reg.fixedSize(u"geometry_msgs/Point"_s), 24);
        QByteArray bytes;
        QDataStream out(&bytes, QIODevice::WriteOnly);
        out.setByteOrder(QDataStream::LittleEndian);
        out << quint32(100000);
        bytes.append(QByteArray(100000 * 24, '\0'));
        QDataStream tail(&bytes, QIODevice::Append);
        tail.setByteOrder(QDataStream::LittleEndian);
        tail << quint32(3);
        bytes.append("end");
        const auto v = RosMessageDecoder::decode(reg, u"test/Many"_s, bytes);
        QVERIFY(v);
        QCOMPARE(v->find(u"points"_s)->children.size(), 16);
        QCOMPARE(v->find(u"tail"_s)->value.toString(), u"end"_s);
    }

    void malformedInputGivesAnErrorNotACrash_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        QTest::newRow("empty") << QByteArray() << u"byte 0"_s;
        QTest::newRow("truncated string")
            << QByteArray("\x07\x00\x00\x00\x00\xf1\x53\x65\x15\xcd\x5b\x07\xff\xff\xff\x7f", 16)
            << u"frame_id"_s;
        QTest::newRow("trailing bytes")
            << Fixtures::read(u"mqtt_client/wire/header.payload.bin"_s) + "x" << u"left over"_s;
    }
    void malformedInputGivesAnErrorNotACrash()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const auto info = MqttClientWire::decodeType(Fixtures::read(u"mqtt_client/wire/header.type.bin"_s));
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(info->name, info->definition));
        QString error;
        QVERIFY(!noted(RosMessageDecoder::decode(reg, info->name, bytes), &error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }

    void malformedTypeAnnouncementsAreRejected_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        const QByteArray good = Fixtures::read(u"mqtt_client/wire/pose.type.bin"_s);
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("cut") << good.left(100);
        QTest::newRow("huge length") << QByteArray("\xff\xff\xff\xff", 4) + good;
        QTest::newRow("extra byte") << good + "x";
        QTest::newRow("text") << QByteArray("geometry_msgs/PoseStamped");
    }
    void malformedTypeAnnouncementsAreRejected()
    {
        QFETCH(QByteArray, bytes);
        QString error;
        QVERIFY(!noted(MqttClientWire::decodeType(bytes), &error));
        QVERIFY(!error.isEmpty());
    }

    void malformedDefinitionsAreRejected()
    {
        RosTypeRegistry reg;
        QString error;
        QVERIFY(!noted(reg.addDefinition(u"a/B"_s, u"int32[x] bad\n"_s), &error));
        QVERIFY(error.contains(u"line 1"_s));
        QVERIFY(!noted(reg.addDefinition(u"a/B"_s, u"int32 ok\n=====\nnot a header\n"_s), &error));
        // Constants are not on the wire; comments are ignored.
        QVERIFY(noted(reg.addDefinition(u"a/C"_s, u"int32 X=3 # three\nstring S=a#b\nuint8 v # value\n"_s),
                      &error));
        QCOMPARE(reg.find(u"a/C"_s)->fields.size(), 1);
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"a/Missing"_s, QByteArray(4, 0)), &error));
    }
    // Regression (issue 11, item 4): a retained announcement of "Inner[] items" whose Inner takes no
    // bytes, and the payload ff ff ff ff, made the decoder step over 4.3e9 empty elements.
    void arraysOfEmptyElementsCostNoLoop()
    {
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(
            u"pkg/Outer"_s,
            u"Inner[] items\n"
            "================================================================================\n"
            "MSG: pkg/Inner\nstring[0] s\n"_s));
        QCOMPARE(reg.fixedSize(u"pkg/Inner"_s), 0);
        QCOMPARE(reg.minSize(u"pkg/Inner"_s), 0);
        for (const int shown : {1, 16}) {
            RosDecodeLimits limits;
            limits.maxArrayElements = shown;
            QString error;
            const auto v = noted(
                RosMessageDecoder::decode(reg, u"pkg/Outer"_s, QByteArray(4, '\xff'), limits), &error);
            QVERIFY2(v, qPrintable(error));
            QCOMPARE(v->find(u"items"_s)->arrayLength, 0xffffffffu);
            QCOMPARE(v->find(u"items"_s)->children.size(), shown);
            QVERIFY(RosMessageDecoder::lastSteps() < 100);
        }
    }

    void hostileLengthsFailBeforeTheLoop_data()
    {
        QTest::addColumn<QString>("definition");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        // Strings take at least their 4-byte length: 4e9 of them cannot follow 4 bytes.
        QTest::newRow("strings") << u"string[] names"_s << QByteArray(4, '\xff')
                                 << u"claims 4294967295 elements"_s;
        QTest::newRow("messages of strings") << u"Item[] items\n===\nMSG: pkg/Item\nstring a\nuint8 b\n"_s
                                             << QByteArray(4, '\xff') << u"at least 5 bytes"_s;
        QTest::newRow("fixed array of messages of strings")
            << u"Item[4000000000] items\n===\nMSG: pkg/Item\nstring a\n"_s << QByteArray(8, '\0')
            << u"claims 4000000000 elements"_s;
        // A type that contains itself has no finite value.
        QTest::newRow("recursive elements")
            << u"Node[] nodes\n===\nMSG: pkg/Node\nNode next\n"_s << QByteArray(4, '\xff') << u"claims"_s;
        QTest::newRow("recursive field")
            << u"Node n\n===\nMSG: pkg/Node\nNode next\n"_s << QByteArray(64, '\0') << u"nested deeper"_s;
        // 16 elements shown per level of empty messages: 16^8 values from 0 bytes.
        QString nest;
        for (int i = 0; i < 8; ++i)
            nest += u"L%1[16] a\n===\nMSG: pkg/L%1\n"_s.arg(i);
        nest += u"uint8[0] end\n"_s;
        QTest::newRow("nested empty arrays") << nest << QByteArray() << u"more than 50000 values"_s;
        // Elements of at least one byte each, 1,000,001 of them: bytes alone would allow it.
        QByteArray many(4, '\0');
        qToLittleEndian<quint32>(1000001, many.data());
        many += QByteArray(1000001 * 5, '\0');
        QTest::newRow("many small elements") << u"Item[] items\n===\nMSG: pkg/Item\nuint8 a\nuint8[] b\n"_s
                                             << many << u"more than 1000000 steps"_s;
    }
    void hostileLengthsFailBeforeTheLoop()
    {
        QFETCH(QString, definition);
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        RosTypeRegistry reg;
        QString error;
        QVERIFY2(noted(reg.addDefinition(u"pkg/Top"_s, definition), &error), qPrintable(error));
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"pkg/Top"_s, bytes), &error));
        QVERIFY2(error.contains(expected), qPrintable(error));
        QVERIFY(RosMessageDecoder::lastSteps() <= RosDecodeLimits().maxSteps + 1);
    }

    void workBudgetsAreLimits()
    {
        RosTypeRegistry reg;
        QVERIFY(reg.addDefinition(u"pkg/Names"_s, u"string[] names\n"_s));
        QByteArray bytes;
        QDataStream out(&bytes, QIODevice::WriteOnly);
        out.setByteOrder(QDataStream::LittleEndian);
        out << quint32(1000);
        for (int i = 0; i < 1000; ++i)
            out << quint32(0);
        QVERIFY(RosMessageDecoder::decode(reg, u"pkg/Names"_s, bytes));
        RosDecodeLimits limits;
        limits.maxSteps = 500;
        QString error;
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"pkg/Names"_s, bytes, limits), &error));
        QVERIFY2(error.contains(u"more than 500 steps"_s), qPrintable(error));
        limits = {};
        limits.maxBytes = 100;
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"pkg/Names"_s, bytes, limits), &error));
        QVERIFY2(error.contains(u"4004 bytes"_s), qPrintable(error));
    }

    // Sizes are 64-bit and saturate: 16 bytes times 2^30 wrapped to 0 in an int.
    void hostileDefinitionsAreSizedWithoutOverflow()
    {
        RosTypeRegistry reg;
        QString error;
        QVERIFY2(noted(reg.addDefinition(u"pkg/Wrap"_s,
                                         u"Pair[1073741824] x\n===\nMSG: pkg/Pair\nfloat64 a\nfloat64 b\n"_s),
                       &error),
                 qPrintable(error));
        QCOMPARE(reg.fixedSize(u"pkg/Wrap"_s), qint64(1) << 34);
        QVERIFY2(noted(reg.addDefinition(u"pkg/Huge"_s,
                                         u"float64[4294967295] a\nHuge2[4294967295] b\n===\n"
                                         "MSG: pkg/Huge2\nfloat64[4294967295] c\n"_s),
                       &error),
                 qPrintable(error));
        QCOMPARE(reg.fixedSize(u"pkg/Huge"_s), RosTypeRegistry::kHugeSize);
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"pkg/Huge"_s, QByteArray(64, '\0')), &error));
        QVERIFY2(error.contains(u"ends while reading"_s) || error.contains(u"claims"_s), qPrintable(error));
        // Lengths beyond a uint32, signs and spaces are not array lengths.
        for (const QString& bad : {u"int32[-1] x"_s, u"int32[4294967296] x"_s, u"int32[+3] x"_s})
            QVERIFY2(!noted(reg.addDefinition(u"pkg/Bad"_s, bad), &error), qPrintable(bad));
        // A chain of 100,000 dependencies: sized without recursing 100,000 deep.
        QString chain;
        for (int i = 0; i < 100000; ++i)
            chain += u"T%1 a\n===\nMSG: pkg/T%1\n"_s.arg(i + 1);
        chain += u"uint8 end\n"_s;
        QVERIFY(noted(reg.addDefinition(u"pkg/T0"_s, chain), &error));
        QCOMPARE(reg.fixedSize(u"pkg/T0"_s), -1);
        QVERIFY(reg.minSize(u"pkg/T0"_s) >= 0);
        QVERIFY(!noted(RosMessageDecoder::decode(reg, u"pkg/T0"_s, QByteArray(1, '\0')), &error));
        QVERIFY2(error.contains(u"nested deeper"_s), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestRosMessage)
#include "tst_rosmessage.moc"
