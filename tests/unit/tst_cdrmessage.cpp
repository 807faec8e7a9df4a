// SPDX-License-Identifier: MIT
// ROS 2 messages as DDS carries them: CDR after a 4-byte encapsulation header, aligned as CDR
// aligns. The bytes come from eProsima Fast CDR, the serializer of ROS 2's default RMW
// (rmw_fastrtps serializes each member in order with it, as below), in both byte orders, and are
// decoded with the bundled ROS 2 definitions (resources/ros2, compiled in as :/ros2).
#include "resulttext.h"
#include "wire/ros2definitions.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <QTest>

using namespace Qt::StringLiterals;
using eprosima::fastcdr::Cdr;

namespace {

/// Every bundled ROS 2 definition, as the application loads them (from its resources).
RosTypeRegistry ros2Registry()
{
    QStringList errors;
    RosTypeRegistry registry = Ros2Definitions::registry({}, &errors);
    if (!errors.isEmpty())
        qFatal("%s", qPrintable(errors.join(u'\n')));
    return registry;
}

/// Serializes with Fast CDR as rmw_fastrtps does: the encapsulation, then `write`.
template<typename Write> QByteArray fastCdr(Cdr::Endianness endianness, Write write)
{
    static std::vector<char> buffer(1 << 20);
    eprosima::fastcdr::FastBuffer fb(buffer.data(), buffer.size());
    Cdr cdr(fb, endianness, Cdr::DDS_CDR);
    cdr.serialize_encapsulation();
    write(cdr);
    return QByteArray(buffer.data(), qsizetype(cdr.getSerializedDataLength()));
}

void header(Cdr& cdr, int32_t sec, uint32_t nanosec, const std::string& frame)
{
    cdr << sec << nanosec << frame;
}

QString field(const RosValue& v, const QString& path)
{
    const RosValue* f = v.find(path);
    return f ? f->value.toString() : u"<missing %1>"_s.arg(path);
}

} // namespace

class TestCdrMessage : public QObject
{
    Q_OBJECT
    RosTypeRegistry m_registry {RosTypeRegistry::Dialect::Ros2};

private slots:
    void initTestCase()
    {
        m_registry = ros2Registry();
        QVERIFY(m_registry.contains(u"sensor_msgs/msg/PointCloud2"_s));
        QVERIFY(m_registry.contains(u"builtin_interfaces/msg/Time"_s));
    }

    void ros2DefinitionsParse()
    {
        // Header: no seq, time as a message; names resolved to pkg/msg/Type.
        const RosMessageType* h = m_registry.find(u"std_msgs/msg/Header"_s);
        QVERIFY(h);
        QCOMPARE(h->fields.size(), 2);
        QCOMPARE(h->fields[0].type, u"builtin_interfaces/msg/Time"_s);
        const RosMessageType* cloud
            = m_registry.find(u"sensor_msgs/Pointcloud2"_s.replace(u"Pointcloud"_s, u"PointCloud"_s));
        QVERIFY(!cloud); // the registry's names are pkg/msg/Type
        cloud = m_registry.find(RosTypeRegistry::ros2TypeName(u"sensor_msgs/PointCloud2"_s));
        QVERIFY(cloud);
        QCOMPARE(cloud->fields[3].type, u"sensor_msgs/msg/PointField"_s); // a bare name: same package
        // Bounds, defaults and constants.
        RosTypeRegistry r(RosTypeRegistry::Dialect::Ros2);
        QString error;
        QVERIFY2(noted(r.addDefinition(u"demo/Bounded"_s,
                                       u"int32 LIMIT=5\nstring<=10 name \"x\"\nint32[<=5] few\nfloat64[3] "
                                       u"three [1.0, 2.0, 3.0]\n"
                                       "uint8 level 7 # a default\nwstring<=4 wide\n"_s),
                       &error),
                 qPrintable(error));
        const RosMessageType* b = r.find(u"demo/msg/Bounded"_s);
        QVERIFY(b);
        QCOMPARE(b->fields.size(), 5);
        QCOMPARE(b->fields[0].type, u"string"_s);
        QVERIFY(b->fields[1].isArray && b->fields[1].fixedLength == -1);
        QCOMPARE(b->fields[2].fixedLength, 3);
        QCOMPARE(b->fields[3].name, u"level"_s);
        QCOMPARE(b->fields[4].type, u"wstring"_s);
        QVERIFY(!noted(r.addDefinition(u"demo/Bad"_s, u"int32[<=] x\n"_s), &error));
    }

