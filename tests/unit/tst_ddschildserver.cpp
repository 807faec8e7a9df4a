// SPDX-License-Identifier: MIT
// The request side of bridgescope-dds (DdsChildServer, issue 42 point 2): the parent's bytes cut
// into frames, each request one call of the participant, names checked before DDS sees them, every
// Advertise and Subscribe answered, a bounded number of requests a turn, and a stream that does
// not read ends the child with the reason. The participant here records what reaches it (the
// child's engine joins a domain; tst_ros2bridge and tst_ros2hostile run that one).
#include "ros2/ddschildserver.h"

#include <QTest>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

namespace {

class RecordingEngine : public Ros2ChildEngine
{
public:
    QStringList calls;
    bool startOk = true;
    QString refuseType; ///< advertise() and subscribeSamples() refuse it, saying nothing

    Status start(const Ros2Options& options) override
    {
        calls << u"start %1 %2"_s.arg(options.domain).arg(options.localhostOnly);
        if (!startOk)
            return LocatedError {u"no domain"_s};
        return {};
    }
    void setGraphInterval(int ms) override { calls << u"interval %1"_s.arg(ms); }
    void monitor(const QString& topic, bool waitForType) override
    {
        calls << u"monitor %1 %2"_s.arg(topic).arg(waitForType);
    }
    void unmonitor(const QString& topic) override { calls << u"unmonitor "_s + topic; }
    void watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override
    {
        calls << u"watch %1 %2 %3"_s.arg(topic).arg(maxMessages).arg(maxBytes);
    }
    void unwatchMessages(const QString& topic) override { calls << u"unwatch "_s + topic; }
    void keepArrivals(std::size_t maxArrivals) override { calls << u"keep %1"_s.arg(maxArrivals); }
    void setNode(const QString& nameSpace, const QString& name) override
    {
        calls << u"node %1 %2"_s.arg(nameSpace, name);
    }
    Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        calls << u"advertise %1 %2 %3"_s.arg(topic, type).arg(qos.depth);
        return refusal(type);
    }
    void unadvertise(const QString& topic) override { calls << u"unadvertise "_s + topic; }
    bool publish(const QString& topic, const QByteArray& cdr) override
    {
        calls << u"publish %1 %2"_s.arg(topic).arg(cdr.size());
        return true;
    }
    Status subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        calls << u"subscribe %1 %2 %3"_s.arg(topic, type).arg(qos.depth);
        return refusal(type);
    }
    void unsubscribeSamples(const QString& topic) override { calls << u"unsubscribe "_s + topic; }

private:
    Status refusal(const QString& type) const
    {
        if (type == refuseType)
            return LocatedError {}; // refused, saying nothing
        return {};
    }
};

struct Sent
{
    Kind kind;
    QByteArray body;
};

QByteArray endpoint(Kind kind, const QString& topic, const QString& type, int depth = 10)
{
    Ros2Protocol::EndpointRequest r;
    r.topic = topic;
    r.type = type;
    r.qos.depth = depth;
    return Ros2Protocol::frame(kind, Ros2Protocol::encodeEndpoint(r));
}

QByteArray strings(Kind kind, const QStringList& s)
{
    return Ros2Protocol::frame(kind, Ros2Protocol::encodeStrings(s));
}

} // namespace

class TestDdsChildServer : public QObject
{
    Q_OBJECT

    RecordingEngine m_engine;
    std::vector<Sent> m_sent;
    std::unique_ptr<DdsChildServer> m_server;

    std::vector<Ros2Protocol::EndpointDone> answers() const
    {
        std::vector<Ros2Protocol::EndpointDone> out;
        for (const Sent& s : m_sent)
            if (s.kind == Kind::EndpointDone) {
                const auto d = Ros2Protocol::decodeEndpointDone(s.body);
                if (d)
                    out.push_back(*d);
            }
        return out;
    }

private slots:
    void init()
    {
        m_engine = RecordingEngine();
        m_sent.clear();
        m_server = std::make_unique<DdsChildServer>(
            m_engine, [this](Kind kind, const QByteArray& body) { m_sent.push_back({kind, body}); });
    }

