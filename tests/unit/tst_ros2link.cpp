// SPDX-License-Identifier: MIT
// Ros2Link without a child process: frames fed by hand, what it sends read back from a pipe that
// records (issue 42: the parent side of the participant, tested alone).
#include "ros2/ros2link.h"

#include <QSignalSpy>
#include <QTest>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

namespace {

/// A child that is up (or not) and keeps every frame sent to it.
class RecordingPipe : public DdsChildPipe
{
public:
    bool up = true;
    qint64 pending = 0;
    QList<Ros2Protocol::Frame> sent;

    bool hasChild() const override { return up; }
    bool childRunning() const override { return up; }
    qint64 bytesToWrite() const override { return pending; }
    void send(Kind kind, const QByteArray& body) override
    {
        if (up)
            sent.append({kind, body});
    }

    /// Each frame as "Kind topic" (the first string of its body where it has one).
    QStringList said() const
    {
        QStringList out;
        for (const Ros2Protocol::Frame& f : sent)
            out << describe(f);
        return out;
    }

private:
    static QString describe(const Ros2Protocol::Frame& f)
    {
        switch (f.kind) {
        case Kind::Start:
            return u"Start"_s;
        case Kind::KeepArrivals:
            return u"KeepArrivals %1"_s.arg(Ros2Protocol::decodeNumber(f.body).value_or(0));
        case Kind::Watch: {
            const auto w = Ros2Protocol::decodeWatch(f.body);
            return u"Watch %1 %2"_s.arg(w ? w->topic : u"?"_s).arg(w ? w->maxMessages : 0);
        }
        case Kind::Advertise:
        case Kind::Subscribe: {
            const auto e = Ros2Protocol::decodeEndpoint(f.body);
            return (f.kind == Kind::Advertise ? u"Advertise "_s : u"Subscribe "_s) + (e ? e->topic : u"?"_s);
        }
        case Kind::Monitor:
        case Kind::Unmonitor:
        case Kind::Unwatch:
        case Kind::Unadvertise: {
            const auto s = Ros2Protocol::decodeStrings(f.body, 1);
            return QString::fromLatin1(kindName(f.kind)) + u' ' + (s ? s->first() : u"?"_s);
        }
        case Kind::SetNode: {
            const auto s = Ros2Protocol::decodeStrings(f.body, 2);
            return u"SetNode "_s + (s ? s->join(u' ') : u"?"_s);
        }
        default:
            return u"kind %1"_s.arg(int(f.kind));
        }
    }
    static const char* kindName(Kind k)
    {
        switch (k) {
        case Kind::Monitor:
            return "Monitor";
        case Kind::Unmonitor:
            return "Unmonitor";
        case Kind::Unwatch:
            return "Unwatch";
        default:
            return "Unadvertise";
        }
    }
};

const QString kString = u"std_msgs/msg/String"_s;

Ros2Protocol::Frame endpointDone(bool advertise, const QString& topic, const QString& why = {})
{
    return {Kind::EndpointDone, Ros2Protocol::encodeEndpointDone({advertise, topic, kString, why})};
}

Ros2Protocol::Frame graphWith(const QString& topic, int participants)
{
    Ros2Protocol::GraphUpdate g;
    g.graph.participants = participants;
    Ros2Topic t;
    t.name = topic;
    t.types = {kString};
    g.graph.topics = {t};
    g.badDiscoveryInfo = 2;
    return {Kind::Graph, Ros2Protocol::encodeGraph(g)};
}

Ros2Protocol::Frame samples(const QString& topic, std::vector<Ros2Sample> s, quint64 dropped = 0)
{
    return {Kind::Samples, Ros2Protocol::encodeSamples({topic, dropped, std::move(s)})};
}

const QByteArray kCdr = QByteArray::fromHex("0001000006000000686f6c610000");

} // namespace

class TestRos2Link : public QObject
{
    Q_OBJECT
private slots:
    void replaysEverythingAskedAfterARestart();
    void aRequestTheChildDiedOnIsQuarantinedNotReplayed();
    void anAnsweredRequestIsNotQuarantined();
    void aRefusedEndpointIsForgotten();
    void monitorUsesAreCounted();
    void eachOwnerOfAWatchedTopicGetsEverySample();
    void framesTheChildMayNotSendDoNotRead();
    void peersCauseAnEndWhenOthersAreOnTheDomain();
    void publishKeepsItsBound();
    void eachHeadTapGetsEveryHeadAndTheChildKeepsForTheLargest();
};

