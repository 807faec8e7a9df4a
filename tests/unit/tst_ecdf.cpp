// SPDX-License-Identifier: MIT
// ECDFs: exact steps, and the reduction for drawing that moves no step by more than a column.
#include "latency/ecdf.h"
#include "latency/latencyengine.h"
#include "latency/latencyseries.h"
#include "latency/latencyseriesset.h"
#include "latency/seriesid.h"

#include <cmath>
#include <QTest>
#include <random>

using namespace Qt::StringLiterals;

class TestEcdf : public QObject
{
    Q_OBJECT
private:
    /// Where the reduced curve first reaches `level` (its x), or NaN.
    static double firstReach(const QList<QPointF>& curve, double level)
    {
        for (const QPointF& p : curve)
            if (p.y() >= level - 1e-12)
                return p.x();
        return std::nan("");
    }

private slots:
    // Issue 33, point 2: the range a figure shows ends at a high quantile, not at a lone outlier;
    // a spread without outliers and a handful of values are shown whole.
    void theShownRangeLeavesOutliersOnly()
    {
        LatencySeries few;
        for (qint64 v : {10, 12, 11, 300})
            few.append(v * 1'000'000);
        QCOMPARE(Ecdf::shownRange(few), std::make_pair(10.0, 300.0));
        QCOMPARE(Ecdf::countAbove(few, 100), 1);

        std::mt19937 random(33);
        std::normal_distribution<double> normal(20.0, 3.0);
        LatencySeries spread;
        spread.setWindow(0);
        for (int i = 0; i < 600; ++i)
            spread.append(qint64(normal(random) * 1e6));
        const double max = spread.toMs(spread.sorted().max());
        QCOMPARE(Ecdf::shownRange(spread).second, max); // the normal tail is no outlier
        spread.append(328'000'000);
        const auto [lo, hi] = Ecdf::shownRange(spread);
        QVERIFY(lo < 15 && hi >= max - 1 && hi < 40);
        QCOMPARE(Ecdf::countAbove(spread, hi), 1); // the outlier alone
        QCOMPARE(Ecdf::countAbove(spread, 400), 0);
    }

    void stepsAreExact()
    {
        LatencySeries s;
        for (qint64 v : {3, 1, 3, 2})
            s.append(v * 1'000'000);
        const QList<QPointF> steps = Ecdf::steps(s);
        QCOMPARE(steps, (QList<QPointF> {{1.0, 0.25}, {2.0, 0.5}, {3.0, 1.0}}));
    }

    void reductionMovesNoStepByMoreThanAColumn_data()
    {
        QTest::addColumn<int>("values");
        QTest::addColumn<bool>("logScale");
        QTest::newRow("100k, linear") << 100'000 << false;
        QTest::newRow("100k, log") << 100'000 << true;
    }

    void reductionMovesNoStepByMoreThanAColumn()
    {
        QFETCH(int, values);
        QFETCH(bool, logScale);
        std::mt19937_64 rng(17);
        std::lognormal_distribution<double> dist(std::log(80.0), 0.08); // ms, like the paper's totals
        LatencySeries s;
        s.setWindow(0);
        for (int i = 0; i < values; ++i)
            s.append(qint64(dist(rng) * 1e6));
        const double lo = 50;
        const double hi = 130;
        const int columns = 800;
        const QList<QPointF> reduced = Ecdf::reduced(s, lo, hi, columns, logScale);
        QVERIFY(reduced.size() <= 2 * columns + 2);
        for (qsizetype i = 1; i < reduced.size(); ++i) {
            QVERIFY(reduced[i].x() >= reduced[i - 1].x());
            QVERIFY(reduced[i].y() >= reduced[i - 1].y());
        }
        QCOMPARE(reduced.last().y(), 1.0);
        const auto px = [&](double x) {
            return logScale ? (std::log(x) - std::log(lo)) / (std::log(hi) - std::log(lo)) * columns
                            : (x - lo) / (hi - lo) * columns;
        };
        for (const QPointF& step : Ecdf::steps(s)) {
            if (step.x() < lo || step.x() > hi)
                continue;
            const double drawn = firstReach(reduced, step.y());
            QVERIFY(!std::isnan(drawn));
            QVERIFY2(std::abs(px(drawn) - px(step.x())) <= 1.0 + 1e-9,
                     qPrintable(QStringLiteral("step at %1 drawn at %2").arg(step.x()).arg(drawn)));
        }
    }

