// SPDX-License-Identifier: MIT
// Bridgescope's own ROS 2 endpoints (Ros2Participant's setNode(), advertise(), publish(),
// subscribe()) against nodes built on Cyclone DDS that speak as rmw_cyclonedds_cpp does
// (tests/ros2peer): what we write is what such a node receives; what it writes comes to received()
// as soon as it arrives; our node is in ros_discovery_info with its endpoints, and in our own graph;
// reliability matches as DDS says (a reliable reader never matches a best-effort writer).
#include "base/wallclock.h"
#include "ddschild.h"
#include "peakrss.h"
#include "resulttext.h"
#include "ros2/ros2participant.h"
#include "ros2peer.h"

#include <chrono>
#include <QSignalSpy>
#include <QtEndian>
#include <QTest>
#include <thread>

using namespace Qt::StringLiterals;

namespace {
/// A std_msgs/msg/String as rclcpp serializes it: header, length with the NUL, bytes, NUL.
QByteArray stringCdr(const QString& text)
{
    const QByteArray utf8 = text.toUtf8();
    QByteArray out = QByteArray::fromHex("00010000");
    char len[4];
    qToLittleEndian(quint32(utf8.size() + 1), len);
    out.append(len, 4);
    out += utf8;
    out.append('\0');
    return out;
}

/// The text of a std_msgs/msg/String sample, or "<bad>".
QString stringOf(const QByteArray& cdr)
{
    if (cdr.size() < 8 || cdr.left(2) != QByteArray::fromHex("0001"))
        return u"<bad>"_s;
    const quint32 n = qFromLittleEndian<quint32>(cdr.constData() + 4);
    if (n == 0 || qsizetype(n) > cdr.size() - 8)
        return u"<bad>"_s;
    return QString::fromUtf8(cdr.mid(8, n - 1));
}

Ros2Qos qos(Ros2Qos::Reliability r)
{
    Ros2Qos q;
    q.reliability = r;
    return q;
}

const Ros2Node* node(const Ros2Graph& g, const QString& name)
{
    for (const Ros2Node& n : g.nodes)
        if (n.name == name)
            return &n;
    return nullptr;
}
} // namespace

class TestRos2Endpoints : public QObject
{
    Q_OBJECT
    int m_domain = 0;

private slots:
    void initTestCase() { m_domain = Ros2Peer::freeDomain(150, 180); }

    void ourWriterReachesANode()
    {
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        QVERIFY(!p.node().publish(u"/chatter"_s, stringCdr(u"early"_s))); // not advertised
        QCOMPARE(p.node().publishDropped(), 1u);
        p.node().advertise(u"/chatter"_s, u"std_msgs/msg/String"_s);
        Ros2Peer listener(m_domain, {u"--node"_s, u"/listener"_s, u"--sub"_s, u"/chatter:std_msgs/msg/String"_s,
                                     u"--cdr"_s});
        QVERIFY2(listener.waitFor(u"ready"_s), qPrintable(listener.errors()));
        QVERIFY2(listener.waitFor(u"matched /chatter 1"_s), qPrintable(listener.errors()));
        for (int i = 1; i <= 5; ++i) {
            QVERIFY(p.node().publish(u"/chatter"_s, stringCdr(u"from bridgescope %1"_s.arg(i))));
            QTest::qWait(20);
        }
        QVERIFY2(listener.waitFor(u"recv /chatter 5 "_s), qPrintable(listener.lines().join(u'\n')));
        const QStringList lines = listener.lines();
        for (int i = 1; i <= 5; ++i)
            QVERIFY2(lines.contains(u"recv /chatter %1 from bridgescope %1"_s.arg(i)), qPrintable(lines.join(u'\n')));
        // the bytes as sent: the header, the length 18 + 1, the text (27 bytes; RTPS pads to 28)
        QVERIFY2(lines.filter(u"cdr /chatter 1 "_s).value(0).startsWith(u"cdr /chatter 1 2"_s)
                     && lines.filter(u"cdr /chatter 1 "_s).value(0).contains(u" 00 01 00 00 13 00 00 00 66 72"_s),
                 qPrintable(lines.join(u'\n')));
        QCOMPARE(p.node().publishDropped(), 1u);
    }

