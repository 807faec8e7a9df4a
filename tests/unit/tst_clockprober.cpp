// SPDX-License-Identifier: MIT
// ClockProber (through UdpClockProber, against a hand-made far side on loopback): the burst and
// the pacing, answers matched by nonce and t1, and what is not an answer to one of its probes
// (duplicates, strangers, wrong nonces, another host's name, late ones, garbage) counted, never
// fed to the estimate.
#include "base/wallclock.h"
#include "clock/udpclockprober.h"

#include <QElapsedTimer>
#include <QNetworkDatagram>
#include <QSignalSpy>
#include <QTest>
#include <QUdpSocket>

using namespace Qt::StringLiterals;

namespace {
/// The far side: a socket the test answers from, by hand.
struct FarSide
{
    QUdpSocket socket;
    FarSide() { socket.bind(QHostAddress::LocalHost, 0); }

    /// The next probe and where it came from.
    std::pair<ClockProbe, QNetworkDatagram> nextProbe()
    {
        // The prober's timers run meanwhile: an event loop, not a blocking wait.
        if (!QTest::qWaitFor([this] { return socket.hasPendingDatagrams(); }, 5000))
            return {};
        const QNetworkDatagram d = socket.receiveDatagram();
        return {ClockProbe::decode(d.data()).valueOr({}), d};
    }
    /// A prober of host "cloud" at this side, with `count` probes and the given timings.
    std::unique_ptr<UdpClockProber> prober(qint64 count, int answerTimeoutMs = 2000, int intervalMs = 1000)
    {
        auto p = std::make_unique<UdpClockProber>(u"cloud"_s, QHostAddress::LocalHost, socket.localPort());
        ClockProberOptions o;
        o.count = count;
        o.answerTimeoutMs = answerTimeoutMs;
        o.intervalMs = intervalMs;
        p->setOptions(o);
        return p;
    }
    void send(const QByteArray& bytes, const QNetworkDatagram& to)
    {
        socket.writeDatagram(bytes, to.senderAddress(), quint16(to.senderPort()));
    }
};
} // namespace

class TestClockProber : public QObject
{
    Q_OBJECT

private slots:
    void burstThenInterval()
    {
        FarSide far;
        const auto proberPtr = far.prober(10, 2000, 400);
        UdpClockProber& prober = *proberPtr;
        QElapsedTimer t;
        t.start();
        prober.start();
        QList<qint64> at;
        for (int i = 0; i < 10; ++i) {
            const auto [probe, from] = far.nextProbe();
            QCOMPARE(probe.kind, ClockProbe::Kind::Probe);
            QCOMPARE(probe.name, u"cloud"_s);
            QVERIFY(probe.replyTopic.isEmpty());
            at << t.elapsed();
            const qint64 now = wallClockNs();
            far.send(probe.answer(u"cloud"_s, now, now, {}).encode(), from);
        }
        // Eight within about 8 × 50 ms, then the interval.
        QVERIFY2(at[7] < 1000, qPrintable(QString::number(at[7])));
        QVERIFY2(at[9] - at[8] >= 350, qPrintable(QString::number(at[9] - at[8])));
        QSignalSpy finished(&prober, &ClockProber::finished);
        QVERIFY(finished.wait(5000));
        QCOMPARE(prober.counters().answered, 10);
        QCOMPARE(prober.estimate(wallClockNs()).probes, 10);
    }

    void onlyItsOwnAnswersCount()
    {
        FarSide far;
        const auto proberPtr = far.prober(1, 1000);
        UdpClockProber& prober = *proberPtr;
        QUdpSocket stranger;
        QVERIFY(stranger.bind(QHostAddress::LocalHost, 0));
        QSignalSpy estimates(&prober, &ClockProber::estimateChanged);
        prober.start();
        const auto [probe, from] = far.nextProbe();
        QCOMPARE(probe.kind, ClockProbe::Kind::Probe);
        const qint64 now = wallClockNs();
        ClockProbe wrongNonce = probe;
        ++wrongNonce.nonce;
        ClockProbe wrongT1 = probe;
        --wrongT1.t1;
        // The impostors claim a clock a second ahead: were one taken, the estimate would say so.
        const qint64 ahead = now + 1'000'000'000;
        far.send(wrongNonce.answer(u"cloud"_s, ahead, ahead, {}).encode(), from); // unknown
        far.send(wrongT1.answer(u"cloud"_s, ahead, ahead, {}).encode(), from); // unknown
        far.send(probe.answer(u"edge"_s, ahead, ahead, {}).encode(), from); // another host: unknown
        far.send(probe.encode(), from); // a probe, not an answer: malformed
        far.send("garbage", from); // malformed
        stranger.writeDatagram(probe.answer(u"cloud"_s, ahead, ahead, {}).encode(), QHostAddress::LocalHost,
                               quint16(from.senderPort())); // right bytes, wrong sender: unknown
        far.send(probe.answer(u"cloud"_s, now, now, {}).encode(), from); // the answer
        far.send(probe.answer(u"cloud"_s, now, now, {}).encode(), from); // again: unknown
        QTRY_COMPARE(prober.counters().unknown, 5);
        const ClockProberCounters c = prober.counters();
        QCOMPARE(c.answered, 1);
        QCOMPARE(c.malformed, 2);
        QCOMPARE(c.lost, 0);
        QCOMPARE(estimates.size(), 1);
        QVERIFY2(std::llabs(estimates.first().first().value<ClockEstimate>().offsetNs) < 100'000'000,
                 "an impostor's answer was taken");
        QCOMPARE(prober.farName(), u"cloud"_s);
    }

    void aLateAnswerIsLostThenUnknown()
    {
        FarSide far;
        const auto proberPtr = far.prober(1, 200);
        UdpClockProber& prober = *proberPtr;
        QSignalSpy finished(&prober, &ClockProber::finished);
        prober.start();
        const auto [probe, from] = far.nextProbe();
        QVERIFY(finished.wait(5000)); // given up for lost
        QCOMPARE(prober.counters().lost, 1);
        const qint64 now = wallClockNs();
        far.send(probe.answer(u"cloud"_s, now, now, {}).encode(), from);
        QTRY_COMPARE(prober.counters().unknown, 1);
        QCOMPARE(prober.counters().answered, 0);
        QVERIFY(!prober.estimate(now).isValid());
    }

    void answersTheEstimatorRefusesAreNotEstimates()
    {
        FarSide far;
        const auto proberPtr = far.prober(1);
        UdpClockProber& prober = *proberPtr;
        QSignalSpy estimates(&prober, &ClockProber::estimateChanged);
        QSignalSpy finished(&prober, &ClockProber::finished);
        prober.start();
        const auto [probe, from] = far.nextProbe();
        // The far side claims to have held the probe longer than it was away: a negative round trip.
        const qint64 now = wallClockNs();
        far.send(probe.answer(u"cloud"_s, now - 10'000'000'000LL, now, {}).encode(), from);
        QVERIFY(finished.wait(5000));
        QCOMPARE(prober.counters().answered, 1);
        QCOMPARE(prober.estimator().refused(), 1);
        QCOMPARE(estimates.size(), 0);
    }
};

QTEST_GUILESS_MAIN(TestClockProber)
#include "tst_clockprober.moc"
