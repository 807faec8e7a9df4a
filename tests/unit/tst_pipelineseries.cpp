// SPDX-License-Identifier: MIT
// PipelineSeries: the series a pipeline gives and what one sample adds to each (the engine's
// statistics are pinned in tst_latencystats).
#include "latency/pipeline.h"
#include "latency/pipelineseries.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
Pipeline crossingTwice(bool oneClock)
{
    Pipeline p({u"/v/a"_s, u"/c/b"_s, u"/c/c"_s, u"/v/d"_s}, 0);
    p.setHost(u"/v/a"_s, u"vehicle"_s);
    p.setHost(u"/c/b"_s, u"cloud"_s);
    p.setHost(u"/c/c"_s, u"cloud"_s);
    p.setHost(u"/v/d"_s, u"vehicle"_s);
    p.setOneClock(oneClock);
    return p;
}

ClockEstimate clock(const QString& host, double offsetMs, double uncertaintyMs)
{
    ClockEstimate e;
    e.host = host;
    e.offsetNs = qint64(offsetMs * 1e6);
    e.uncertaintyNs = qint64(uncertaintyMs * 1e6);
    e.probes = 8;
    return e;
}
} // namespace

class TestPipelineSeries : public QObject
{
    Q_OBJECT
private slots:
    void aPipelineWithoutHostsHasItsStagesAndTheTotal()
    {
        PipelineSeries set;
        set.rebuild(Pipeline({u"/a"_s, u"/b"_s, u"/c"_s}, 0), 0);
        QCOMPARE(set.count(), 3);
        QCOMPARE(set.info(0).id, u"stage:0"_s);
        QCOMPARE(set.info(set.totalSeries()).label, u"total"_s);
        QCOMPARE(set.roundTripSeries(), -1);
        QCOMPARE(set.clockOffsetSeries(), -1);
        QCOMPARE(set.add({0, 3'000'000, 10'000'000}), qint64(10'000'000));
        QCOMPARE(set.series(1).stats().mean, 7.0);
        QCOMPARE(set.series(set.totalSeries()).stats().mean, 10.0);
        QVERIFY(!set.clockOffsetBoundsMs());
    }

    void twoClocksGiveTheRoundTripAndTheOffsetWithItsBounds()
    {
        PipelineSeries set;
        set.rebuild(crossingTwice(false), 0);
        QVERIFY(set.roundTripSeries() >= 0 && set.oneWaySeries() >= 0 && set.clockOffsetSeries() >= 0);
        QCOMPARE(set.thereSeries(), -1);
        // out 12 ms, the cloud 5 ms, back 8 ms: the round trip leaves out the cloud's stage
        set.add({0, 12'000'000, 17'000'000, 25'000'000});
        QCOMPARE(set.series(set.roundTripSeries()).stats().mean, 20.0);
        QCOMPARE(set.series(set.oneWaySeries()).stats().mean, 10.0);
        QCOMPARE(set.series(set.clockOffsetSeries()).stats().mean, 2.0);
        QCOMPARE(set.clockOffsetBoundsMs(), std::make_optional(std::make_pair(-8.0, 12.0)));
    }

    void oneClockGivesEachLegInstead()
    {
        PipelineSeries set;
        set.rebuild(crossingTwice(true), 0);
        QCOMPARE(set.clockOffsetSeries(), -1);
        QCOMPARE(set.info(set.thereSeries()).label, u"communication, there (vehicle → cloud)"_s);
        set.add({0, 12'000'000, 17'000'000, 25'000'000});
        QCOMPARE(set.series(set.thereSeries()).stats().mean, 12.0);
        QCOMPARE(set.series(set.backSeries()).stats().mean, 8.0);
    }

