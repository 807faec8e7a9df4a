// SPDX-License-Identifier: MIT
// The pure parts of ROS 2 on the wire: REP 2008 names, QoS compatibility, ros_discovery_info read
// from bytes Fast CDR writes as rmw_dds_common does (both Gid layouts, hostile lengths), the graph
// built from endpoints and node announcements, and the bundled definitions.
#include "ros2/ros2graph.h"
#include "ros2/ros2names.h"
#include "wire/ros2definitions.h"

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

using namespace Qt::StringLiterals;
using eprosima::fastcdr::Cdr;

namespace {

struct Node
{
    std::string ns, name;
    std::vector<QByteArray> readers, writers;
};

QByteArray gid(int participant, int entity)
{
    QByteArray g(16, '\0');
    g[0] = char(0x01);
    g[1] = char(0x0f);
    g[11] = char(participant);
    g[13] = char(entity >> 16);
    g[14] = char(entity >> 8);
    g[15] = char(entity);
    return g;
}

/// rmw_dds_common/msg/ParticipantEntitiesInfo as Fast CDR writes it: Gid is `uint8[gidSize]`
/// (24 in Humble, 16 from Iron), sequences are a uint32 count then their elements.
QByteArray infoBytes(Cdr::Endianness endianness, int gidSize, const QByteArray& participant,
                     const std::vector<Node>& nodes)
{
    static std::vector<char> buffer(1 << 16);
    eprosima::fastcdr::FastBuffer fb(buffer.data(), buffer.size());
    Cdr cdr(fb, endianness, Cdr::DDS_CDR);
    cdr.serialize_encapsulation();
    auto writeGid = [&](const QByteArray& g) {
        for (int i = 0; i < gidSize; ++i)
            cdr << uint8_t(i < g.size() ? uchar(g[i]) : 0);
    };
    writeGid(participant);
    cdr << uint32_t(nodes.size());
    for (const Node& n : nodes) {
        cdr << n.ns << n.name;
        for (const auto* list : {&n.readers, &n.writers}) {
            cdr << uint32_t(list->size());
            for (const QByteArray& g : *list)
                writeGid(g);
        }
    }
    return QByteArray(buffer.data(), qsizetype(cdr.getSerializedDataLength()));
}

Ros2Endpoint endpoint(const QByteArray& g, const QString& topic, const QString& type, bool pub)
{
    Ros2Endpoint e;
    e.gid = g;
    e.topic = topic;
    e.type = type;
    e.publisher = pub;
    return e;
}

} // namespace

class TestRos2Graph : public QObject
{
    Q_OBJECT
private slots:
    void names()
    {
        QString name;
        QCOMPARE(Ros2Names::classifyDdsTopic(u"rt/chatter"_s, &name), Ros2Names::TopicKind::Topic);
        QCOMPARE(name, u"/chatter"_s);
        QCOMPARE(Ros2Names::classifyDdsTopic(u"rt/robot1/odom"_s, &name), Ros2Names::TopicKind::Topic);
        QCOMPARE(name, u"/robot1/odom"_s);
        QCOMPARE(Ros2Names::classifyDdsTopic(u"rq/add_two_intsRequest"_s, &name),
                 Ros2Names::TopicKind::ServiceRequest);
        QCOMPARE(name, u"/add_two_ints"_s);
        QCOMPARE(Ros2Names::classifyDdsTopic(u"rr/add_two_intsReply"_s, &name),
                 Ros2Names::TopicKind::ServiceReply);
        QCOMPARE(name, u"/add_two_ints"_s);
        QCOMPARE(Ros2Names::classifyDdsTopic(u"ros_discovery_info"_s, &name), Ros2Names::TopicKind::Other);
        QCOMPARE(Ros2Names::classifyDdsTopic(u"rt/"_s, &name), Ros2Names::TopicKind::Other);
        QCOMPARE(Ros2Names::ddsTopic(u"/chatter"_s), u"rt/chatter"_s);
        QCOMPARE(Ros2Names::ddsTopic(u"a/b"_s), u"rt/a/b"_s);

        QCOMPARE(Ros2Names::rosType(u"std_msgs::msg::dds_::String_"_s), u"std_msgs/msg/String"_s);
        QCOMPARE(Ros2Names::rosType(u"example_interfaces::srv::dds_::AddTwoInts_Request_"_s),
                 u"example_interfaces/srv/AddTwoInts_Request"_s);
        QCOMPARE(Ros2Names::rosType(u"HelloWorld"_s), u"HelloWorld"_s); // plain DDS: as it is
        QCOMPARE(Ros2Names::rosType(u"a::b::c::D_"_s), u"a::b::c::D_"_s);
        QCOMPARE(Ros2Names::ddsType(u"std_msgs/msg/String"_s), u"std_msgs::msg::dds_::String_"_s);
        QCOMPARE(Ros2Names::ddsType(u"std_msgs/String"_s), u"std_msgs::msg::dds_::String_"_s);
        QCOMPARE(Ros2Names::ddsType(u"String"_s), QString());
        QCOMPARE(Ros2Names::ddsType(u"a//b"_s), QString());
    }