void TestRos2Link::replaysEverythingAskedAfterARestart()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    pipe.up = false; // asked before start(): made once a child runs
    link.monitor(u"/a"_s);
    link.monitor(u"/a"_s);
    link.watches().openQueue(u"/w"_s, 5, 1000, nullptr);
    const std::unique_ptr<HeadTap> heads = link.openHeadTap(7);
    link.endpoints().setNode(u"/ns"_s, u"bridge"_s);
    QVERIFY(link.endpoints().advertise(u"/out"_s, kString, {}));
    QVERIFY(link.endpoints().subscribe(u"/in"_s, kString, {}));

    pipe.up = true;
    pipe.sent.clear();
    link.replay({});
    QCOMPARE(pipe.said(),
             QStringList({u"Start"_s, u"KeepArrivals 7"_s, u"Watch /w 5"_s, u"Monitor /a"_s,
                          u"Advertise /out"_s, u"Subscribe /in"_s, u"SetNode /ns bridge"_s}));
    QVERIFY(link.makingRequests());
    QVERIFY(link.handle(endpointDone(true, u"/out"_s)));
    QVERIFY(link.handle(endpointDone(false, u"/in"_s)));
    QVERIFY(!link.makingRequests());

    // a child that ends after it answered: the next is asked the same
    QSignalSpy refused(&link.endpoints(), &Ros2EndpointLink::endpointRefused);
    link.childLost(u"crashed (signal 11)"_s);
    QCOMPARE(refused.count(), 0);
    pipe.sent.clear();
    link.replay({});
    QCOMPARE(pipe.said(),
             QStringList({u"Start"_s, u"KeepArrivals 7"_s, u"Watch /w 5"_s, u"Monitor /a"_s,
                          u"Advertise /out"_s, u"Subscribe /in"_s, u"SetNode /ns bridge"_s}));
    const auto start = Ros2Protocol::decodeStart(pipe.sent.first().body);
    QVERIFY(start);
    QCOMPARE(start->graphIntervalMs, 250);
}

void TestRos2Link::aRequestTheChildDiedOnIsQuarantinedNotReplayed()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QVERIFY(link.endpoints().advertise(u"/out"_s, kString, {}));
    QVERIFY(link.endpoints().subscribe(u"/in"_s, kString, {}));
    QVERIFY(link.handle(endpointDone(false, u"/in"_s))); // answered: not what the child died on
    QVERIFY(link.makingRequests());
    QVERIFY(link.causedByPeers(false));

    QSignalSpy refused(&link.endpoints(), &Ros2EndpointLink::endpointRefused);
    link.childLost(u"crashed (signal 6)"_s);
    const QString reason
        = u"the DDS process crashed (signal 6) while making it: quarantined, not asked again"_s;
    QCOMPARE(refused.count(), 1);
    QCOMPARE(refused.at(0).at(0).toString(), u"/out"_s);
    QCOMPARE(refused.at(0).at(1).toString(), reason);
    QCOMPARE(link.endpoints().quarantined(), 1);
    QCOMPARE(link.endpoints().lastQuarantineReason(), u"/out: "_s + reason);
    QVERIFY(!link.endpoints().isAdvertised(u"/out"_s));
    QVERIFY(link.endpoints().isSubscribed(u"/in"_s));

    pipe.sent.clear();
    link.replay({});
    QCOMPARE(pipe.said(), QStringList({u"Start"_s, u"Subscribe /in"_s}));

    // asked again as it was: refused at once, never sent
    pipe.sent.clear();
    QVERIFY(!link.endpoints().advertise(u"/out"_s, kString, {}));
    QCOMPARE(refused.count(), 2);
    QCOMPARE(refused.at(1).at(1).toString(), reason);
    QVERIFY(pipe.sent.isEmpty());
    // another type on the topic is another request
    QVERIFY(link.endpoints().advertise(u"/out"_s, u"std_msgs/msg/Int32"_s, {}));
    QCOMPARE(pipe.said(), QStringList({u"Advertise /out"_s}));
}

