// SPDX-License-Identifier: MIT
// ClockEstimator: the far clock's offset from four-timestamp probes lies within the stated
// uncertainty of the truth whenever both legs of every probe take no negative time and the drift
// stays within the allowance; better probes give a smaller uncertainty; bad probes are refused.
#include "clock/clockestimator.h"

#include <cmath>
#include <QRandomGenerator>
#include <QTest>

namespace {
constexpr qint64 kStart = 1'800'000'000'000'000'000LL; // 2027, ns since the epoch
constexpr qint64 kMs = 1'000'000;

/// A far clock: offset + drift·(t − kStart) ahead of ours, processing a probe in `serverNs`.
struct FarClock
{
    qint64 offsetNs = 0;
    double driftPpm = 0;

    qint64 at(qint64 ourNs) const
    {
        return ourNs + offsetNs + qint64(std::llround(driftPpm * 1e-6 * double(ourNs - kStart)));
    }
    qint64 trueOffset(qint64 ourNs) const { return at(ourNs) - ourNs; }

    /// Adds one probe sent at `t1` with the given legs and processing time (our ns).
    void probe(ClockEstimator& e, qint64 t1, qint64 outNs, qint64 serverNs, qint64 backNs) const
    {
        QVERIFY(e.add(t1, at(t1 + outNs), at(t1 + outNs + serverNs), t1 + outNs + serverNs + backNs));
    }
};
} // namespace

