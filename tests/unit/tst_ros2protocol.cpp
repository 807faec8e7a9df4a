// SPDX-License-Identifier: MIT
// The pipe to bridgescope-dds (Ros2Protocol): every body reads back as written; frames and bodies
// that are cut, too long, of an unknown kind or that claim more elements than their bytes hold are
// refused without allocating what they claim. The child runs a library that hostile datagrams can
// take over, so its frames are input like any other.
#include "ros2/ros2protocol.h"

#include <cmath>
#include <limits>
#include <QTest>

using namespace Qt::StringLiterals;
using namespace Ros2Protocol;

namespace {
Ros2Endpoint endpoint(char id, const QString& topic, bool publisher)
{
    Ros2Endpoint e;
    e.gid = QByteArray(16, id);
    e.topic = topic;
    e.type = u"std_msgs/msg/String"_s;
    e.publisher = publisher;
    e.qos.reliability = Ros2Qos::BestEffort;
    e.qos.durability = Ros2Qos::TransientLocal;
    e.node = u"/lab/talker"_s;
    return e;
}

Ros2Graph sampleGraph()
{
    Ros2Graph g;
    g.participants = 3;
    g.services = 7;
    Ros2Topic a;
    a.name = u"/a"_s;
    a.types = {u"std_msgs/msg/String"_s};
    a.publishers = {endpoint('\x01', a.name, true)};
    a.subscribers = {endpoint('\x02', a.name, false), endpoint('\x03', a.name, false)};
    Ros2Topic b;
    b.name = u"/b/ü"_s;
    b.types = {u"x/msg/A"_s, u"x/msg/B"_s};
    g.topics = {a, b};
    g.nodes = {Ros2Node {u"/lab/talker"_s, {u"/a"_s}, {}}, Ros2Node {u"/lab/listener"_s, {}, {u"/a"_s, u"/b/ü"_s}}};
    return g;
}
} // namespace

class TestRos2Protocol : public QObject
{
    Q_OBJECT
private slots:
    void framesSplitAnyWay()
    {
        const QByteArray stream = frame(Kind::Heartbeat) + frame(Kind::Graph, "abc") + frame(Kind::Started);
        for (int cut = 1; cut <= 4; ++cut) { // fed in slices of 1 to 4 bytes
            FrameReader r;
            QList<Frame> got;
            for (qsizetype i = 0; i < stream.size(); i += cut) {
                r.append(stream.mid(i, cut));
                while (auto f = r.next())
                    got.append(*f);
            }
            QCOMPARE(got.size(), 3);
            QCOMPARE(got[1].kind, Kind::Graph);
            QCOMPARE(got[1].body, QByteArray("abc"));
            QCOMPARE(r.pending(), 0);
            QVERIFY(!r.failed());
        }
    }

    void frameTooLongOrUnknownEndsTheStream()
    {
        FrameReader tooLong;
        QByteArray head(5, '\0');
        head[0] = '\xff';
        head[1] = '\xff';
        head[2] = '\xff';
        head[3] = '\x7f';
        head[4] = char(Kind::Graph);
        tooLong.append(head);
        QVERIFY(!tooLong.next());
        QVERIFY(tooLong.failed());
        QVERIFY2(tooLong.error().contains(u"bytes"_s), qPrintable(tooLong.error()));
        QCOMPARE(tooLong.pending(), 0); // nothing of it is kept
        tooLong.append(frame(Kind::Heartbeat));
        QVERIFY(!tooLong.next()); // a stream that failed stays failed

        FrameReader unknown;
        unknown.append(QByteArray("\0\0\0\0\x0e", 5)); // after the last request (Unsubscribe)
        QVERIFY(!unknown.next());
        QVERIFY(unknown.failed());
        FrameReader request; // a kind the parent sends is known, and refused by the parent's handler
        request.append(frame(Kind::Monitor, encodeStrings({u"/a"_s})));
        QVERIFY(request.next());
    }