    void stringInBothByteOrders()
    {
        for (const auto endianness : {Cdr::LITTLE_ENDIANNESS, Cdr::BIG_ENDIANNESS}) {
            for (const std::string& text : {std::string("hello, ROS 2"), std::string()}) {
                const QByteArray bytes = fastCdr(endianness, [&](Cdr& cdr) { cdr << text; });
                QString error;
                const auto v
                    = noted(RosMessageDecoder::decodeCdr(m_registry, u"std_msgs/String"_s, bytes), &error);
                QVERIFY2(v, qPrintable(error));
                QCOMPARE(field(*v, u"data"_s), QString::fromStdString(text));
            }
        }
    }

    void poseStampedIsAligned()
    {
        // frame_id of odd length puts the float64s off 8: CDR pads to align them.
        for (const auto endianness : {Cdr::LITTLE_ENDIANNESS, Cdr::BIG_ENDIANNESS}) {
            const QByteArray bytes = fastCdr(endianness, [](Cdr& cdr) {
                header(cdr, 1700000000, 123456789, "base_link"); // 22 bytes: 2 of padding follow
                cdr << 1.5 << -2.25 << 3.0; // position
                cdr << 0.0 << 0.0 << 0.6 << 0.8; // orientation
            });
            QString error;
            const auto v = noted(
                RosMessageDecoder::decodeCdr(m_registry, u"geometry_msgs/msg/PoseStamped"_s, bytes), &error);
            QVERIFY2(v, qPrintable(error));
            QCOMPARE(field(*v, u"header.stamp.sec"_s), u"1700000000"_s);
            QCOMPARE(field(*v, u"header.stamp.nanosec"_s), u"123456789"_s);
            QCOMPARE(field(*v, u"header.frame_id"_s), u"base_link"_s);
            QCOMPARE(v->find(u"pose.position.x"_s)->value.toDouble(), 1.5);
            QCOMPARE(v->find(u"pose.position.y"_s)->value.toDouble(), -2.25);
            QCOMPARE(v->find(u"pose.orientation.w"_s)->value.toDouble(), 0.8);
        }
    }

    void pointCloud2()
    {
        std::vector<uint8_t> data(180000);
        for (std::size_t i = 0; i < data.size(); ++i)
            data[i] = uint8_t(i * 7);
        const QByteArray bytes = fastCdr(Cdr::LITTLE_ENDIANNESS, [&](Cdr& cdr) {
            header(cdr, 12, 34, "lidar_top");
            cdr << uint32_t(1) << uint32_t(15000); // height, width
            cdr << uint32_t(3); // fields
            for (const auto& [name, offset] : {std::pair {"x", 0u}, {"y", 4u}, {"intensity", 8u}})
                cdr << std::string(name) << uint32_t(offset) << uint8_t(7) << uint32_t(1);
            cdr << false << uint32_t(12) << uint32_t(180000);
            cdr << uint32_t(data.size());
            cdr.serializeArray(data.data(), data.size());
            cdr << true;
        });
        QString error;
        const auto v = noted(
            RosMessageDecoder::decodeCdr(m_registry, u"sensor_msgs/msg/PointCloud2"_s, bytes), &error);
        QVERIFY2(v, qPrintable(error));
        QCOMPARE(field(*v, u"header.frame_id"_s), u"lidar_top"_s);
        QCOMPARE(field(*v, u"width"_s), u"15000"_s);
        const RosValue* fields = v->find(u"fields"_s);
        QVERIFY(fields);
        QCOMPARE(fields->arrayLength, 3u);
        QCOMPARE(field(*v, u"fields.[2].name"_s), u"intensity"_s);
        QCOMPARE(field(*v, u"fields.[2].offset"_s), u"8"_s);
        QCOMPARE(field(*v, u"row_step"_s), u"180000"_s);
        QCOMPARE(v->find(u"data"_s)->arrayLength, 180000u);
        QVERIFY(v->find(u"data"_s)->value.toString().startsWith(u"00 07 0e 15"_s));
        QCOMPARE(v->find(u"is_dense"_s)->value.toBool(), true);
    }