class TestClockEstimator : public QObject
{
    Q_OBJECT

private slots:
    void trueOffsetLiesWithinTheUncertainty_data()
    {
        QTest::addColumn<qint64>("offsetNs");
        QTest::addColumn<double>("driftPpm");
        QTest::addColumn<qint64>("maxLegNs");
        QTest::newRow("same clock, loopback") << qint64(0) << 0.0 << qint64(200'000);
        QTest::newRow("+35 ms, LAN") << qint64(35 * kMs) << 3.0 << qint64(2 * kMs);
        QTest::newRow("-250 ms, 5G") << qint64(-250 * kMs) << -15.0 << qint64(40 * kMs);
        QTest::newRow("drift at the allowance")
            << qint64(7 * kMs) << ClockEstimator::kDriftAllowancePpm << qint64(10 * kMs);
        QTest::newRow("a day ahead, slow path") << qint64(86'400'000 * kMs) << -20.0 << qint64(500 * kMs);
    }
    void trueOffsetLiesWithinTheUncertainty()
    {
        QFETCH(qint64, offsetNs);
        QFETCH(double, driftPpm);
        QFETCH(qint64, maxLegNs);
        const FarClock far {offsetNs, driftPpm};
        QRandomGenerator random(43);
        for (int run = 0; run < 20; ++run) {
            ClockEstimator e(QStringLiteral("cloud"));
            qint64 t = kStart + qint64(random.bounded(1000)) * kMs;
            for (int i = 0; i < 400; ++i) {
                // Asymmetric on purpose: one leg often far longer than the other.
                const qint64 out = qint64(random.bounded(double(maxLegNs)));
                const qint64 back = random.bounded(4) == 0
                    ? qint64(random.bounded(double(maxLegNs)))
                    : qint64(random.bounded(double(maxLegNs) / 20 + 1));
                const qint64 server = qint64(random.bounded(50'000));
                far.probe(e, t, out, server, back);
                const qint64 now = t + out + server + back + qint64(random.bounded(3'000)) * kMs;
                const ClockEstimate est = e.estimate(now);
                QVERIFY(est.isValid());
                const qint64 error = std::llabs(est.offsetNs - far.trueOffset(now));
                if (error > est.uncertaintyNs)
                    QFAIL(qPrintable(QStringLiteral("run %1 probe %2: error %3 ns > uncertainty %4 ns")
                                         .arg(run)
                                         .arg(i)
                                         .arg(error)
                                         .arg(est.uncertaintyNs)));
                t += qint64(random.bounded(500, 1500)) * kMs;
            }
        }
    }

    void driftIsMeasuredOnceProbesSpanTenSeconds()
    {
        const FarClock far {12 * kMs, 8.0};
        ClockEstimator e;
        for (int i = 0; i < 9; ++i)
            far.probe(e, kStart + i * 1000 * kMs, 100'000, 10'000, 100'000);
        QCOMPARE(e.estimate(kStart + 9000 * kMs).driftPpm, 0.0); // 8 s: not yet
        for (int i = 9; i < 30; ++i)
            far.probe(e, kStart + i * 1000 * kMs, 100'000, 10'000, 100'000);
        const ClockEstimate est = e.estimate(kStart + 30'000 * kMs);
        QVERIFY2(std::fabs(est.driftPpm - 8.0) < 0.1, qPrintable(QString::number(est.driftPpm)));
        QCOMPARE(est.probes, 30);
        QCOMPARE(est.host, QString());
    }

    void betterProbesShrinkTheUncertainty()
    {
        const FarClock far {35 * kMs, 0};
        ClockEstimator e;
        far.probe(e, kStart, 5 * kMs, 0, 5 * kMs);
        const qint64 now = kStart + 20 * kMs;
        const ClockEstimate coarse = e.estimate(now);
        QCOMPARE(coarse.bestRoundTripNs, 10 * kMs);
        QVERIFY(coarse.uncertaintyNs >= 5 * kMs);
        far.probe(e, kStart + 10 * kMs, 1 * kMs, 0, 1 * kMs);
        const ClockEstimate fine = e.estimate(now);
        QCOMPARE(fine.bestRoundTripNs, 2 * kMs);
        QVERIFY2(fine.uncertaintyNs < coarse.uncertaintyNs / 4,
                 qPrintable(QString::number(fine.uncertaintyNs)));
        QVERIFY(std::llabs(fine.offsetNs - 35 * kMs) <= fine.uncertaintyNs);
        // A worse probe later does not widen it, and time since the best probe does (the drift allowance).
        far.probe(e, kStart + 15 * kMs, 8 * kMs, 0, 1 * kMs);
        QCOMPARE(e.estimate(now).uncertaintyNs, fine.uncertaintyNs);
        QVERIFY(e.estimate(now + 60'000 * kMs).uncertaintyNs > fine.uncertaintyNs + 1 * kMs);
    }

    void badProbesAreRefusedAndCounted_data()
    {
        QTest::addColumn<qint64>("t1");
        QTest::addColumn<qint64>("t2");
        QTest::addColumn<qint64>("t3");
        QTest::addColumn<qint64>("t4");
        const qint64 t = kStart;
        QTest::newRow("answer before the probe was sent") << t << t << t << t - 1;
        QTest::newRow("server answered before it received") << t << t + 5 << t + 4 << t + 10;
        QTest::newRow("negative round trip") << t << t << t + 20 << t + 10;
        QTest::newRow("before 1970") << qint64(-5) << t << t << t + 10;
        QTest::newRow("zero far time") << t << qint64(0) << qint64(0) << t + 10;
        QTest::newRow("a round trip of two minutes") << t << t << t << t + 120'000 * kMs;
        QTest::newRow("far clock two years ahead")
            << t << t + 2 * ClockEstimator::kMaxOffsetNs << t + 2 * ClockEstimator::kMaxOffsetNs << t + 10;
        QTest::newRow("beyond 2116") << t << std::numeric_limits<qint64>::max() - 10
                                     << std::numeric_limits<qint64>::max() << t + 10;
    }
    void badProbesAreRefusedAndCounted()
    {
        QFETCH(qint64, t1);
        QFETCH(qint64, t2);
        QFETCH(qint64, t3);
        QFETCH(qint64, t4);
        ClockEstimator e;
        QVERIFY(!e.add(t1, t2, t3, t4));
        QCOMPARE(e.refused(), 1);
        QCOMPARE(e.accepted(), 0);
        QVERIFY(!e.estimate(kStart).isValid());
    }

    void windowIsBounded()
    {
        const FarClock far {1 * kMs, 0};
        ClockEstimator e;
        for (int i = 0; i < 1000; ++i)
            far.probe(e, kStart + i * 100 * kMs, 1000, 0, 1000);
        QCOMPARE(e.size(), ClockEstimator::kMaxProbes);
        QCOMPARE(e.accepted(), 1000);
        // Ten minutes later with one probe: the old ones (over five minutes) are gone.
        far.probe(e, kStart + 1000 * 100 * kMs + 600'000 * kMs, 1000, 0, 1000);
        QCOMPARE(e.size(), 1);
        e.clear();
        QVERIFY(!e.estimate(kStart).isValid());
    }
};

QTEST_APPLESS_MAIN(TestClockEstimator)
#include "tst_clockestimator.moc"
