// SPDX-License-Identifier: MIT
// Issue 33, point 6: ticks on round numbers in every chart and report (1, 2, 2.5 or 5 times a
// power of ten), never 11.8 / 8.88 / 5.92.
#include "text/niceticks.h"

#include <cmath>
#include <QRandomGenerator>
#include <QTest>

class TestNiceTicks : public QObject
{
    Q_OBJECT

private:
    /// Whether `step` is 1, 2, 2.5 or 5 times a power of ten.
    static bool isRound(double step)
    {
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
        for (double f : {1.0, 2.0, 2.5, 5.0, 10.0})
            if (std::abs(mantissa - f) < 1e-9)
                return true;
        return false;
    }

private slots:
    void stepsAreRound_data()
    {
        QTest::addColumn<double>("lo");
        QTest::addColumn<double>("hi");
        QTest::addColumn<double>("step");
        QTest::newRow("a rate chart's 0..11.8") << 0.0 << 11.8 << 2.5;
        QTest::newRow("0..100") << 0.0 << 100.0 << 20.0;
        QTest::newRow("ms 12..31") << 12.0 << 31.0 << 5.0;
        QTest::newRow("small") << 0.0 << 0.37 << 0.1;
        QTest::newRow("seconds ago") << -59.0 << 0.0 << 20.0;
    }

    void stepsAreRound()
    {
        QFETCH(double, lo);
        QFETCH(double, hi);
        QFETCH(double, step);
        QCOMPARE(NiceTicks::step(lo, hi), step);
    }

    void anAxisEndsOnTicks()
    {
        const NiceTicks::Axis a = NiceTicks::axis(0, 11.8, 5);
        QCOMPARE(a.lo, 0.0);
        QCOMPARE(a.step, 5.0);
        QCOMPARE(a.hi, 15.0);
        QCOMPARE(a.tickCount(), 4);
        QCOMPARE(a.decimals, 0);
        QCOMPARE(NiceTicks::decimals(2.5), 1);
        QCOMPARE(NiceTicks::decimals(0.25), 2);
        QCOMPARE(NiceTicks::decimals(0.1), 1);
        const NiceTicks::Axis flat = NiceTicks::axis(10, 10);
        QVERIFY(flat.lo < 10 && flat.hi > 10 && isRound(flat.step));
    }

    void everyRangeGetsRoundTicks()
    {
        QRandomGenerator random(33);
        for (int i = 0; i < 2000; ++i) {
            const double scale = std::pow(10.0, random.bounded(12) - 6);
            const double lo = (random.generateDouble() - 0.3) * 100 * scale;
            const double hi = lo + random.generateDouble() * 100 * scale + 1e-9;
            for (int wanted : {4, 5, 6, 8}) {
                const NiceTicks::Axis a = NiceTicks::axis(lo, hi, wanted);
                const QString what = QString::number(lo) + u".." + QString::number(hi);
                QVERIFY2(isRound(a.step), qPrintable(what));
                QVERIFY2(a.lo <= lo && a.hi >= hi, qPrintable(what));
                QVERIFY2(a.tickCount() >= 2 && a.tickCount() <= std::max(wanted, 3), qPrintable(what));
                for (double end : {a.lo, a.hi})
                    QVERIFY2(std::abs(end / a.step - std::round(end / a.step)) < 1e-6, qPrintable(what));
                // The label shows the tick exactly with the decimals given.
                const double t = a.lo + a.step;
                QVERIFY2(std::abs(QString::number(t, 'f', a.decimals).toDouble() - t) < a.step * 1e-6,
                         qPrintable(what));
                const double s = NiceTicks::step(lo, hi, wanted);
                for (double tick : NiceTicks::ticks(lo, hi, wanted))
                    QVERIFY2(tick >= lo - s * 1e-6 && tick <= hi + s * 1e-6
                                 && std::abs(tick / s - std::round(tick / s)) < 1e-6,
                             qPrintable(what));
            }
        }
    }
};

QTEST_MAIN(TestNiceTicks)
#include "tst_niceticks.moc"