    void aNodesSamplesComeAsTheyArrive()
    {
        Ros2Participant p;
        QSignalSpy received(&p.node(), &Ros2EndpointLink::received);
        p.node().subscribe(u"/chatter"_s, u"std_msgs/msg/String"_s); // before start(): made once it runs
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        Ros2Peer talker(m_domain, {u"--node"_s, u"/talker"_s, u"--pub"_s, u"/chatter:std_msgs/msg/String:50"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QTRY_VERIFY_WITH_TIMEOUT(received.size() >= 10, 15000);
        const qint64 now = wallClockNs();
        int previous = 0;
        for (const QList<QVariant>& r : std::as_const(received)) {
            QCOMPARE(r.at(0).toString(), u"/chatter"_s);
            const auto s = r.at(1).value<Ros2Sample>();
            const QString text = stringOf(s.bytes);
            QVERIFY2(text.startsWith(u"hello "_s), qPrintable(text));
            const int n = text.mid(6).toInt();
            QVERIFY2(n > previous, qPrintable(text)); // in order, none twice
            previous = n;
            QVERIFY(s.receivedNs > now - 20'000'000'000 && s.receivedNs <= now);
        }
        // received() as each sample comes, not a poll later: samples sent every 20 ms arrive
        // spread out, not in bursts of a poll interval
        const auto first = received.at(received.size() - 5).at(1).value<Ros2Sample>().receivedNs;
        const auto last = received.last().at(1).value<Ros2Sample>().receivedNs;
        QVERIFY2(last - first > 40'000'000, qPrintable(QString::number(last - first)));
        QCOMPARE(p.node().droppedReceived(), 0u);
        p.node().unsubscribe(u"/chatter"_s);
        QTest::qWait(300);
        const qsizetype after = received.size();
        QTest::qWait(300);
        QCOMPARE(received.size(), after);
    }

    void ourNodeIsInTheGraph()
    {
        Ros2Participant p;
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        p.node().setNode(u"/lab"_s, u"mqtt_client"_s);
        p.node().advertise(u"/out"_s, u"std_msgs/msg/String"_s);
        p.node().advertise(u"/pose"_s, u"geometry_msgs/msg/PoseStamped"_s);
        p.node().subscribe(u"/in"_s, u"std_msgs/msg/String"_s);
        Ros2Peer watcher(m_domain, {u"--node"_s, u"/watcher"_s, u"--show-discovery"_s});
        QVERIFY2(watcher.waitFor(u"node /lab mqtt_client 1 2"_s), qPrintable(watcher.lines().join(u'\n')));
        const QStringList lines = watcher.lines();
        QVERIFY(lines.contains(u"endpoint pub rt/out std_msgs::msg::dds_::String_"_s));
        QVERIFY(lines.contains(u"endpoint pub rt/pose geometry_msgs::msg::dds_::PoseStamped_"_s));
        QVERIFY(lines.contains(u"endpoint sub rt/in std_msgs::msg::dds_::String_"_s));
        // and our own graph shows it, as ROS 2 tools show a node its own endpoints
        QTRY_VERIFY_WITH_TIMEOUT(node(p.graph(), u"/lab/mqtt_client"_s), 5000);
        const Ros2Node* n = node(p.graph(), u"/lab/mqtt_client"_s);
        QCOMPARE(n->publishes, (QStringList {u"/out"_s, u"/pose"_s}));
        QCOMPARE(n->subscribes, QStringList {u"/in"_s});
        // an endpoint that goes is announced without it
        p.node().unadvertise(u"/pose"_s);
        QVERIFY2(watcher.waitFor(u"node /lab mqtt_client 1 1"_s), qPrintable(watcher.lines().join(u'\n')));
        QTRY_VERIFY_WITH_TIMEOUT(node(p.graph(), u"/lab/mqtt_client"_s)->publishes == QStringList {u"/out"_s}, 5000);
    }

    void reliabilityMatchesAsDdsSays()
    {
        Ros2Participant p;
        QSignalSpy received(&p.node(), &Ros2EndpointLink::received);
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        // our writers: best effort to a reliable reader never matches, reliable does
        p.node().advertise(u"/strict"_s, u"std_msgs/msg/String"_s, qos(Ros2Qos::BestEffort));
        p.node().advertise(u"/fine"_s, u"std_msgs/msg/String"_s, qos(Ros2Qos::Reliable));
        // our readers: reliable of a best-effort writer never matches, best effort does
        p.node().subscribe(u"/lossy"_s, u"std_msgs/msg/String"_s, qos(Ros2Qos::Reliable));
        p.node().subscribe(u"/lossy2"_s, u"std_msgs/msg/String"_s, qos(Ros2Qos::BestEffort));
        Ros2Peer peer(m_domain, {u"--sub"_s, u"/strict:std_msgs/msg/String:reliable"_s, u"--sub"_s,
                                 u"/fine:std_msgs/msg/String:reliable"_s, u"--pub"_s,
                                 u"/lossy:std_msgs/msg/String:50:best_effort"_s, u"--pub"_s,
                                 u"/lossy2:std_msgs/msg/String:50:best_effort"_s});
        QVERIFY2(peer.waitFor(u"matched /fine 1"_s), qPrintable(peer.lines().join(u'\n')));
        QVERIFY2(peer.waitFor(u"matched /lossy2 1"_s), qPrintable(peer.lines().join(u'\n')));
        QTRY_VERIFY_WITH_TIMEOUT(received.size() >= 5, 10000);
        QTest::qWait(1000);
        for (const QList<QVariant>& r : std::as_const(received))
            QCOMPARE(r.at(0).toString(), u"/lossy2"_s);
        QVERIFY(!peer.lines().contains(u"matched /strict 1"_s));
        QVERIFY(!peer.lines().contains(u"matched /lossy 1"_s));
    }

    // A node that publishes faster than we take them: 1 MiB samples as fast as the peer sends them
    // (faster than the pipe carries them in a Debug build), and our event loop blocked for 4 s. The
    // child queues within Ros2Endpoints::kMaxQueuedBytes (128 MiB), one batch on its way through
    // the pipe besides (the taken samples counted until written: before, a whole queue waited in
    // the pipe's write while a second one filled), and drops the rest, counted by
    // droppedReceived(); this process holds a frame at a time. The child's growth is counted from
    // its resident set on the domain before any sample.
    void aFloodWhileWeDoNotReadStaysWithinTheBounds()
    {
        Ros2Participant p;
        quint64 samples = 0;
        connect(&p.node(), &Ros2EndpointLink::received, this, [&samples](const QString&, const Ros2Sample&) { ++samples; });
        Ros2Qos q;
        q.depth = 100;
        p.node().subscribe(u"/flood"_s, u"sensor_msgs/msg/PointCloud2"_s, q);
        QSignalSpy joined(&p, &Ros2Participant::joined);
        QString error;
        QVERIFY2(noted(p.start({m_domain, true}), &error), qPrintable(error));
        QVERIFY(joined.wait(10000));
        const qint64 child = DdsChild::of();
        QVERIFY(child > 0);
        QTest::qWait(500);
        const qint64 childIdle = PeakRss::of(child); // on the domain, nothing received yet
        Ros2Peer talker(m_domain, {u"--node"_s, u"/flooder"_s, u"--pub"_s,
                                   u"/flood:sensor_msgs/msg/PointCloud2:1000:reliable,depth=100"_s,
                                   u"--size"_s, u"1048576"_s, u"--duration"_s, u"30"_s});
        QVERIFY2(talker.waitFor(u"ready"_s), qPrintable(talker.errors()));
        QTRY_VERIFY_WITH_TIMEOUT(samples > 0, 15000);
        QVERIFY(PeakRss::reset());
        const qint64 ownBase = PeakRss::of();
        std::this_thread::sleep_for(std::chrono::seconds(4)); // no event loop: the pipe stays full
        QTRY_VERIFY_WITH_TIMEOUT(p.node().droppedReceived() > 0, 5000);
        QTest::qWait(1000); // what waited comes
        const qint64 childGrew = PeakRss::of(child) - childIdle;
        const qint64 ownGrew = PeakRss::of() - ownBase;
        qInfo("%llu samples, %llu dropped; the child grew by %.1f MiB from %.1f MiB, this process by %.1f MiB",
              samples, p.node().droppedReceived(), double(childGrew) / (1 << 20), double(childIdle) / (1 << 20),
              double(ownGrew) / (1 << 20));
        QCOMPARE(DdsChild::of(), child); // not restarted for it
        constexpr qint64 kSlack = 32LL << 20; // allocation slack
        constexpr qint64 kChildQueue = 128LL << 20; // Ros2Endpoints::kMaxQueuedBytes (core/dds)
        // The queue, a batch on its way and its frame, allocation slack, and what Cyclone holds of
        // a reliable 1 MiB stream sent at 1 kHz while it is reassembled and delivered: that part is
        // not ours and bimodal (17 runs: the child grew by 136-141 MiB, or by 240-248 MiB in a
        // third of them, with or without glibc's dynamic mmap threshold and with Cyclone's
        // delivery queue cut to 16 samples). The bound allows it; 3 GiB are sent meanwhile.
        constexpr qint64 kCyclone = 128LL << 20;
        QVERIFY2(childGrew < kChildQueue + 2 * Ros2Protocol::kBatchBytes + kSlack + kCyclone
                     + PeakRss::kSanitizerSlack,
                 qPrintable(u"the child grew by %1 MiB"_s.arg(childGrew >> 20)));
        QVERIFY2(ownGrew < 2 * Ros2Protocol::kBatchBytes + kSlack + PeakRss::kSanitizerSlack,
                 qPrintable(u"this process grew by %1 MiB"_s.arg(ownGrew >> 20)));
    }
};

QTEST_GUILESS_MAIN(TestRos2Endpoints)
#include "tst_ros2endpoints.moc"