    void qosCompatibility()
    {
        Ros2Qos reliable, bestEffort, latched;
        bestEffort.reliability = Ros2Qos::BestEffort;
        latched.durability = Ros2Qos::TransientLocal;
        QString why;
        QVERIFY(ros2QosCompatible(reliable, bestEffort));
        QVERIFY(!ros2QosCompatible(bestEffort, reliable, &why));
        QVERIFY2(why.contains(u"reliable"_s), qPrintable(why));
        QVERIFY(ros2QosCompatible(latched, reliable));
        QVERIFY(!ros2QosCompatible(reliable, latched, &why));
        QVERIFY2(why.contains(u"transient local"_s), qPrintable(why));
        latched.depth = 1;
        QCOMPARE(latched.text(), u"reliable, transient local, depth 1"_s);
    }

    void discoveryInfo_data()
    {
        QTest::addColumn<int>("gidSize");
        QTest::addColumn<bool>("littleEndian");
        QTest::newRow("Humble, little-endian") << 24 << true;
        QTest::newRow("Humble, big-endian") << 24 << false;
        QTest::newRow("Jazzy, little-endian") << 16 << true;
    }
    void discoveryInfo()
    {
        QFETCH(int, gidSize);
        QFETCH(bool, littleEndian);
        const std::vector<Node> nodes {{"/", "talker", {}, {gid(1, 3)}},
                                       {"/robot1", "listener", {gid(1, 4), gid(1, 7)}, {}}};
        const QByteArray bytes = infoBytes(littleEndian ? Cdr::LITTLE_ENDIANNESS : Cdr::BIG_ENDIANNESS,
                                           gidSize, gid(1, 0xc1), nodes);
        const auto info = Ros2DiscoveryInfo::parse(bytes);
        QVERIFY2(info, qPrintable(info.error().toString()));
        QCOMPARE(info->gid, gid(1, 0xc1));
        QCOMPARE(info->nodes.size(), 2);
        QCOMPARE(info->nodes[0].fullName(), u"/talker"_s);
        QCOMPARE(info->nodes[0].writers, QList<QByteArray>({gid(1, 3)}));
        QCOMPARE(info->nodes[1].fullName(), u"/robot1/listener"_s);
        QCOMPARE(info->nodes[1].readers, QList<QByteArray>({gid(1, 4), gid(1, 7)}));
    }

    void hostileDiscoveryInfo()
    {
        const QByteArray good
            = infoBytes(Cdr::LITTLE_ENDIANNESS, 24, gid(1, 0xc1), {{"/", "talker", {}, {gid(1, 3)}}});
        QString error;
        // no truncation reads past the end or yields the node; one is ambiguous by nature: 4 + 24
        // bytes of a Humble sample (its Gid's zero tail as the node count) read as a Jazzy one without nodes
        for (int n = 0; n < good.size() - 3; ++n) {
            const auto cut = Ros2DiscoveryInfo::parse(good.left(n));
            QVERIFY2(!cut || (n >= 4 + 16 + 4 && n <= 4 + 16 + 4 + 3 && cut->nodes.isEmpty()),
                     qPrintable(QString::number(n)));
            if (!cut)
                error = cut.error().toString();
        }
        QVERIFY(!error.isEmpty());
        // a node count of four billion in 40 bytes: refused before anything is allocated
        QByteArray huge = good;
        huge[4 + 24] = char(0xff);
        huge[4 + 25] = char(0xff);
        huge[4 + 26] = char(0xff);
        huge[4 + 27] = char(0xff);
        QVERIFY(!Ros2DiscoveryInfo::parse(huge));
        // not CDR at all
        QVERIFY(!Ros2DiscoveryInfo::parse("\x00\x07\x00\x00garbage"));
        // a node name longer than rmw's 256
        const std::string longName(300, 'n');
        QVERIFY(!Ros2DiscoveryInfo::parse(
            infoBytes(Cdr::LITTLE_ENDIANNESS, 24, gid(1, 0xc1), {{"/", longName, {}, {}}})));
        // trailing garbage beyond alignment padding
        QVERIFY(!Ros2DiscoveryInfo::parse(good + QByteArray(16, 'x')));
    }