    // The encoder writes what Fast CDR writes, byte for byte (rmw_fastrtps, and so mqtt_client for
    // ROS 2): alignment after an odd string, int8 then uint16 then float64, fixed arrays without a
    // length, sequences of messages, a message of no fields as one byte; and decodes back.
    void encoderMatchesFastCdr()
    {
        struct Case
        {
            QString type;
            QVariantMap value;
            QByteArray expected;
        };
        const QVariantMap stamp {{u"sec"_s, 1700000000}, {u"nanosec"_s, 123456789u}};
        QVariantList covariance;
        for (int i = 0; i < 9; ++i)
            covariance << 0.5 * i;
        const QList<Case> cases {
            {u"std_msgs/msg/String"_s,
             {{u"data"_s, u"hello, ROS 2"_s}},
             fastCdr(Cdr::LITTLE_ENDIANNESS, [](Cdr& cdr) { cdr << std::string("hello, ROS 2"); })},
            {u"std_msgs/msg/Empty"_s,
             {},
             fastCdr(Cdr::LITTLE_ENDIANNESS, [](Cdr& cdr) { cdr << uint8_t(0); })},
            {u"geometry_msgs/msg/PoseStamped"_s,
             {{u"header"_s, QVariantMap {{u"stamp"_s, stamp}, {u"frame_id"_s, u"base_link"_s}}},
              {u"pose"_s,
               QVariantMap {{u"position"_s, QVariantMap {{u"x"_s, 1.5}, {u"y"_s, -2.25}, {u"z"_s, 3}}},
                            {u"orientation"_s, QVariantMap {{u"z"_s, 0.6}, {u"w"_s, 0.8}}}}}},
             fastCdr(Cdr::LITTLE_ENDIANNESS,
                     [](Cdr& cdr) {
                         header(cdr, 1700000000, 123456789, "base_link");
                         cdr << 1.5 << -2.25 << 3.0 << 0.0 << 0.0 << 0.6 << 0.8;
                     })},
            {u"sensor_msgs/msg/NavSatFix"_s,
             {{u"header"_s, QVariantMap {{u"stamp"_s, stamp}, {u"frame_id"_s, u"gps"_s}}},
              {u"status"_s, QVariantMap {{u"status"_s, -1}, {u"service"_s, 5}}},
              {u"latitude"_s, 50.78},
              {u"longitude"_s, 6.06},
              {u"altitude"_s, 200.5},
              {u"position_covariance"_s, covariance},
              {u"position_covariance_type"_s, 2}},
             fastCdr(Cdr::LITTLE_ENDIANNESS,
                     [](Cdr& cdr) {
                         header(cdr, 1700000000, 123456789, "gps");
                         cdr << int8_t(-1) << uint16_t(5) << 50.78 << 6.06 << 200.5;
                         for (int i = 0; i < 9; ++i)
                             cdr << 0.5 * i;
                         cdr << uint8_t(2);
                     })},
            {u"std_msgs/msg/Int16MultiArray"_s,
             {{u"layout"_s,
               QVariantMap {
                   {u"dim"_s,
                    QVariantList {QVariantMap {{u"label"_s, u"rows"_s}, {u"size"_s, 2}, {u"stride"_s, 6}},
                                  QVariantMap {{u"label"_s, u"c"_s}, {u"size"_s, 3}, {u"stride"_s, 3}}}},
                   {u"data_offset"_s, 1}}},
              {u"data"_s, QVariantList {-3, 7, 32767, -32768, 0, 1}}},
             fastCdr(Cdr::LITTLE_ENDIANNESS,
                     [](Cdr& cdr) {
                         cdr << uint32_t(2) << std::string("rows") << uint32_t(2) << uint32_t(6)
                             << std::string("c") << uint32_t(3) << uint32_t(3) << uint32_t(1);
                         cdr << uint32_t(6);
                         for (int16_t v : {-3, 7, 32767, -32768, 0, 1})
                             cdr << v;
                     })},
        };
        for (const Case& c : cases) {
            QString error;
            const auto bytes = noted(RosMessageEncoder::encodeCdr(m_registry, c.type, c.value), &error);
            QVERIFY2(bytes, qPrintable(c.type + u": "_s + error));
            QCOMPARE(bytes->toHex(' '), c.expected.toHex(' '));
            const auto back = noted(RosMessageDecoder::decodeCdr(m_registry, c.type, *bytes), &error);
            QVERIFY2(back, qPrintable(c.type + u": "_s + error));
            const auto yaml = RosMessageEncoder::toYaml(*back);
            QVERIFY(yaml);
        }
        // what CDR cannot carry, or the type does not allow, is an error naming the field
        QString error;
        QVERIFY(!noted(RosMessageEncoder::encodeCdr(m_registry, u"std_msgs/msg/String"_s,
                                                    QVariantMap {{u"data"_s, u"a\u0000b"_s}}),
                       &error));
        QVERIFY2(error.contains(u"data"_s) && error.contains(u"NUL"_s), qPrintable(error));
        QVERIFY(!noted(
            RosMessageEncoder::encodeCdr(m_registry, u"sensor_msgs/msg/NavSatFix"_s,
                                         QVariantMap {{u"status"_s, QVariantMap {{u"service"_s, 70000}}}}),
            &error));
        QVERIFY2(error.contains(u"status.service"_s), qPrintable(error));
    }