    void measuredClocksCorrectEachCrossingWithItsUncertainty()
    {
        PipelineSeries set;
        set.rebuild(crossingTwice(false), 0);
        // The cloud's clock 35 ms ahead; out 20 ms (10 ms more than back), the cloud 5 ms, back 10 ms.
        const auto sample = [&set](qint64 at) {
            set.add({at, at + 55'000'000, at + 60'000'000, at + 35'000'000});
        };
        sample(0);
        QCOMPARE(set.correctedSeries(0), -1); // nothing measured, nothing made
        QCOMPARE(set.asymmetrySeries(), -1);
        const quint64 layout = set.layoutRevision();
        set.setClock(clock(u"cloud"_s, 35, 0.3));
        QCOMPARE(set.correctedSeries(0), -1); // the vehicle's clock is not known yet
        QCOMPARE(set.layoutRevision(), layout);
        set.setClock(clock(u"vehicle"_s, 0, 0.2));
        QVERIFY(set.layoutRevision() != layout);
        QCOMPARE(set.correctedSeries(1), -1); // within the cloud: no crossing
        const int there = set.correctedSeries(0);
        const int back = set.correctedSeries(2);
        QVERIFY(there >= 0 && back >= 0 && set.asymmetrySeries() >= 0);
        QCOMPARE(set.info(there).id, u"corrected:0"_s);
        QCOMPARE(set.info(there).kind, SeriesKind::Corrected);
        QCOMPARE(set.indexOf(u"corrected:2"_s), back);
        QCOMPARE(set.series(there).count(), qint64(0)); // corrected from the next sample on
        sample(100'000'000);
        sample(200'000'000);
        QCOMPARE(set.series(there).stats().median, 20.0);
        QCOMPARE(set.series(back).stats().median, 10.0);
        QCOMPARE(set.uncertaintyMs(there), std::make_optional(0.5));
        // The paper's derived one way puts 15 ms on each; the asymmetry is what it misattributes.
        QCOMPARE(set.series(set.oneWaySeries()).stats().median, 15.0);
        QCOMPARE(set.series(set.asymmetrySeries()).stats().median, 5.0);
        QCOMPARE(set.uncertaintyMs(set.asymmetrySeries()), std::make_optional(0.5));
        QVERIFY(!set.uncertaintyMs(set.totalSeries()));

        // A later, worse estimate: the figure carries the largest uncertainty of its window.
        set.setClock(clock(u"cloud"_s, 36, 1.3));
        sample(300'000'000);
        QCOMPARE(set.series(there).stats().min, 19.0);
        QCOMPARE(set.uncertaintyMs(there), std::make_optional(1.5));

        // A new pipeline keeps the clocks: its crossings are corrected at once; one clock needs none.
        set.rebuild(crossingTwice(false), 0);
        QVERIFY(set.correctedSeries(0) >= 0);
        set.rebuild(crossingTwice(true), 0);
        QCOMPARE(set.correctedSeries(0), -1);
        QCOMPARE(set.asymmetrySeries(), -1);
    }

    void correctedCrossingsAreNamedByTheirHostsUnlessTwoShareThem()
    {
        Pipeline p({u"/v/a"_s, u"/c/b"_s, u"/v/c"_s, u"/c/d"_s}, 0);
        for (const QString& t : p.topics())
            p.setHost(t, t.startsWith(u"/v/"_s) ? u"vehicle"_s : u"cloud"_s);
        PipelineSeries set;
        set.rebuild(p, 0);
        set.setClock(clock(u"vehicle"_s, 0, 0.1));
        set.setClock(clock(u"cloud"_s, 5, 0.1));
        QCOMPARE(set.info(set.correctedSeries(1)).label, u"communication, cloud → vehicle, clocks measured"_s);
        QCOMPARE(set.info(set.correctedSeries(0)).label, set.info(0).label + u", clocks measured"_s);
        QCOMPARE(set.info(set.correctedSeries(2)).label, set.info(2).label + u", clocks measured"_s);
    }

    void seriesIdsOfCorrectedCrossingsRoundTrip()
    {
        QCOMPARE(SeriesId::ofCorrected(3).toString(), u"corrected:3"_s);
        QCOMPARE(SeriesId::parse(u"corrected:3"_s), std::make_optional(SeriesId::ofCorrected(3)));
        QCOMPARE(SeriesId::parse(u"asymmetry"_s),
                 std::make_optional(SeriesId::ofKind(SeriesKind::Asymmetry)));
        QVERIFY(!SeriesId::parse(u"corrected:-1"_s));
        QVERIFY(!SeriesId::parse(u"corrected:x"_s));
        QCOMPARE(SeriesId::parse(u"stage:2"_s), std::make_optional(SeriesId::ofStage(2)));
    }

    void externalsSurviveANewPipelineAndChangeTheLayout()
    {
        PipelineSeries set;
        set.rebuild(Pipeline({u"/a"_s, u"/b"_s}, 0), 0);
        const quint64 layout = set.layoutRevision();
        const int ext = set.external(u"bridge"_s, 0);
        QCOMPARE(set.external(u"bridge"_s, 0), ext); // made once
        QVERIFY(set.layoutRevision() != layout);
        set.series(ext).append(4'000'000);
        set.rebuild(Pipeline({u"/a"_s, u"/b"_s, u"/c"_s}, 0), 0);
        const int moved = set.indexOf(u"ext:bridge"_s);
        QCOMPARE(moved, set.count() - 1);
        QCOMPARE(set.series(moved).stats().mean, 4.0);
        set.clearValues();
        QCOMPARE(set.series(moved).count(), qint64(0));
        QCOMPARE(set.indexOf(u"ext:bridge"_s), moved); // the layout stays
    }
};

QTEST_GUILESS_MAIN(TestPipelineSeries)
#include "tst_pipelineseries.moc"