    // Issue 41: one participant announcing 100,000 endpoints on one topic, each of a type of its
    // own. The old build looked each type up in the topic's list (quadratic: minutes, past the
    // parent's 10 s watchdog, again after every restart); now a topic keeps at most 16 types and
    // 10,000 endpoints, the rest counted, in well under a second, and the other topics stay listed.
    void aFloodOfTypesOnOneTopicIsBoundedAndFast()
    {
        QList<Ros2Endpoint> endpoints;
        for (int i = 0; i < 100'000; ++i)
            endpoints.append(endpoint(gid(7, i), u"/flood"_s, u"flood_msgs/msg/T%1"_s.arg(i), i % 2 == 0));
        endpoints.append(endpoint(gid(1, 1), u"/chatter"_s, u"std_msgs/msg/String"_s, true));
        QElapsedTimer timer;
        timer.start();
        const Ros2Graph g = Ros2Graph::build(endpoints, {}, 2);
        const qint64 ms = timer.elapsed();
        QVERIFY2(ms < 3000, qPrintable(u"%1 ms"_s.arg(ms)));
        const Ros2Topic* flood = g.topic(u"/flood"_s);
        QVERIFY(flood);
        QCOMPARE(flood->types.size(), 16);
        QCOMPARE(flood->publishers.size() + flood->subscribers.size(), 16);
        QCOMPARE(g.omitted, quint64(100'000 - 16));
        const Ros2Topic* chatter = g.topic(u"/chatter"_s);
        QVERIFY(chatter);
        QCOMPARE(chatter->publishers.size(), 1);

        // of one type, a topic keeps 10,000 endpoints
        QList<Ros2Endpoint> same;
        for (int i = 0; i < 12'000; ++i)
            same.append(endpoint(gid(7, i), u"/flood"_s, u"std_msgs/msg/String"_s, true));
        const Ros2Graph h = Ros2Graph::build(same, {}, 1);
        QCOMPARE(h.topic(u"/flood"_s)->publishers.size(), 10'000);
        QCOMPARE(h.omitted, quint64(2'000));
    }

    // Names and types are checked before they reach DDS (issue 41: a 70,000-character type name
    // from a retained MQTT announcement crashed Cyclone in dds_create_writer).
    void typeAndTopicNamesAreCheckedBeforeDds()
    {
        for (const QString& ok : {u"std_msgs/msg/String"_s, u"geometry_msgs/msg/PoseStamped"_s,
                                  u"std_msgs/String"_s, u"a/msg/B_2"_s})
            QVERIFY2(Ros2Names::isValidType(ok), qPrintable(ok));
        QString why;
        QVERIFY(!Ros2Names::isValidType(u"a"_s.repeated(70'000) + u"/msg/T"_s, &why));
        QVERIFY2(why.contains(u"70006 characters (at most 255)"_s), qPrintable(why));
        for (const QString& bad :
             {QString(), u"String"_s, u"std_msgs/srv/AddTwoInts"_s, u"std_msgs::msg::dds_::String_"_s,
              u"a/msg/B/C"_s, u"a/msg/"_s, u"1a/msg/B"_s, u"a/msg/B-C"_s, u"a/msg/B\0"_s}) {
            QVERIFY2(!Ros2Names::isValidType(bad, &why), qPrintable(bad));
            QVERIFY2(why.contains(u"not a ROS 2 message type"_s), qPrintable(why));
        }
        QVERIFY(Ros2Names::isValidTopic(u"/chatter"_s));
        QVERIFY(Ros2Names::isValidTopic(u"/"_s + u"x"_s.repeated(255))); // rt/ and 255
        QVERIFY(!Ros2Names::isValidTopic(u"/"_s + u"x"_s.repeated(256), &why));
        QVERIFY2(why.contains(u"at most 255"_s), qPrintable(why));
        QVERIFY(!Ros2Names::isValidTopic(u"/a b"_s, &why));
    }

    void graph()
    {
        Ros2ParticipantInfo talker {gid(1, 0xc1), {{u"/"_s, u"talker"_s, {}, {gid(1, 3)}}}};
        Ros2ParticipantInfo listener {gid(2, 0xc1), {{u"/robot1"_s, u"listener"_s, {gid(2, 4)}, {}}}};
        Ros2Endpoint pub = endpoint(gid(1, 3), u"/chatter"_s, u"std_msgs/msg/String"_s, true);
        pub.qos.durability = Ros2Qos::TransientLocal;
        const QList<Ros2Endpoint> endpoints {
            pub, endpoint(gid(2, 4), u"/chatter"_s, u"std_msgs/msg/String"_s, false),
            endpoint(gid(3, 9), u"/odom"_s, u"nav_msgs/msg/Odometry"_s, false)};
        const Ros2Graph g = Ros2Graph::build(endpoints, {talker, listener}, 3, {u"/a"_s, u"/a"_s, u"/b"_s});
        QCOMPARE(g.participants, 3);
        QCOMPARE(g.services, 2);
        QCOMPARE(g.topics.size(), 2);
        const Ros2Topic* chatter = g.topic(u"/chatter"_s);
        QVERIFY(chatter);
        QCOMPARE(chatter->type(), u"std_msgs/msg/String"_s);
        QCOMPARE(chatter->publishers.size(), 1);
        QCOMPARE(chatter->publishers[0].node, u"/talker"_s);
        QCOMPARE(chatter->publishers[0].qos.durability, Ros2Qos::TransientLocal);
        QCOMPARE(chatter->subscribers[0].node, u"/robot1/listener"_s);
        // an endpoint no node claims stays, without a node
        QCOMPARE(g.topic(u"/odom"_s)->subscribers[0].node, QString());
        QCOMPARE(g.nodes.size(), 2);
        QCOMPARE(g.nodes[0].name, u"/robot1/listener"_s);
        QCOMPARE(g.nodes[0].subscribes, QStringList {u"/chatter"_s});
        QCOMPARE(g.nodes[1].publishes, QStringList {u"/chatter"_s});

        // equality sees a change of QoS or node and nothing else
        QVERIFY(g == Ros2Graph::build(endpoints, {talker, listener}, 3, {u"/a"_s, u"/b"_s}));
        QVERIFY(!(g == Ros2Graph::build(endpoints, {talker}, 3, {u"/a"_s, u"/b"_s})));
        // publishers' type first when publishers and subscribers disagree
        const Ros2Graph mixed = Ros2Graph::build({endpoint(gid(2, 4), u"/x"_s, u"a/msg/B"_s, false),
                                                  endpoint(gid(1, 3), u"/x"_s, u"c/msg/D"_s, true)},
                                                 {}, 2);
        QCOMPARE(mixed.topics[0].types, QStringList({u"c/msg/D"_s, u"a/msg/B"_s}));
    }

    void bundledDefinitions()
    {
        QStringList errors;
        const RosTypeRegistry r = Ros2Definitions::registry({}, &errors);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(u'\n')));
        for (const char* type :
             {"std_msgs/msg/String", "geometry_msgs/msg/PoseStamped", "sensor_msgs/msg/PointCloud2",
              "builtin_interfaces/msg/Time", "std_msgs/msg/Header"})
            QVERIFY2(r.contains(QString::fromLatin1(type)), type);
        // ROS 2's Header: no seq
        QCOMPARE(r.find(u"std_msgs/msg/Header"_s)->fields.size(), 2);
        QCOMPARE(Ros2Definitions::typeOfPath(u"/opt/ros/humble/share/my_pkg/msg/Thing.msg"_s),
                 u"my_pkg/msg/Thing"_s);
        QCOMPARE(Ros2Definitions::typeOfPath(u"Thing.msg"_s), QString());
    }

    void userDefinitions()
    {
        QTemporaryDir dir;
        QDir(dir.path()).mkpath(u"share/my_pkg/msg"_s);
        QDir(dir.path()).mkpath(u"share/bad_pkg/msg"_s);
        auto write = [&](const QString& rel, const QByteArray& text) {
            QFile f(dir.filePath(rel));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text);
        };
        write(u"share/my_pkg/msg/Reading.msg"_s, "std_msgs/Header header\nfloat64 value\nstring<=8 unit\n");
        write(u"share/bad_pkg/msg/Broken.msg"_s, "justonetoken\n");
        write(u"share/bad_pkg/msg/Huge.msg"_s, QByteArray(Ros2Definitions::kMaxFileBytes + 1, '#'));
        QStringList errors;
        const RosTypeRegistry r = Ros2Definitions::registry({dir.path()}, &errors);
        QVERIFY(r.contains(u"my_pkg/msg/Reading"_s));
        QVERIFY(r.contains(u"std_msgs/msg/String"_s)); // the bundled ones stay
        QCOMPARE(errors.size(), 2);
        QVERIFY(errors.filter(u"Broken.msg"_s).size() == 1);
        QVERIFY(errors.filter(u"Huge.msg"_s).size() == 1);
    }
};

QTEST_GUILESS_MAIN(TestRos2Graph)
#include "tst_ros2graph.moc"