void TestRos2Link::anAnsweredRequestIsNotQuarantined()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QVERIFY(link.endpoints().advertise(u"/out"_s, kString, {}));
    QVERIFY(link.handle(endpointDone(true, u"/out"_s)));
    link.endpoints().unadvertise(u"/out"_s);
    QVERIFY(!link.makingRequests());
    link.childLost(u"crashed (signal 11)"_s);
    QCOMPARE(link.endpoints().quarantined(), 0);
}

void TestRos2Link::aRefusedEndpointIsForgotten()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QSignalSpy refused(&link.endpoints(), &Ros2EndpointLink::endpointRefused);
    QVERIFY(!link.endpoints().advertise(u"/bad topic"_s, kString, {}));
    QCOMPARE(refused.count(), 1);
    QVERIFY(pipe.sent.isEmpty());

    QVERIFY(link.endpoints().advertise(u"/out"_s, kString, {}));
    QVERIFY(link.handle(endpointDone(true, u"/out"_s, u"Cyclone said no"_s)));
    QCOMPARE(refused.count(), 2);
    QCOMPARE(refused.at(1).at(1).toString(), u"Cyclone said no"_s);
    QVERIFY(!link.endpoints().isAdvertised(u"/out"_s));
    QCOMPARE(link.endpoints().quarantined(), 0);
    pipe.sent.clear();
    link.replay({});
    QCOMPARE(pipe.said(), QStringList({u"Start"_s}));
}

void TestRos2Link::monitorUsesAreCounted()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QSignalSpy failed(&link, &Ros2Link::monitorFailed);
    link.monitor(u"/a"_s); // the child's graph does not have it
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.at(0).at(1).toString(),
             u"/a has no publisher or subscriber yet, so its type is not known"_s);
    QVERIFY(pipe.sent.isEmpty());

    QVERIFY(link.handle(graphWith(u"/a"_s, 1)));
    QCOMPARE(link.badDiscoveryInfo(), quint64(2));
    link.monitor(u"/a"_s);
    link.monitor(u"/a"_s);
    QVERIFY(link.isMonitored(u"/a"_s));
    link.unmonitor(u"/a"_s);
    QCOMPARE(pipe.said(), QStringList({u"Monitor /a"_s}));
    link.unmonitor(u"/a"_s);
    QCOMPARE(pipe.said(), QStringList({u"Monitor /a"_s, u"Unmonitor /a"_s}));
    QVERIFY(!link.isMonitored(u"/a"_s));

    // the child's figures of a topic no longer monitored are left out
    Ros2Protocol::TopicStats t;
    t.topic = u"/a"_s;
    QVERIFY(link.handle({Kind::Stats, Ros2Protocol::encodeStats({t})}));
    QVERIFY(link.stats().isEmpty());
}

void TestRos2Link::eachOwnerOfAWatchedTopicGetsEverySample()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    int plot = 0, stamps = 0;
    link.watches().openQueue(u"/w"_s, 2, 1 << 20, &plot);
    link.watches().openQueue(u"/w"_s, 10, 1 << 20, &stamps);
    QCOMPARE(pipe.said(), QStringList({u"Watch /w 2"_s, u"Watch /w 10"_s}));
    QVERIFY(link.handle(samples(u"/w"_s, {{1, kCdr}, {2, kCdr}, {3, kCdr}}, 4)));
    QCOMPARE(link.watches().takeQueued(u"/w"_s, &plot).size(), std::size_t(2));
    QCOMPARE(link.watches().droppedQueued(u"/w"_s, &plot), quint64(1 + 4));
    QCOMPARE(link.watches().takeQueued(u"/w"_s, &stamps).size(), std::size_t(3));
    QCOMPARE(link.watches().droppedQueued(u"/w"_s, &stamps), quint64(4));

    link.watches().closeQueue(u"/w"_s, &stamps);
    QCOMPARE(pipe.said().last(), u"Watch /w 2"_s);
    link.watches().closeQueue(u"/w"_s, &plot);
    QCOMPARE(pipe.said().last(), u"Unwatch /w"_s);
    QVERIFY(link.handle(samples(u"/w"_s, {{4, kCdr}}))); // unwatched since the child sent it
    QVERIFY(!link.watches().isWatched(u"/w"_s));
}