    void bodiesRoundTrip()
    {
        const auto start = decodeStart(encodeStart({{42, true}, 20}));
        QVERIFY(start);
        QCOMPARE(start->options.domain, 42);
        QVERIFY(start->options.localhostOnly);
        QVERIFY(!start->options.limitedGraph);
        QCOMPARE(start->graphIntervalMs, 20);
        Ros2Options limited {7, false};
        limited.limitedGraph = true; // after a loop of restarts (issue 41)
        const auto restart = decodeStart(encodeStart({limited, 250}));
        QVERIFY(restart && restart->options.limitedGraph && !restart->options.localhostOnly);
        QByteArray flags = encodeStart({limited, 250});
        flags[4] = 4; // no such flag
        QVERIFY(!decodeStart(flags));
        // Static peers (a lab across hosts, ROS_STATIC_PEERS): addresses only, at most kMaxStaticPeers.
        Ros2Options peered {9, false};
        peered.staticPeers = {u"10.0.0.1"_s, u"fd00::2"_s};
        const auto withPeers = decodeStart(encodeStart({peered, 250}));
        QVERIFY(withPeers);
        QCOMPARE(withPeers->options.staticPeers, (QStringList {u"10.0.0.1"_s, u"fd00::2"_s}));
        peered.staticPeers = {u"10.0.0.1\"/><Peer Address=\"evil"_s};
        QVERIFY(!decodeStart(encodeStart({peered, 250})));
        peered.staticPeers.clear();
        for (int i = 0; i <= Ros2Options::kMaxStaticPeers; ++i)
            peered.staticPeers << u"10.0.0.%1"_s.arg(i + 1);
        QVERIFY(!decodeStart(encodeStart({peered, 250})));

        const auto watch = decodeWatch(encodeWatch({u"/pose"_s, 5, 1 << 20}));
        QVERIFY(watch);
        QCOMPARE(watch->topic, u"/pose"_s);
        QCOMPARE(watch->maxMessages, 5u);
        QCOMPARE(watch->maxBytes, 1 << 20);

        const auto strings = decodeStrings(encodeStrings({u"/a"_s, u"why ✓"_s}), 2);
        QVERIFY(strings);
        QCOMPARE(*strings, QStringList({u"/a"_s, u"why ✓"_s}));
        QVERIFY(!decodeStrings(encodeStrings({u"/a"_s, u"b"_s}), 1)); // bytes left over
        QCOMPARE(decodeNumber(encodeNumber(123456789012ull)).value_or(0), 123456789012ull);

        const Ros2Graph g = sampleGraph();
        const auto graph = decodeGraph(encodeGraph({g, 9}));
        QVERIFY(graph);
        QVERIFY(graph->graph == g);
        QCOMPARE(graph->badDiscoveryInfo, 9u);

        Ros2MonitorStats s;
        s.messages = 10;
        s.bytes = 1000;
        s.lastSize = 100;
        s.lastNs = 1'700'000'000'000'000'000;
        s.rateHz = 9.5;
        s.bytesPerSecond = 950;
        s.type = u"std_msgs/msg/String"_s;
        s.lastMessage = QByteArray("\0\1\0\0abc", 7);
        s.lost = 2;
        s.matchedPublishers = 1;
        s.ageMs = 0.25;
        const auto stats = decodeStats(encodeStats({{u"/a"_s, s, true}, {u"/b"_s, s, false}}));
        QVERIFY(stats);
        QCOMPARE(stats->size(), 2);
        QCOMPARE(stats->at(0).stats.ageMs, 0.25);
        // no source timestamp: NaN, and so it stays
        QVERIFY(
            std::isnan(decodeStats(encodeStats({{u"/a"_s, Ros2MonitorStats {}, false}}))->at(0).stats.ageMs));
        QCOMPARE(stats->at(0).stats.lastMessage, s.lastMessage);
        QCOMPARE(stats->at(0).stats.rateHz, 9.5);
        QCOMPARE(stats->at(0).stats.lastNs, s.lastNs);
        QVERIFY(!stats->at(1).withMessage);
        QVERIFY(stats->at(1).stats.lastMessage.isEmpty());

        const auto samples = decodeSamples(encodeSamples({u"/p"_s, 4, {{1, "one"}, {2, QByteArray(100000, 'x')}}}));
        QVERIFY(samples);
        QCOMPARE(samples->dropped, 4u);
        QCOMPARE(samples->samples.size(), 2u);
        QCOMPARE(samples->samples[1].bytes.size(), 100000);

        // The graph is not on the wire: what the child sends reads back as ROS 2's, whatever it was.
        const auto arrivals
            = decodeArrivals(encodeArrivals({3,
                                             {{SourceGraph::Mqtt, u"/t"_s, 5, 100, "0123456789abcdef",
                                               ContentKey::of("0123456789abcdef"), 0, ContentKey::of("17")},
                                              {SourceGraph::Ros2, u"/u"_s, 6, 1, "x", std::nullopt}}}));
        QVERIFY(arrivals);
        QCOMPARE(arrivals->dropped, 3u);
        QCOMPARE(arrivals->arrivals.front().graph, SourceGraph::Ros2);
        QCOMPARE(arrivals->arrivals.front().topic, u"/t"_s);
        QCOMPARE(arrivals->arrivals.front().receivedNs, 5);
        QCOMPARE(arrivals->arrivals.front().size, 100);
        QCOMPARE(arrivals->arrivals.front().head, QByteArray("0123456789abcdef"));
        QCOMPARE(arrivals->arrivals.front().key,
                 std::optional<ContentKey>(ContentKey::of("0123456789abcdef")));
        QCOMPARE(arrivals->arrivals.front().textKey,
                 std::optional<ContentKey>(ContentKey::of("17"))); // issue 45
        QCOMPARE(arrivals->arrivals.back().key, std::nullopt);
        QCOMPARE(arrivals->arrivals.back().textKey, std::nullopt);
    }