    // Start joins the domain and says so; a participant that cannot join says why.
    void startIsAnsweredEitherWay()
    {
        Ros2Protocol::StartRequest r;
        r.options.domain = 42;
        r.options.localhostOnly = true;
        r.graphIntervalMs = 300;
        m_server->append(Ros2Protocol::frame(Kind::Start, Ros2Protocol::encodeStart(r)));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_engine.calls, (QStringList {u"interval 300"_s, u"start 42 1"_s}));
        QCOMPARE(m_sent.size(), 1u);
        QCOMPARE(m_sent[0].kind, Kind::Started);

        m_engine.startOk = false;
        m_server->append(Ros2Protocol::frame(Kind::Start, Ros2Protocol::encodeStart(r)));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_sent.size(), 2u);
        QCOMPARE(m_sent[1].kind, Kind::StartFailed);
        QCOMPARE(Ros2Protocol::decodeStrings(m_sent[1].body, 1).value_or(QStringList {}),
                 QStringList {u"no domain"_s});
    }

    // A frame cut anywhere is handled once it is whole, however the pipe delivered it.
    void framesCutAnywhereAreHandledWhenWhole()
    {
        const QByteArray bytes = strings(Kind::Monitor, {u"/chatter"_s}) + strings(Kind::Unmonitor, {u"/chatter"_s});
        for (qsizetype i = 0; i < bytes.size(); ++i) {
            m_server->append(bytes.mid(i, 1));
            QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        }
        QCOMPARE(m_engine.calls, (QStringList {u"monitor /chatter 1"_s, u"unmonitor /chatter"_s}));
        QCOMPARE(m_server->pending(), 0);
    }

    // Every Advertise and Subscribe is answered: made, refused by the participant (with a reason
    // even when it gave none), or refused before DDS for a name DDS may not be given.
    void everyEndpointIsAnsweredAndBadNamesNeverReachDds()
    {
        m_engine.refuseType = u"pkg/msg/Refused"_s;
        const QString longType = u"pkg/msg/"_s + QString(300, u'A');
        m_server->append(endpoint(Kind::Advertise, u"/a"_s, u"std_msgs/msg/String"_s)
                         + endpoint(Kind::Subscribe, u"/b"_s, u"pkg/msg/Refused"_s, 5)
                         + endpoint(Kind::Advertise, u"/1bad"_s, u"std_msgs/msg/String"_s)
                         + endpoint(Kind::Subscribe, u"/c"_s, longType)
                         + endpoint(Kind::Advertise, u"/d"_s, u"not a type"_s));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_engine.calls, (QStringList {u"advertise /a std_msgs/msg/String 10"_s,
                                               u"subscribe /b pkg/msg/Refused 5"_s}));
        const auto done = answers();
        QCOMPARE(done.size(), 5u);
        QVERIFY(done[0].advertise && done[0].topic == u"/a"_s && done[0].why.isEmpty());
        QVERIFY(!done[1].advertise && done[1].topic == u"/b"_s);
        QCOMPARE(done[1].why, u"Cyclone DDS refused it"_s);
        for (std::size_t i = 2; i < done.size(); ++i)
            QVERIFY2(!done[i].why.isEmpty(), qPrintable(done[i].topic));
        QCOMPARE(done[3].type, longType); // said back as asked, so that the parent finds its request
    }

    // Watch and Unwatch keep the set the drain reads; Unmonitor forgets what was sent of a topic.
    void watchedTopicsAndSentCountsFollowTheRequests()
    {
        m_server->append(Ros2Protocol::frame(Kind::Watch, Ros2Protocol::encodeWatch({u"/w"_s, 50, 4096}))
                         + Ros2Protocol::frame(Kind::Watch, Ros2Protocol::encodeWatch({u"/x"_s, 1, 0})));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_server->watched(), (std::set<QString> {u"/w"_s, u"/x"_s}));
        m_server->sentMessages()[u"/w"_s] = 7;
        m_server->append(strings(Kind::Unwatch, {u"/x"_s}) + strings(Kind::Unmonitor, {u"/w"_s}));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_server->watched(), (std::set<QString> {u"/w"_s}));
        QVERIFY(m_server->sentMessages().empty());
        QCOMPARE(m_engine.calls, (QStringList {u"watch /w 50 4096"_s, u"watch /x 1 0"_s, u"unwatch /x"_s,
                                               u"unmonitor /w"_s}));
    }

    // The rest of the requests, each one call with what the frame says.
    void eachRequestIsOneCall()
    {
        m_server->append(strings(Kind::SetNode, {u"/ns"_s, u"bridge"_s})
                         + Ros2Protocol::frame(Kind::KeepArrivals, Ros2Protocol::encodeNumber(1000))
                         + Ros2Protocol::frame(Kind::GraphInterval, Ros2Protocol::encodeNumber(500))
                         + Ros2Protocol::frame(Kind::Publish,
                                               Ros2Protocol::encodePublish({u"/a"_s, QByteArray("\0\1\0\0abcd", 8)}))
                         + strings(Kind::Unadvertise, {u"/a"_s}) + strings(Kind::Unsubscribe, {u"/b"_s}));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_engine.calls, (QStringList {u"node /ns bridge"_s, u"keep 1000"_s, u"interval 500"_s,
                                               u"publish /a 8"_s, u"unadvertise /a"_s, u"unsubscribe /b"_s}));
        QVERIFY(m_sent.empty()); // none of these is answered
    }

    // However many requests wait, a turn handles at most its count (the child's heartbeat and
    // drain run between turns, issue 41); the rest are handled by the next turns, in order.
    void aTurnIsBounded()
    {
        QByteArray bytes;
        for (int i = 0; i < 150; ++i)
            bytes += strings(Kind::Monitor, {u"/t%1"_s.arg(i)});
        m_server->append(bytes);
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::More);
        QCOMPARE(m_engine.calls.size(), DdsChildServer::kFramesPerTurn);
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::More);
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Idle);
        QCOMPARE(m_engine.calls.size(), 150);
        QCOMPARE(m_engine.calls.last(), u"monitor /t149 1"_s);
        QCOMPARE(m_server->handlePending(3), DdsChildServer::Turn::Idle);
    }

    // A request that does not read, or values out of range, end the child with the reason
    // (the parent's own bug: it checks everything it sends); nothing of it reaches the participant.
    void aRequestThatDoesNotReadFails_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("error");
        QTest::newRow("graph interval 0")
            << Ros2Protocol::frame(Kind::GraphInterval, Ros2Protocol::encodeNumber(0)) << u"kind 7"_s;
        QTest::newRow("graph interval over an hour")
            << Ros2Protocol::frame(Kind::GraphInterval, Ros2Protocol::encodeNumber(3'600'001)) << u"kind 7"_s;
        QTest::newRow("arrival bound too large")
            << Ros2Protocol::frame(Kind::KeepArrivals, Ros2Protocol::encodeNumber(100'000'001)) << u"kind 6"_s;
        QTest::newRow("monitor without its topic") << Ros2Protocol::frame(Kind::Monitor, {}) << u"kind 2"_s;
        QTest::newRow("set node with one name") << strings(Kind::SetNode, {u"/ns"_s}) << u"kind 8"_s;
        QTest::newRow("a kind the child never gets") << Ros2Protocol::frame(Kind::Heartbeat, {}) << u"kind 71"_s;
        QTest::newRow("publish cut short") << Ros2Protocol::frame(Kind::Publish, QByteArray("\0\0\0\5/a", 6))
                                           << u"kind 11"_s;
    }
    void aRequestThatDoesNotReadFails()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, error);
        m_server->append(bytes + strings(Kind::Monitor, {u"/after"_s}));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Failed);
        QVERIFY2(m_server->error().contains(error), qPrintable(m_server->error()));
        QVERIFY2(!m_engine.calls.join(u' ').contains(u"/after"_s), qPrintable(m_engine.calls.join(u", "_s)));
    }

    // A stream that is not frames (a length past the bound) fails as the reader says.
    void aStreamThatIsNotFramesFails()
    {
        m_server->append(QByteArray("\xff\xff\xff\xff\x02", 5));
        QCOMPARE(m_server->handlePending(), DdsChildServer::Turn::Failed);
        QVERIFY(!m_server->error().isEmpty());
        QVERIFY(m_engine.calls.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestDdsChildServer)
#include "tst_ddschildserver.moc"
