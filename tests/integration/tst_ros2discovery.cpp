// SPDX-License-Identifier: MIT
// ROS 2 on the wire, with no ROS 2 installed: Bridgescope's participant (Cyclone DDS, in
// bridgescope-dds) against nodes built on Cyclone DDS (tests/ros2peer) that speak as rmw_cyclonedds_cpp does (REP 2008 names and
// types, XCDR1, ros_discovery_info). Topics, types, node names, QoS and counts appear and
// disappear; samples of std_msgs/String, geometry_msgs/PoseStamped and sensor_msgs/PointCloud2
// decode to what was sent; an unknown type stays raw bytes of the right size; a watched topic's
// whole samples queue within their bounds. `bridgescope watch` watches a ROS 2 config's links from
// DDS and the broker. Hostile nodes (malformed CDR, huge lengths, unreadable ros_discovery_info) and
// garbage on the RTPS ports are counted or refused, never fatal.
#include "base/wallclock.h"
#include "mqtt/mqttconnection.h"
#include "resulttext.h"
#include "ros2/ros2participant.h"
#include "ros2peer.h"
#include "testservers.h"
#include "wire/ros2definitions.h"

#include <memory>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUdpSocket>

using namespace Qt::StringLiterals;

namespace {
QString field(const RosValue& v, const QString& path)
{
    const RosValue* f = v.find(path);
    return f ? f->value.toString() : u"<missing %1>"_s.arg(path);
}

int publishers(const Ros2Participant& p, const QString& topic)
{
    const Ros2Topic* t = p.graph().topic(topic);
    return t ? int(t->publishers.size()) : 0;
}

int subscribers(const Ros2Participant& p, const QString& topic)
{
    const Ros2Topic* t = p.graph().topic(topic);
    return t ? int(t->subscribers.size()) : 0;
}

bool hasNode(const Ros2Participant& p, const QString& name)
{
    for (const Ros2Node& n : p.graph().nodes)
        if (n.name == name)
            return true;
    return false;
}
} // namespace

class TestRos2Discovery : public QObject
{
    Q_OBJECT
    int m_domain = 0;
    static constexpr int kCloudBytes = 64 * 1024;

private slots:
    void initTestCase() { m_domain = Ros2Peer::freeDomain(1, 60); }

    void refusesBadDomain()
    {
        Ros2Participant p;
        QString error;
        QVERIFY(!noted(p.start({233, true}), &error));
        QVERIFY2(error.contains(u"232"_s), qPrintable(error));
        QVERIFY(!p.isRunning());
    }