    // Every prefix of a body is refused (no partial value is taken), and so is a body with a byte
    // more.
    void cutBodiesAreRefused()
    {
        const QByteArray graph = encodeGraph({sampleGraph(), 1});
        for (qsizetype n = 0; n < graph.size(); ++n)
            QVERIFY2(!decodeGraph(graph.left(n)), qPrintable(QString::number(n)));
        QVERIFY(!decodeGraph(graph + '\0'));
        const QByteArray samples = encodeSamples({u"/p"_s, 0, {{1, "abc"}}});
        for (qsizetype n = 0; n < samples.size(); ++n)
            QVERIFY(!decodeSamples(samples.left(n)));
    }

    // A count that claims more elements than the bytes left could hold is refused before anything
    // is reserved (2^32 - 1 endpoints would be hundreds of GB).
    void hugeCountsAreRefusedWithoutAllocating()
    {
        Writer w;
        w.u64(0);
        w.u32(1);
        w.u32(0);
        w.u32(0xffffffffu); // topics
        QVERIFY(!decodeGraph(w.data()));

        Writer s;
        s.string(u"/p"_s);
        s.u64(0);
        s.u32(0xfffffff0u); // samples
        s.i64(1);
        s.u32(0xfffffff0u); // a sample's length
        QVERIFY(!decodeSamples(s.data()));

        Writer a;
        a.u64(0);
        a.u32(1);
        a.string(u"/t"_s);
        a.i64(1);
        a.u32(10);
        a.bytes(QByteArray(17, 'h')); // a head longer than an arrival keeps
        QVERIFY(!decodeArrivals(a.data()));
    }

    // ROS_STATIC_PEERS: IP addresses separated by ';'; anything else is said and none is taken.
    void staticPeersFromTheEnvironment()
    {
        qputenv("ROS_STATIC_PEERS", " 10.0.0.1;;fd00::2 ");
        QString error;
        QCOMPARE(Ros2Options::fromEnvironment(&error).staticPeers,
                 (QStringList {u"10.0.0.1"_s, u"fd00::2"_s}));
        QVERIFY(error.isEmpty());
        qputenv("ROS_STATIC_PEERS", "10.0.0.1;cloud.lab");
        QVERIFY(Ros2Options::fromEnvironment(&error).staticPeers.isEmpty());
        QVERIFY2(error.contains(u"cloud.lab"_s), qPrintable(error));
        qunsetenv("ROS_STATIC_PEERS");
    }