void TestRos2Link::framesTheChildMayNotSendDoNotRead()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QVERIFY(link.handle({Kind::Heartbeat, {}}));
    QVERIFY(!link.handle({Kind::Heartbeat, "x"}));
    QVERIFY(!link.handle({Kind::Monitor, Ros2Protocol::encodeStrings({u"/a"_s})}));
    QVERIFY(!link.handle({Kind::Graph, "\x01\x02"}));
    QVERIFY(!link.handle({Kind::EndpointDone, {}}));

    QSignalSpy started(&link, &Ros2Link::started);
    QSignalSpy startFailed(&link, &Ros2Link::startFailed);
    QVERIFY(link.handle({Kind::Started, {}}));
    QVERIFY(link.handle({Kind::StartFailed, Ros2Protocol::encodeStrings({u"no transport"_s})}));
    QCOMPARE(started.count(), 1);
    QCOMPARE(startFailed.count(), 1);
    QCOMPARE(startFailed.at(0).at(0).toString(), u"no transport"_s);
}

void TestRos2Link::peersCauseAnEndWhenOthersAreOnTheDomain()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QVERIFY(!link.causedByPeers(true));
    QVERIFY(link.handle(graphWith(u"/a"_s, 3)));
    QVERIFY(link.causedByPeers(true));
    QVERIFY(!link.causedByPeers(false)); // ended as asked, or by its exit code: not a peer's doing
    link.childLost(u"sent nothing for 10 s"_s);
    QCOMPARE(link.graph().participants, 0);
    QVERIFY(!link.causedByPeers(true));
}

void TestRos2Link::publishKeepsItsBound()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    QVERIFY(!link.endpoints().publish(u"/out"_s, kCdr)); // not advertised
    QVERIFY(link.endpoints().advertise(u"/out"_s, kString, {}));
    QVERIFY(link.endpoints().publish(u"/out"_s, kCdr));
    link.endpoints().setPublishBound(16);
    pipe.pending = 8;
    QVERIFY(!link.endpoints().publish(u"/out"_s, kCdr)); // 8 waiting + 14 is over 16
    pipe.pending = 0;
    QVERIFY(link.endpoints().publish(u"/out"_s, kCdr + kCdr)); // larger than the bound, but nothing waits
    QVERIFY(!link.endpoints().publish(u"/out"_s, QByteArray("\x00\x01", 2))); // not CDR
    pipe.up = false;
    QVERIFY(!link.endpoints().publish(u"/out"_s, kCdr));
    QCOMPARE(link.endpoints().publishDropped(), quint64(4));
}

void TestRos2Link::eachHeadTapGetsEveryHeadAndTheChildKeepsForTheLargest()
{
    RecordingPipe pipe;
    Ros2Link link(pipe);
    pipe.up = false; // monitored before the child knows the topic: asked once it runs
    link.monitor(u"/a"_s);
    pipe.up = true;
    std::unique_ptr<HeadTap> small = link.openHeadTap(2);
    std::unique_ptr<HeadTap> large = link.openHeadTap(50);
    std::unique_ptr<HeadTap> middle = link.openHeadTap(9); // not the largest: nothing to ask
    QCOMPARE(pipe.said(), QStringList({u"KeepArrivals 2"_s, u"KeepArrivals 50"_s}));

    const auto arrivals = [](quint64 dropped, int heads) {
        Ros2Protocol::ArrivalBatch b;
        b.dropped = dropped;
        for (int i = 0; i < heads; ++i)
            b.arrivals.push_back(
                {SourceGraph::Ros2, i % 2 ? u"/unmonitored"_s : u"/a"_s, i, 8, "head", std::nullopt});
        return Ros2Protocol::Frame {Kind::Arrivals, Ros2Protocol::encodeArrivals(b)};
    };
    QVERIFY(link.handle(arrivals(3, 8))); // four of /a; the child dropped three
    QCOMPARE(small->take().size(), std::size_t(2));
    QCOMPARE(small->dropped(), quint64(2 + 3));
    QCOMPARE(large->take().size(), std::size_t(4));
    QCOMPARE(large->dropped(), quint64(3));
    QVERIFY(link.handle(arrivals(5, 0))); // the child's count is cumulative: two more
    QCOMPARE(large->dropped(), quint64(5));
    QCOMPARE(middle->dropped(), quint64(5));

    pipe.sent.clear();
    large.reset();
    middle.reset();
    small.reset();
    QCOMPARE(pipe.said(), QStringList({u"KeepArrivals 9"_s, u"KeepArrivals 2"_s, u"KeepArrivals 0"_s}));
}

QTEST_GUILESS_MAIN(TestRos2Link)
#include "tst_ros2link.moc"