    void graphAppearsAndDisappears()
    {
        Ros2Participant p;
        QSignalSpy changed(&p, &Ros2Participant::graphChanged);
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));

        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/talker"_s, u"--pub"_s, u"/chatter:std_msgs/msg/String:20"_s,
                         u"--pub"_s, u"/pose:geometry_msgs/msg/PoseStamped:20:best_effort,transient_local"_s,
                         u"--lease-ms"_s, u"2000"_s});
        Ros2Peer listener(m_domain,
                          {u"--node"_s, u"/robot1/listener"_s, u"--sub"_s, u"/chatter:std_msgs/msg/String"_s,
                           u"--lease-ms"_s, u"2000"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QVERIFY2(listener.waitFor(u"ready"_s), qPrintable(listener.errors()));

        QTRY_VERIFY_WITH_TIMEOUT(publishers(p, u"/chatter"_s) == 1 && subscribers(p, u"/chatter"_s) == 1
                                     && publishers(p, u"/pose"_s) == 1 && hasNode(p, u"/talker"_s)
                                     && hasNode(p, u"/robot1/listener"_s),
                                 15000);
        QVERIFY(!changed.isEmpty());
        const Ros2Topic* chatter = p.graph().topic(u"/chatter"_s);
        QCOMPARE(chatter->type(), u"std_msgs/msg/String"_s);
        QCOMPARE(chatter->publishers[0].node, u"/talker"_s);
        QCOMPARE(chatter->subscribers[0].node, u"/robot1/listener"_s);
        QCOMPARE(chatter->publishers[0].qos.reliability, Ros2Qos::Reliable);
        QCOMPARE(chatter->publishers[0].qos.durability, Ros2Qos::Volatile);
        const Ros2Topic* pose = p.graph().topic(u"/pose"_s);
        QCOMPARE(pose->type(), u"geometry_msgs/msg/PoseStamped"_s);
        QCOMPARE(pose->publishers[0].qos.reliability, Ros2Qos::BestEffort);
        QCOMPARE(pose->publishers[0].qos.durability, Ros2Qos::TransientLocal);
        QVERIFY(p.graph().participants >= 2);
        // ros_discovery_info itself is DDS plumbing, not a ROS topic
        for (const Ros2Topic& t : p.graph().topics)
            QVERIFY2(t.name.startsWith(u'/'), qPrintable(t.name));
        QCOMPARE(p.badDiscoveryInfo(), quint64(0));

        // a node that leaves politely is gone at once
        listener.terminate();
        QTRY_VERIFY_WITH_TIMEOUT(subscribers(p, u"/chatter"_s) == 0 && !hasNode(p, u"/robot1/listener"_s),
                                 8000);
        QCOMPARE(publishers(p, u"/chatter"_s), 1);

        // one that vanishes without goodbye is gone when its lease (2 s) runs out
        QElapsedTimer killed;
        talker.kill();
        killed.start();
        QTRY_VERIFY_WITH_TIMEOUT(!p.graph().topic(u"/chatter"_s) && !p.graph().topic(u"/pose"_s)
                                     && !hasNode(p, u"/talker"_s),
                                 15000);
        qInfo("a vanished participant was dropped after %lld ms", killed.elapsed());
        QVERIFY(killed.elapsed() >= 1000); // by the lease, not by a goodbye
    }

    void samplesDecode()
    {
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        QSignalSpy failed(&p, &Ros2Participant::monitorFailed);
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/sensors"_s, u"--size"_s, QString::number(kCloudBytes), u"--pub"_s,
                         u"/chatter:std_msgs/msg/String:20"_s, u"--pub"_s,
                         u"/pose:geometry_msgs/msg/PoseStamped:20"_s, u"--pub"_s,
                         u"/cloud:sensor_msgs/msg/PointCloud2:10"_s, u"--pub"_s,
                         u"/blob:bridgescope_test/msg/Opaque:10"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        const QStringList topics {u"/chatter"_s, u"/pose"_s, u"/cloud"_s, u"/blob"_s};
        QTRY_VERIFY_WITH_TIMEOUT(std::all_of(topics.begin(), topics.end(),
                                             [&](const QString& t) { return publishers(p, t) == 1; }),
                                 15000);
        for (const QString& t : topics)
            p.monitor(t);
        QVERIFY(failed.isEmpty());
        auto messages = [&](const QString& t) { return p.snapshot(wallClockNs()).value(t).messages; };
        QTRY_VERIFY_WITH_TIMEOUT(
            std::all_of(topics.begin(), topics.end(), [&](const QString& t) { return messages(t) >= 10; }),
            15000);
        // a steady rate over the window: 40 samples of /chatter, 2 s of its 20 Hz
        QTRY_VERIFY_WITH_TIMEOUT(messages(u"/chatter"_s) >= 40, 15000);
        const auto stats = p.snapshot(wallClockNs());

        const RosTypeRegistry registry = Ros2Definitions::registry();
        // std_msgs/String: "hello <n>"
        {
            const Ros2MonitorStats& s = stats[u"/chatter"_s];
            QCOMPARE(s.type, u"std_msgs/msg/String"_s);
            QCOMPARE(s.matchedPublishers, 1);
            QVERIFY2(s.rateHz > 14 && s.rateHz < 26, qPrintable(QString::number(s.rateHz)));
            // Issue 45: no Header, yet an age, from the DDS source timestamp of a writer on this host
            QVERIFY2(s.ageMs >= 0 && s.ageMs < 200, qPrintable(QString::number(s.ageMs)));
            const auto v = noted(RosMessageDecoder::decodeCdr(registry, s.type, s.lastMessage), &error);
            QVERIFY2(v, qPrintable(error));
            QVERIFY2(field(*v, u"data"_s).startsWith(u"hello "_s), qPrintable(field(*v, u"data"_s)));
        }
        // geometry_msgs/PoseStamped: position (n, 2n, 0.5), frame "map", a stamp of now
        {
            const Ros2MonitorStats& s = stats[u"/pose"_s];
            const auto v = noted(RosMessageDecoder::decodeCdr(registry, s.type, s.lastMessage), &error);
            QVERIFY2(v, qPrintable(error));
            const double x = v->find(u"pose.position.x"_s)->value.toDouble();
            QVERIFY(x >= 1);
            QCOMPARE(v->find(u"pose.position.y"_s)->value.toDouble(), 2 * x);
            QCOMPARE(v->find(u"pose.position.z"_s)->value.toDouble(), 0.5);
            QCOMPARE(v->find(u"pose.orientation.w"_s)->value.toDouble(), 1.0);
            QCOMPARE(field(*v, u"header.frame_id"_s), u"map"_s);
            const qint64 sec = v->find(u"header.stamp.sec"_s)->value.toLongLong();
            QVERIFY(qAbs(sec - wallClockNs() / 1'000'000'000) < 30);
        }
        // sensor_msgs/PointCloud2 of 64 KiB: width, fields and the data's size
        {
            const Ros2MonitorStats& s = stats[u"/cloud"_s];
            QVERIFY2(s.rateHz > 6 && s.rateHz < 14, qPrintable(QString::number(s.rateHz)));
            QVERIFY(s.lastSize > kCloudBytes);
            const auto v = noted(RosMessageDecoder::decodeCdr(registry, s.type, s.lastMessage), &error);
            QVERIFY2(v, qPrintable(error));
            QCOMPARE(v->find(u"width"_s)->value.toInt(), kCloudBytes / 16);
            QCOMPARE(v->find(u"point_step"_s)->value.toInt(), 16);
            QCOMPARE(int(v->find(u"data"_s)->arrayLength), kCloudBytes);
            QCOMPARE(v->find(u"fields"_s)->arrayLength, 4u);
            QCOMPARE(field(*v, u"fields.[0].name"_s), u"x"_s);
            QCOMPARE(v->find(u"fields.[3].offset"_s)->value.toInt(), 12);
        }
        // a type we have no definition for: raw bytes of the size sent (header, n, length, blob)
        {
            const Ros2MonitorStats& s = stats[u"/blob"_s];
            QCOMPARE(s.type, u"bridgescope_test/msg/Opaque"_s);
            QVERIFY(!registry.contains(s.type));
            QCOMPARE(s.lastSize, 4 + 4 + 4 + kCloudBytes);
            QVERIFY(!noted(RosMessageDecoder::decodeCdr(registry, s.type, s.lastMessage), &error));
        }

        // unsubscribing while samples flow, and stopping with subscriptions open, are clean
        p.unmonitor(u"/chatter"_s);
        QVERIFY(!p.isMonitored(u"/chatter"_s));
        QVERIFY(!p.snapshot(wallClockNs()).contains(u"/chatter"_s));
        p.stop();
        QVERIFY(!p.isRunning());
    }

    // A hostile node: samples no rmw would write (a String of 4 GiB, a PointCloud2 claiming 2^31
    // fields, a truncated PoseStamped, an unknown representation, half a header). They arrive,
    // are counted with their exact sizes, and do not decode, with a reason, in bounded work; a
    // big-endian sample, legal CDR that rmw does not write, decodes. The unknown representation
    // (12 34) never arrives: Cyclone DDS drops its datagram as malformed before any reader sees it
    // (Fast DDS passed it on); its bytes are still refused by the decoder, with the reason.
    void hostileSamples()
    {
        struct Case
        {
            QString topic, type, hex, error; // error: a word of the decoder's reason, empty: decodes
            bool dropped = false; ///< by the DDS library, before it reaches us
        };
        const QList<Case> cases {
            {u"/h/huge_string"_s, u"std_msgs/msg/String"_s,
             u"00010000"
             "f0ffffff"
             "61626300"_s,
             u"needs 4294967280"_s},
            {u"/h/huge_fields"_s, u"sensor_msgs/msg/PointCloud2"_s,
             u"00010000"
             "01000000"
             "00000000"
             "04000000"
             "6d617000"
             "01000000"
             "10000000"
             "ffffff7f"_s,
             u"claims 2147483647 elements"_s},
            {u"/h/truncated"_s, u"geometry_msgs/msg/PoseStamped"_s,
             u"00010000"
             "01000000"_s,
             u"reading 'nanosec'"_s},
            {u"/h/bad_header"_s, u"std_msgs/msg/String"_s,
             u"12340000"
             "04000000"
             "61626300"_s,
             u"encapsulation 12 34"_s, true},
            {u"/h/half_header"_s, u"std_msgs/msg/String"_s, u"0001"_s, u"reading 'data'"_s},
            {u"/h/big_endian"_s, u"std_msgs/msg/String"_s,
             u"00000000"
             "00000004"
             "61626300"_s,
             QString()},
        };
        QStringList args {u"--node"_s, u"/evil"_s};
        for (const Case& c : cases)
            args << u"--pub"_s << u"%1:%2:20:best_effort"_s.arg(c.topic, c.type) << u"--raw"_s
                 << u"%1:%2"_s.arg(c.topic, c.hex);
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        Ros2Peer evil(m_domain, args);
        QVERIFY2(evil.waitFor(u"ready"_s), qPrintable(evil.errors()));
        QTRY_VERIFY_WITH_TIMEOUT(std::all_of(cases.begin(), cases.end(),
                                             [&](const Case& c) { return publishers(p, c.topic) == 1; }),
                                 15000);
        for (const Case& c : cases)
            p.monitor(c.topic);
        const auto arrived = [&](const Case& c) {
            const auto stats = p.snapshot(wallClockNs());
            return c.dropped || stats.value(c.topic).messages >= 5;
        };
        const auto counts = [&] {
            QStringList out;
            const auto stats = p.snapshot(wallClockNs());
            for (const Case& c : cases)
                out << u"%1 %2"_s.arg(c.topic).arg(stats.value(c.topic).messages);
            return out.join(u", "_s);
        };
        QTRY_VERIFY2_WITH_TIMEOUT(std::all_of(cases.begin(), cases.end(), arrived), qPrintable(counts()),
                                  15000);

        const RosTypeRegistry registry = Ros2Definitions::registry();
        const auto stats = p.snapshot(wallClockNs());
        for (const Case& c : cases) {
            const Ros2MonitorStats& s = stats[c.topic];
            const QByteArray sent = QByteArray::fromHex(c.hex.toLatin1());
            if (c.dropped) {
                QCOMPARE(s.messages, quint64(0));
                QCOMPARE(s.type, c.type); // subscribed all the same
                QVERIFY(!noted(RosMessageDecoder::decodeCdr(registry, c.type, sent), &error));
                QVERIFY2(error.contains(c.error, Qt::CaseInsensitive), qPrintable(c.topic + u": "_s + error));
                continue;
            }
            QCOMPARE(s.type, c.type);
            // RTPS pads a serialized payload to a multiple of 4 bytes
            QCOMPARE(s.lastSize, int((sent.size() + 3) & ~3));
            QCOMPARE(s.lastMessage.left(sent.size()), sent);
            QElapsedTimer took;
            took.start();
            error.clear();
            const auto v = noted(RosMessageDecoder::decodeCdr(registry, s.type, s.lastMessage), &error);
            QVERIFY2(took.elapsed() < 100, qPrintable(c.topic));
            QVERIFY2(RosMessageDecoder::lastSteps() < 100, qPrintable(c.topic));
            if (c.error.isEmpty()) {
                QVERIFY2(v, qPrintable(c.topic + u": "_s + error));
                QCOMPARE(field(*v, u"data"_s), u"abc"_s);
            } else {
                QVERIFY2(!v, qPrintable(c.topic));
                QVERIFY2(error.contains(c.error, Qt::CaseInsensitive), qPrintable(c.topic + u": "_s + error));
            }
        }
        QCOMPARE(p.badDiscoveryInfo(), quint64(0)); // the hostile node's graph is fine
        QVERIFY(hasNode(p, u"/evil"_s));
    }

    // Hostile announcements on ros_discovery_info (a node list of 2^32 - 1 entries, a truncated
    // one, a node name of 2 GiB): counted and shown by `discover`, never taken; the hostile
    // participants' topics stay in the graph, and a good node beside them keeps its name.
    void hostileDiscoveryInfo()
    {
        const QString gid = u"01"_s.repeated(16) + u"00"_s.repeated(8);
        const QStringList infos {
            u"00010000"_s + gid + u"ffffffff"_s,
            u"00010000"_s + gid.left(20),
            u"00010000"_s + gid
                + u"01000000"
                  "ffffff7f"
                  "2f00"_s,
        };
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        std::vector<std::unique_ptr<Ros2Peer>> evil;
        for (int i = 0; i < int(infos.size()); ++i) {
            evil.push_back(std::make_unique<Ros2Peer>(
                m_domain,
                QStringList {u"--node"_s, u"/evil%1"_s.arg(i), u"--pub"_s,
                             u"/evil%1/out:std_msgs/msg/String:5"_s.arg(i), u"--graph-raw"_s, infos[i]}));
        }
        Ros2Peer good(m_domain, {u"--node"_s, u"/good"_s, u"--pub"_s, u"/good/out:std_msgs/msg/String:5"_s});
        for (const auto& e : evil)
            QVERIFY2(e->waitFor(u"ready"_s), qPrintable(e->errors()));
        QVERIFY2(good.waitFor(u"ready"_s), qPrintable(good.errors()));
        const auto state = [&] {
            return u"publishers %1 %2 %3, /good named %4, unreadable %5"_s.arg(publishers(p, u"/evil0/out"_s))
                .arg(publishers(p, u"/evil1/out"_s))
                .arg(publishers(p, u"/evil2/out"_s))
                .arg(hasNode(p, u"/good"_s))
                .arg(p.badDiscoveryInfo());
        };
        QTRY_VERIFY2_WITH_TIMEOUT(publishers(p, u"/evil0/out"_s) == 1 && publishers(p, u"/evil1/out"_s) == 1
                                      && publishers(p, u"/evil2/out"_s) == 1 && hasNode(p, u"/good"_s)
                                      && p.badDiscoveryInfo() >= quint64(infos.size()),
                                  qPrintable(state()), 15000);
        for (int i = 0; i < int(infos.size()); ++i) {
            QVERIFY(!hasNode(p, u"/evil%1"_s.arg(i)));
            QVERIFY(p.graph().topic(u"/evil%1/out"_s.arg(i))->publishers[0].node.isEmpty());
        }
        QCOMPARE(p.graph().topic(u"/good/out"_s)->publishers[0].node, u"/good"_s);

        // the command line says so too
        QProcess discover;
        discover.start(QStringLiteral(BRIDGESCOPE_BINARY),
                       {u"discover"_s, u"--json"_s, u"--ros"_s, u"2"_s, u"--ros-domain"_s,
                        QString::number(m_domain), u"--ros-localhost-only"_s, u"--seconds"_s, u"4"_s});
        QVERIFY(discover.waitForFinished(30000));
        const QJsonObject ros2
            = QJsonDocument::fromJson(discover.readAllStandardOutput()).object().value(u"ros2"_s).toObject();
        QVERIFY2(ros2.value(u"unreadable_discovery_info"_s).toInt() >= int(infos.size()),
                 qPrintable(QString::fromUtf8(QJsonDocument(ros2).toJson())));
    }

    // Garbage on the RTPS ports: random datagrams, and RTPS headers followed by random
    // submessages, 4,000 of them (seeded, so a failure repeats), at the discovery and user ports of
    // the first participant indices. The participant lives on, and still sees a node that comes
    // after the flood and its samples.
    void rtpsGarbage()
    {
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        QRandomGenerator random(20261126);
        QUdpSocket socket;
        int sent = 0;
        for (int i = 0; i < 4000; ++i) {
            QByteArray d(int(random.bounded(8, 600)), Qt::Uninitialized);
            for (char& c : d)
                c = char(random.bounded(256));
            if (i % 2 == 1) { // "RTPS", version 2.1, vendor, a guid prefix, then submessages of any kind
                const QByteArray head = QByteArray("RTPS\x02\x01\x01\x10", 8) + d.left(12);
                d = head + d.mid(12);
            }
            const int index = int(random.bounded(4));
            const quint16 port = quint16(7400 + 250 * m_domain + 10 + 2 * index + int(random.bounded(2)));
            if (socket.writeDatagram(d, QHostAddress::LocalHost, port) == d.size())
                ++sent;
            if (i % 200 == 0)
                QCoreApplication::processEvents(); // let the graph timer run meanwhile
        }
        QVERIFY(sent > 3000);
        Ros2Peer talker(m_domain, {u"--node"_s, u"/after"_s, u"--pub"_s, u"/after:std_msgs/msg/String:20"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QTRY_VERIFY_WITH_TIMEOUT(publishers(p, u"/after"_s) == 1 && hasNode(p, u"/after"_s), 15000);
        p.monitor(u"/after"_s);
        QTRY_VERIFY_WITH_TIMEOUT(p.snapshot(wallClockNs()).value(u"/after"_s).messages >= 5, 10000);
    }

    // The plotter's queue: whole samples of a watched topic, the newest within the bounds (the
    // rest dropped and counted), subscribed without being monitored, kept across monitor() and
    // unmonitor() and across stop() and start().
    void watchedSamplesQueueBounded()
    {
        Ros2Participant p;
        QVERIFY(p.start({m_domain, true}));
        // asked for before the topic exists: subscribed once the graph knows its type
        std::unique_ptr<Tap> tap = p.openTap(u"/pose"_s, 5, 1024 * 1024);
        QVERIFY(p.isWatched(u"/pose"_s));
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/poser"_s, u"--pub"_s, u"/pose:geometry_msgs/msg/PoseStamped:50"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        // (QTRY evaluates its condition more than once: what was taken is kept)
        std::size_t got = 0;
        const auto arrive = [&] { return (got += tap->take().size()) > 0; };
        QTRY_VERIFY_WITH_TIMEOUT(arrive(), 15000);
        QVERIFY(!p.isMonitored(u"/pose"_s));
        QVERIFY(!p.snapshot(wallClockNs()).contains(u"/pose"_s));

        // about 30 samples come while nobody takes: the newest 5 are kept, in order, as sent
        const quint64 droppedBefore = tap->dropped();
        QTRY_VERIFY_WITH_TIMEOUT(tap->dropped() >= droppedBefore + 15, 10000);
        const std::vector<SourceArrival> taken = tap->take();
        QCOMPARE(taken.size(), 5u);
        const RosTypeRegistry registry = Ros2Definitions::registry();
        QString error;
        double previous = 0;
        for (const SourceArrival& s : taken) {
            QCOMPARE(s.graph, SourceGraph::Ros2);
            QCOMPARE(s.type, u"geometry_msgs/msg/PoseStamped"_s); // as the graph names it
            const auto v = noted(
                RosMessageDecoder::decodeCdr(registry, u"geometry_msgs/msg/PoseStamped"_s, s.bytes), &error);
            QVERIFY2(v, qPrintable(error));
            const double x = v->find(u"pose.position.x"_s)->value.toDouble();
            QCOMPARE(v->find(u"pose.position.y"_s)->value.toDouble(), 2 * x);
            QVERIFY2(previous == 0 || x == previous + 1, qPrintable(u"%1 after %2"_s.arg(x).arg(previous)));
            previous = x;
        }
        QVERIFY(taken.front().receivedNs <= taken.back().receivedNs);

        // the bytes bound, in a second tap of the same topic: two samples' worth keeps two, while
        // the first tap keeps its own five
        std::unique_ptr<Tap> small = p.openTap(u"/pose"_s, 1000, 2 * taken.back().bytes.size());
        const quint64 firstDropped = tap->dropped();
        QTRY_VERIFY_WITH_TIMEOUT(small->dropped() >= 3 && tap->dropped() >= firstDropped + 3, 10000);
        QCOMPARE(small->take().size(), 2u); // both full: what comes meanwhile drops their oldest
        QCOMPARE(tap->take().size(), 5u);
        small.reset(); // one tap closes, the other goes on
        QVERIFY(p.isWatched(u"/pose"_s));

        // monitor() and unmonitor() of the same topic leave the tap alone
        tap = p.openTap(u"/pose"_s, 1000, 1024 * 1024);
        p.monitor(u"/pose"_s);
        QVERIFY(p.isMonitored(u"/pose"_s));
        QTRY_VERIFY_WITH_TIMEOUT(p.snapshot(wallClockNs()).value(u"/pose"_s).messages > 0, 5000);
        p.unmonitor(u"/pose"_s);
        QVERIFY(!p.isMonitored(u"/pose"_s));
        QVERIFY(!p.snapshot(wallClockNs()).contains(u"/pose"_s));
        tap->take();
        std::size_t kept = 0;
        QTRY_VERIFY_WITH_TIMEOUT((kept += tap->take().size()) >= 5, 10000);

        // a new participant (another domain join) subscribes the tapped topic again
        p.stop();
        QVERIFY(tap->take().empty());
        QVERIFY(p.start({m_domain, true}));
        got = 0;
        QTRY_VERIFY_WITH_TIMEOUT(arrive(), 15000);

        // the last tap closed: the subscription ends (the talker sees its reader go)
        const auto unmatched = [&] { return talker.lines().count(u"matched /pose 0"_s); };
        const qsizetype unmatchedBefore = unmatched();
        tap.reset();
        QVERIFY(!p.isWatched(u"/pose"_s));
        QTRY_VERIFY_WITH_TIMEOUT(unmatched() > unmatchedBefore, 10000);
    }

    // Two users of one subscription (Discover's Mon and the Links page) do not end each other's,
    // and a monitored topic is subscribed again after stop() and start() (another domain and back).
    void monitorUsesAreCounted()
    {
        Ros2Participant p;
        QVERIFY(p.start({m_domain, true}));
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/twice"_s, u"--pub"_s, u"/twice:std_msgs/msg/String:20"_s,
                         u"--duration"_s, u"60"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QTRY_VERIFY_WITH_TIMEOUT(publishers(p, u"/twice"_s) == 1, 15000);
        const auto messages = [&] { return p.snapshot(wallClockNs()).value(u"/twice"_s).messages; };
        p.monitor(u"/twice"_s);
        p.monitor(u"/twice"_s);
        QTRY_VERIFY_WITH_TIMEOUT(messages() >= 3, 10000);
        p.unmonitor(u"/twice"_s);
        QVERIFY(p.isMonitored(u"/twice"_s));
        const quint64 before = messages();
        QTRY_VERIFY_WITH_TIMEOUT(messages() >= before + 3, 10000);

        p.stop();
        QVERIFY(p.start({m_domain, true}));
        QTRY_VERIFY_WITH_TIMEOUT(p.isMonitored(u"/twice"_s) && messages() >= 3, 15000);

        p.unmonitor(u"/twice"_s);
        QVERIFY(!p.isMonitored(u"/twice"_s));
        QVERIFY(!p.snapshot(wallClockNs()).contains(u"/twice"_s));
        p.unmonitor(u"/twice"_s); // one too many: nothing to end
        QVERIFY(!p.isMonitored(u"/twice"_s));
    }

    void monitorUnknownTopicFails()
    {
        Ros2Participant p;
        QVERIFY(p.start({m_domain, true}));
        QSignalSpy failed(&p, &Ros2Participant::monitorFailed);
        p.monitor(u"/nobody"_s);
        QCOMPARE(failed.size(), 1);
        QVERIFY(!p.isMonitored(u"/nobody"_s));
    }

    // watch --ros 2: a ROS 2 config's links, the ROS end read from DDS. A stand-in for the bridge
    // feeds one MQTT topic; the other stays silent while its ROS 2 source publishes: a stall.
    void watchRos2Config()
    {
        TestServers servers;
        QVERIFY(servers.startMosquitto());
        Ros2Peer talker(m_domain,
                        {u"--node"_s, u"/talker"_s, u"--pub"_s, u"/chatter:std_msgs/msg/String:20"_s,
                         u"--pub"_s, u"/idle:std_msgs/msg/String:20"_s, u"--duration"_s, u"60"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        const QString config = servers.tempPath() + u"/bridge.ros2.yaml"_s;
        QFile f(config);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("/**/*:\n  ros__parameters:\n    broker: {host: 127.0.0.1, port: 1883}\n    bridge:\n"
                "      ros2mqtt:\n        ros_topics: [/chatter, /idle]\n"
                "        /chatter: {mqtt_topic: lab/chatter}\n        /idle: {mqtt_topic: lab/idle}\n");
        f.close();

        MqttConnection bridge; // stands in for mqtt_client: /chatter arrives on the broker
        bridge.open(MqttProfile::fromUrl(servers.brokerUrl()));
        QTRY_VERIFY_WITH_TIMEOUT(bridge.state() == MqttConnection::State::Connected, 10000);
        QTimer feed;
        int fed = 0;
        connect(&feed, &QTimer::timeout, this, [&] {
            if (bridge.publish(u"lab/chatter"_s, "hello", 0, false))
                ++fed;
        });
        feed.start(50);

        const quint16 port = TestServers::freePort();
        QProcess watch;
        watch.setProcessChannelMode(QProcess::SeparateChannels);
        watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    {u"watch"_s, config, u"--broker"_s, servers.brokerUrl(), u"--ros"_s, u"2"_s,
                     u"--ros-domain"_s, QString::number(m_domain), u"--ros-localhost-only"_s,
                     u"--no-discover"_s, u"--metrics"_s, u"127.0.0.1:%1"_s.arg(port), u"--seconds"_s,
                     u"30"_s});
        QVERIFY(watch.waitForStarted(5000));
        QVERIFY(TestServers::waitForPort(port, 10000));
        const auto value = [&](const QString& topic, const QString& side) {
            const double v = TestServers::metricSample(
                TestServers::httpGet(port, u"/metrics"_s), u"bridgescope_link_messages_total"_s,
                {u"link=\"%1 → "_s.arg(topic), u"side=\"%1\""_s.arg(side)}); // ROS → MQTT links
            return qIsNaN(v) ? 0.0 : v;
        };
        // both ROS 2 sources counted from DDS, /chatter's destination from the broker
        QTRY_VERIFY_WITH_TIMEOUT(value(u"/chatter"_s, u"source"_s) > 40 && value(u"/idle"_s, u"source"_s) > 40
                                     && value(u"/chatter"_s, u"destination"_s) > 40,
                                 20000);
        const double before = value(u"/chatter"_s, u"source"_s);
        QTest::qWait(2000); // the stimulus: 2 s of traffic, whose rate is checked
        const double rate = (value(u"/chatter"_s, u"source"_s) - before) / 2.0;
        QVERIFY2(rate > 14 && rate < 26, qPrintable(QString::number(rate)));
        QCOMPARE(value(u"/idle"_s, u"destination"_s), 0.0);
        // the silent destination of a publishing source is a stall event on stdout
        QString out;
        QTRY_VERIFY_WITH_TIMEOUT(
            (out += QString::fromUtf8(watch.readAllStandardOutput())).contains(u"/idle"_s), 15000);
        bool stall = false;
        for (const QString& line : out.split(u'\n', Qt::SkipEmptyParts)) {
            const QJsonObject e = QJsonDocument::fromJson(line.toUtf8()).object();
            if (e.value(u"ros_topic"_s).toString() == u"/idle"_s
                && e.value(u"event"_s).toString() == u"start"_s)
                stall = stall || e.value(u"reasons"_s).toVariant().toStringList().contains(u"stall"_s);
            QVERIFY2(e.value(u"ros_topic"_s).toString() != u"/chatter"_s, qPrintable(line));
        }
        QVERIFY2(stall, qPrintable(out));
        watch.terminate();
        QVERIFY(watch.waitForFinished(10000));
        QCOMPARE(watch.exitCode(), 0);
        QVERIFY(fed > 0);
    }
};

QTEST_GUILESS_MAIN(TestRos2Discovery)
#include "tst_ros2discovery.moc"