    void valuesOutOfRangeAreRefused()
    {
        QVERIFY(!decodeStart(encodeStart({{Ros2Options::kMaxDomain + 1, false}, 250})));
        QVERIFY(!decodeStart(encodeStart({{0, false}, 0})));
        // found by fuzz_ros2frames: a domain of 0xffffffff read as the int -1 passed the check
        QVERIFY(!decodeStart(encodeStart({{-1, false}, 250})));
        QVERIFY(!decodeStart(encodeStart({{0, false}, -5})));
        Ros2Graph g = sampleGraph();
        g.topics[0].publishers[0].gid = "short";
        QVERIFY(!decodeGraph(encodeGraph({g, 0})));
        g = sampleGraph();
        std::swap(g.topics[0], g.topics[1]); // not sorted: not what Ros2Graph::build makes
        QVERIFY(!decodeGraph(encodeGraph({g, 0})));
        Ros2MonitorStats s;
        s.rateHz = std::numeric_limits<double>::quiet_NaN();
        QVERIFY(!decodeStats(encodeStats({{u"/a"_s, s, false}})));
        s = {};
        s.ageMs = std::numeric_limits<double>::infinity();
        QVERIFY(!decodeStats(encodeStats({{u"/a"_s, s, false}})));
        QVERIFY(!decodeWatch(encodeWatch({u"/a"_s, 1, -1})));
        // a flag is 0 or 1 (issue 42: one field list for both sides, the check in the reader)
        QByteArray flag = encodeStats({{u"/a"_s, Ros2MonitorStats {}, false}});
        QVERIFY(decodeStats(flag));
        flag[flag.size() - 1] = 2;
        QVERIFY(!decodeStats(flag));
        // an enum past its last value never becomes one
        Reader r(QByteArray(1, char(4)));
        Ros2Qos::Durability d = Ros2Qos::Volatile;
        r.enumeration(d, Ros2Qos::Persistent);
        QVERIFY(!r.ok());
        QCOMPARE(d, Ros2Qos::Volatile);
    }

