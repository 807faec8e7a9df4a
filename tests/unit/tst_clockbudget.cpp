// SPDX-License-Identifier: MIT
// ClockBudget, the clock service's rate limits: per peer, in total, and over a bounded number of peers.
#include "clock/clockbudget.h"

#include <QTest>

namespace {
constexpr qint64 kS = 1'000'000'000;

/// How many of `n` probes from `peer`, evenly spread over `seconds` from `startNs`, are allowed.
int allowed(ClockBudget& b, const QString& peer, int n, double seconds, qint64 startNs = kS)
{
    int ok = 0;
    for (int i = 0; i < n; ++i)
        ok += b.allow(peer, startNs + qint64(seconds * double(kS) * i / n)) ? 1 : 0;
    return ok;
}
} // namespace

class TestClockBudget : public QObject
{
    Q_OBJECT

private slots:
    void perPeerRateHolds()
    {
        ClockBudget b;
        // 1000 probes in 10 s from one peer: a burst of 20, then 20 per second.
        const int ok = allowed(b, QStringLiteral("10.0.0.1"), 1000, 10);
        QVERIFY2(ok >= 215 && ok <= 221, qPrintable(QString::number(ok)));
        // Another peer has its own bucket.
        QCOMPARE(allowed(b, QStringLiteral("10.0.0.2"), 10, 1, 11 * kS), 10);
    }

    void aProberAtOneHertzWithItsBurstIsNeverDropped()
    {
        ClockBudget b;
        QCOMPARE(allowed(b, QStringLiteral("p"), 8, 0.4), 8); // the start burst, 50 ms apart
        QCOMPARE(allowed(b, QStringLiteral("p"), 60, 60, 2 * kS), 60);
    }

    void totalRateHolds()
    {
        ClockBudget b(20, 500, 100000);
        int ok = 0;
        // 2000 peers at 10 Hz each for 2 s: 40,000 probes, of which 500/s (plus the first second's 500).
        for (int step = 0; step < 20; ++step)
            for (int p = 0; p < 2000; ++p)
                ok += b.allow(QString::number(p), kS + step * kS / 10 + p) ? 1 : 0;
        QVERIFY2(ok >= 1400 && ok <= 1500, qPrintable(QString::number(ok)));
    }

    void peersAreBounded()
    {
        ClockBudget b(20, 1e9, 4);
        for (int p = 0; p < 4; ++p)
            QVERIFY(b.allow(QString::number(p), kS));
        QVERIFY(!b.allow(QStringLiteral("fifth"), kS)); // all four busy
        QCOMPARE(b.peers(), 4);
        // Two seconds later the four are idle (buckets full again) and forgotten.
        QVERIFY(b.allow(QStringLiteral("fifth"), 3 * kS));
        QCOMPARE(b.peers(), 1);
    }
};

QTEST_APPLESS_MAIN(TestClockBudget)
#include "tst_clockbudget.moc"