    void valuesInColumnsOfTheirOwnAreDrawnExactly()
    {
        // Column width 0.1 ms; values 0.25 ms apart: one per column, so every step is exact.
        LatencySeries s;
        s.setWindow(0);
        for (int k = 0; k < 300; ++k)
            s.append(50'000'000 + qint64(k) * 250'000 + (k % 7) * 1000);
        const QList<QPointF> reduced = Ecdf::reduced(s, 50, 130, 800);
        const QList<QPointF> steps = Ecdf::steps(s);
        QCOMPARE(steps.size(), 300);
        for (const QPointF& step : steps)
            QCOMPARE(firstReach(reduced, step.y()), step.x());
    }

    void valuesOutsideTheAxisSetTheLevels()
    {
        LatencySeries s;
        for (qint64 v : {1, 5, 10, 20})
            s.append(v * 1'000'000);
        const QList<QPointF> r = Ecdf::reduced(s, 4, 12, 100);
        QCOMPARE(r.first(), QPointF(4, 0.25)); // 1 ms lies left of the axis
        QCOMPARE(r.last(), QPointF(12, 0.75)); // 20 ms lies right of it
        QVERIFY(Ecdf::reduced(s, 0, 12, 100, true).isEmpty()); // a log axis cannot start at 0
    }

    // The reduction's cost depends on the columns, not on the values (regression guard for a
    // window of a million samples on a 30 Hz redraw).
    void reductionOfAMillionValuesIsBoundedByColumns()
    {
        LatencySeries s;
        s.setWindow(0);
        for (int i = 0; i < 1'000'000; ++i)
            s.append(qint64(i) * 997 % 100'000'000);
        const QList<QPointF> r = Ecdf::reduced(s, 0, 100, 1000);
        QVERIFY(r.size() <= 2002);
        QCOMPARE(r.last().y(), 1.0);
    }

    // Series ids are written and read in one place; every id the engine makes reads back as itself.
    void seriesIdsRoundTrip()
    {
        // Out to the cloud and back: stages, total, round trip, one way and the clock offset.
        Pipeline p({u"/v/out"_s, u"/c/in"_s, u"/c/out"_s, u"/v/in"_s});
        p.setHost(u"/v/out"_s, u"vehicle"_s);
        p.setHost(u"/c/in"_s, u"cloud"_s);
        p.setHost(u"/c/out"_s, u"cloud"_s);
        p.setHost(u"/v/in"_s, u"vehicle"_s);
        LatencyEngine engine(p);
        engine.ingest(LatencyValue {u"mqtt/ext"_s, 1000, 0});
        QStringList ids;
        for (int i = 0; i < engine.seriesCount(); ++i) {
            const QString id = engine.info(i).id;
            const std::optional<SeriesId> parsed = SeriesId::parse(id);
            QVERIFY2(parsed, qPrintable(id));
            QCOMPARE(parsed->toString(), id);
            QCOMPARE(parsed->kind, engine.info(i).kind);
            ids << id;
        }
        for (const QString& id : {u"stage:2"_s, u"total"_s, u"round_trip"_s, u"one_way"_s, u"clock_offset"_s})
            QVERIFY2(ids.contains(id), qPrintable(ids.join(u' ')));
        QVERIFY(ids.contains(u"ext:mqtt/ext"_s));
        QCOMPARE(SeriesId::parse(u"stage:1"_s)->stage, 1);
        QVERIFY(!SeriesId::parse(u"stage:x"_s));
        QVERIFY(!SeriesId::parse(u"stage:-1"_s));
        QVERIFY(!SeriesId::parse(u"totals"_s));
    }

    // A probe's series set is an ECDF source like the engine: ids, labels, whole-run series.
    void seriesSetIsAnEcdfSource()
    {
        LatencySeriesSet set;
        const EcdfSource& source = set;
        QCOMPARE(source.ecdfIndex(LatencySeriesSet::idOf(u"step 1"_s)), -1);
        for (int i = 1; i <= 1000; ++i)
            set.add(u"step 1"_s, i * 1'000'000);
        set.add(u"step 2"_s, 5'000'000);
        const int index = source.ecdfIndex(u"ext:step 1"_s);
        QVERIFY(index >= 0);
        QCOMPARE(source.ecdfLabel(index), u"step 1"_s);
        QCOMPARE(source.ecdfSeries(index).count(), 1000); // the whole run, not a window
        QCOMPARE(source.ecdfSeries(index).quantileMs(0.5), set.find(u"step 1"_s)->quantileMs(0.5));
        QCOMPARE(source.ecdfLayoutRevision(), quint64(2));
        QCOMPARE(set.revision(), quint64(1001));
    }
};

QTEST_GUILESS_MAIN(TestEcdf)
#include "tst_ecdf.moc"