    void hostileBytesAreErrors()
    {
        QString error;
        const QByteArray good = fastCdr(Cdr::LITTLE_ENDIANNESS, [](Cdr& cdr) { cdr << std::string("ok"); });
        // Not CDR, cut anywhere, or more than padding left over.
        QVERIFY(!noted(RosMessageDecoder::decodeCdr(m_registry, u"std_msgs/msg/String"_s,
                                                    QByteArray("\x00\x07\x00\x00", 4) + good.mid(4)),
                       &error));
        QVERIFY2(error.contains(u"not plain CDR"_s), qPrintable(error));
        for (int cut = 0; cut < good.size(); ++cut)
            QVERIFY(!noted(RosMessageDecoder::decodeCdr(m_registry, u"std_msgs/msg/String"_s, good.left(cut)),
                           &error));
        QVERIFY(
            noted(RosMessageDecoder::decodeCdr(m_registry, u"std_msgs/msg/String"_s, good + QByteArray(3, 0)),
                  &error));
        QVERIFY(!noted(
            RosMessageDecoder::decodeCdr(m_registry, u"std_msgs/msg/String"_s, good + QByteArray(4, 0)),
            &error));
        // A sequence claiming 4 billion PointFields fails at once, not after 4 billion tries.
        const QByteArray huge = fastCdr(Cdr::LITTLE_ENDIANNESS, [](Cdr& cdr) {
            header(cdr, 0, 0, "");
            cdr << uint32_t(1) << uint32_t(1) << uint32_t(0xffffffffu);
        });
        QVERIFY(
            !noted(RosMessageDecoder::decodeCdr(m_registry, u"sensor_msgs/msg/PointCloud2"_s, huge), &error));
        QVERIFY2(error.contains(u"claims"_s), qPrintable(error));
        QVERIFY(RosMessageDecoder::lastSteps() < 100);
        // An unknown type and a wstring say so.
        QVERIFY(!noted(RosMessageDecoder::decodeCdr(m_registry, u"nav_msgs/msg/Odometry"_s, good), &error));
        QVERIFY(error.contains(u"nav_msgs/msg/Odometry"_s));
        RosTypeRegistry r(RosTypeRegistry::Dialect::Ros2);
        QVERIFY(r.addDefinition(u"demo/Wide"_s, u"wstring text\n"_s));
        QVERIFY(!noted(RosMessageDecoder::decodeCdr(r, u"demo/Wide"_s, good), &error));
        QVERIFY2(error.contains(u"wstring"_s), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestCdrMessage)
#include "tst_cdrmessage.moc"
