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