    // Issue 41: one peer announcing 700 writers of 60,000-character topics made a graph frame of
    // over 65 MiB, which the parent refused, restarting the child, which found the same graph: a
    // restart loop. A graph past its budget is sent in part, what is left out counted.
    void aGraphPastItsBudgetIsSentInPart()
    {
        Ros2Graph g;
        g.participants = 2;
        g.omitted = 5;
        for (int i = 0; i < 700; ++i) {
            Ros2Topic t;
            t.name = u"/f%1_"_s.arg(i, 4, 10, QLatin1Char('0')) + u"x"_s.repeated(60'000);
            t.types = {u"std_msgs/msg/String"_s};
            t.publishers = {endpoint(char(i), t.name, true)};
            g.topics.append(t);
        }
        g.topics.prepend(Ros2Topic {u"/chatter"_s, {u"std_msgs/msg/String"_s}, {endpoint('\x01', u"/chatter"_s, true)}, {}});
        g.nodes = {Ros2Node {u"/lab/talker"_s, {u"/chatter"_s}, {}}};
        const QByteArray body = encodeGraph({g, 3});
        QVERIFY2(body.size() <= 32 * 1024 * 1024, qPrintable(QString::number(body.size())));
        QVERIFY(body.size() + 5 <= qsizetype(kMaxFrameBytes));
        const auto back = decodeGraph(body);
        QVERIFY(back);
        QCOMPARE(back->badDiscoveryInfo, quint64(3));
        QCOMPARE(back->graph.topics.first().name, u"/chatter"_s);
        const qsizetype kept = back->graph.topics.size();
        QVERIFY2(kept > 1 && kept < 701, qPrintable(QString::number(kept)));
        // the topics left out (each with its one writer), what the graph left out before, and the
        // node if it did not fit after them
        QCOMPARE(back->graph.omitted, quint64(5 + 701 - kept + 1 - back->graph.nodes.size()));
        // a small budget: the same, sooner
        const auto tiny = decodeGraph(encodeGraph({g, 0}, 200));
        QVERIFY(tiny);
        QCOMPARE(tiny->graph.topics.size(), 1);
        QCOMPARE(tiny->graph.omitted, quint64(5 + 700 + 1 - tiny->graph.nodes.size()));
    }

    void endpointDoneReadsBack()
    {
        const EndpointDone d {false, u"/t"_s, u"a/msg/B"_s, u"Cyclone DDS refused it"_s};
        const auto back = decodeEndpointDone(encodeEndpointDone(d));
        QVERIFY(back);
        QCOMPARE(back->advertise, false);
        QCOMPARE(back->topic, d.topic);
        QCOMPARE(back->type, d.type);
        QCOMPARE(back->why, d.why);
        QByteArray bad = encodeEndpointDone(d);
        bad[0] = 2;
        QVERIFY(!decodeEndpointDone(bad));
        QVERIFY(!decodeEndpointDone(encodeEndpointDone(d).chopped(1)));
    }

    void endpointRequestsReadBackAndRefuseWhatNoEndpointIs()
    {
        EndpointRequest e {u"/chatter"_s, u"std_msgs/msg/String"_s, {}};
        e.qos.reliability = Ros2Qos::BestEffort;
        e.qos.durability = Ros2Qos::TransientLocal;
        e.qos.depth = 7;
        const auto back = decodeEndpoint(encodeEndpoint(e));
        QVERIFY(back);
        QCOMPARE(back->topic, e.topic);
        QCOMPARE(back->type, e.type);
        QCOMPARE(back->qos, e.qos);
        for (int depth : {0, -1, kMaxDepth + 1}) { // keep last 1..kMaxDepth only
            EndpointRequest bad = e;
            bad.qos.depth = depth;
            QVERIFY2(!decodeEndpoint(encodeEndpoint(bad)), qPrintable(QString::number(depth)));
        }
        EndpointRequest transient = e;
        transient.qos.durability = Ros2Qos::Transient; // not what a ROS 2 endpoint can be
        QVERIFY(!decodeEndpoint(encodeEndpoint(transient)));
        EndpointRequest noTopic = e;
        noTopic.topic.clear();
        QVERIFY(!decodeEndpoint(encodeEndpoint(noTopic)));
        const QByteArray body = encodeEndpoint(e);
        for (qsizetype cut = 0; cut < body.size(); ++cut)
            QVERIFY(!decodeEndpoint(body.left(cut)));
        QVERIFY(!decodeEndpoint(body + '\0'));

        const PublishRequest p {u"/chatter"_s, QByteArray::fromHex("0001000006000000686f77647900")};
        const auto got = decodePublish(encodePublish(p));
        QVERIFY(got);
        QCOMPARE(got->cdr, p.cdr);
        QVERIFY(!decodePublish(encodePublish({u"/chatter"_s, QByteArray::fromHex("000100")}))); // no header
        const QByteArray pb = encodePublish(p);
        for (qsizetype cut = 0; cut < pb.size(); ++cut)
            QVERIFY(!decodePublish(pb.left(cut)));
        Writer huge; // a sample length far past the body
        huge.string(u"/chatter"_s);
        huge.u32(0xfffffff0u);
        QVERIFY(!decodePublish(huge.data()));
        // the new kinds are known; the one after the last of each direction is not
        FrameReader r;
        r.append(frame(Kind::Unsubscribe) + frame(Kind::Received));
        QVERIFY(r.next());
        QVERIFY(r.next());
        QVERIFY(!isKnown(quint8(Kind::Unsubscribe) + 1));
        QVERIFY(!isKnown(quint8(Kind::EndpointDone) + 1));
    }
};

QTEST_GUILESS_MAIN(TestRos2Protocol)
#include "tst_ros2protocol.moc"
