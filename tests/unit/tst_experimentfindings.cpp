// SPDX-License-Identifier: MIT
// ExperimentFindings: the sentences a factor's finding is made of, from the figures alone.
#include "experiment/experimentfindings.h"
#include "latency/latencyseries.h"

#include <QTest>

using namespace Qt::StringLiterals;

class TestExperimentFindings : public QObject
{
    Q_OBJECT
private slots:
    void shiftTextGivesTheIntervalInMs()
    {
        QCOMPARE(ExperimentFindings::shiftText({3.2, -1.0, 7.5}), u"3.2 ms [-1.0, 7.5] ms, 95 %"_s);
    }

    void aShiftWithZeroInItsIntervalIsNoSignificantDifference()
    {
        const QString line = ExperimentFindings::differenceFinding(u"qos"_s, u"0"_s, 10.0, u"1"_s, 12.0,
                                                                   ShiftEstimate {1.5, -0.5, 3.5});
        QCOMPARE(line,
                 u"qos: no significant difference between 0 and 1: the totals shift by "
                 "1.5 ms [-0.50, 3.5] ms, 95 % (the means: 10.0 and 12.0 ms)"_s);
    }

    void aSignificantShiftGivesBothMeansAndTheDifference()
    {
        const QString line = ExperimentFindings::differenceFinding(u"payload"_s, u"small"_s, 20.0, u"large"_s,
                                                                   25.0, ShiftEstimate {5.0, 4.0, 6.0});
        QCOMPARE(line,
                 u"payload: the total mean is lowest at small (20.0 ms) and highest at large (25.0 ms), "
                 "5.0 ms more (25 %); the totals shift by 5.0 ms [4.0, 6.0] ms, 95 %"_s);
    }

    void tooFewSamplesSayThereIsNoInterval()
    {
        const QString line
            = ExperimentFindings::differenceFinding(u"qos"_s, u"0"_s, 0.0, u"2"_s, 1.5, std::nullopt);
        QCOMPARE(line,
                 u"qos: the total mean is lowest at 0 (0.00 ms) and highest at 2 (1.5 ms), 1.5 ms more "
                 "(– %) (too few samples for an interval)"_s);
    }

    void theShiftIsTakenOverEachSeriesWindow()
    {
        LatencySeries low;
        LatencySeries high;
        low.setWindow(8);
        high.setWindow(8);
        for (int i = 0; i < 8; ++i)
            high.append(1'000'000'000); // left out of the window below
        for (int i = 0; i < 8; ++i) {
            low.append(10'000'000 + i * 100'000);
            high.append(12'000'000 + i * 100'000);
        }
        const std::optional<ShiftEstimate> shift = ExperimentFindings::shiftOf(low, high);
        QVERIFY(shift);
        QCOMPARE(shift->shiftMs, 2.0);
        QVERIFY(shift->significant());
        QVERIFY(!ExperimentFindings::shiftOf(LatencySeries(), high));
    }
};

QTEST_GUILESS_MAIN(TestExperimentFindings)
#include "tst_experimentfindings.moc"
