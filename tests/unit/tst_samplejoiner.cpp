// SPDX-License-Identifier: MIT
// The sample joiner: loss, reordering, duplicates, timeouts and bounded memory.
#include "latency/latencyengine.h"
#include "latency/samplejoiner.h"

#include <QTest>
#include <random>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSec = 1'000'000'000LL;
}

class TestSampleJoiner : public QObject
{
    Q_OBJECT
private slots:
    void completesWhenEveryTopicStamped()
    {
        SampleJoiner j(3);
        std::vector<qint64> times;
        QVERIFY(!j.add(0, 100, 1000, 0, times));
        QVERIFY(!j.add(2, 100, 3000, 0, times));
        QCOMPARE(j.pending(), 1);
        QVERIFY(j.add(1, 100, 2000, 0, times));
        QCOMPARE(times, (std::vector<qint64> {1000, 2000, 3000})); // pipeline order, not arrival order
        QCOMPARE(j.pending(), 0);
        QCOMPARE(j.counters().complete, 1u);
    }

    void reorderedAndInterleavedSamplesJoinCorrectly()
    {
        // 200 samples, their stamps shuffled across samples and topics.
        const int topics = 5;
        std::vector<std::tuple<int, qint64, qint64>> stamps;
        for (qint64 s = 0; s < 200; ++s)
            for (int t = 0; t < topics; ++t)
                stamps.emplace_back(t, s * 1000, s * 1000 + t * 10 + 1);
        std::mt19937 rng(3);
        std::shuffle(stamps.begin(), stamps.end(), rng);
        SampleJoiner j(topics);
        std::vector<qint64> times;
        int completed = 0;
        for (const auto& [t, sample, time] : stamps) {
            if (j.add(t, sample, time, 0, times)) {
                ++completed;
                for (int k = 0; k < topics; ++k)
                    QCOMPARE(times[std::size_t(k)] - times[0], qint64(k * 10));
            }
        }
        QCOMPARE(completed, 200);
        QCOMPARE(j.pending(), 0);
        QCOMPARE(j.counters().dropped(), 0u);
    }

    void lostStampDropsTheSampleAfterTheTimeout()
    {
        SampleJoiner j(3);
        j.setTimeoutNs(5 * kSec);
        std::vector<qint64> times;
        for (int topic = 0; topic < 3; ++topic) // every topic delivers: the measurement is under way
            j.add(topic, 0, 10, 0, times);
        j.add(0, 1, 10, 0, times);
        j.add(1, 1, 20, 0, times); // topic 2 never stamps sample 1
        j.add(0, 2, 10, 1 * kSec, times);
        j.expire(5 * kSec); // exactly the timeout: still waiting
        QCOMPARE(j.pending(), 2);
        j.expire(5 * kSec + 1);
        QCOMPARE(j.pending(), 1);
        QCOMPARE(j.counters().timedOut, 1u);
        j.expire(7 * kSec);
        QCOMPARE(j.counters().timedOut, 2u);
        QCOMPARE(j.pending(), 0);
        // The missing stamp arriving late does not reopen the sample.
        QVERIFY(!j.add(2, 1, 30, 8 * kSec, times));
        QCOMPARE(j.counters().late, 1u);
        QCOMPARE(j.pending(), 0);
    }

    void duplicatesAreCountedAndTheFirstStampKept()
    {
        SampleJoiner j(2);
        std::vector<qint64> times;
        j.add(0, 7, 100, 0, times);
        QVERIFY(!j.add(0, 7, 999, 0, times)); // the same topic again
        QCOMPARE(j.counters().duplicates, 1u);
        QVERIFY(j.add(1, 7, 200, 0, times));
        QCOMPARE(times, (std::vector<qint64> {100, 200}));
        QVERIFY(!j.add(1, 7, 200, 0, times)); // after completion: a duplicate, not a new sample
        QCOMPARE(j.counters().duplicates, 2u);
        QCOMPARE(j.pending(), 0);
    }

    void unknownTopicsAreCounted()
    {
        LatencyEngine engine(Pipeline({u"/a"_s, u"/b"_s}));
        engine.ingest(StampEvent {u"/elsewhere"_s, 1, 2, 3});
        engine.ingest(StampEvent {u"b"_s, 1, 5, 3}); // the MQTT spelling of /b
        engine.ingest(StampEvent {u"/a"_s, 1, 2, 3});
        QCOMPARE(engine.counters().unknownTopic, 1u);
        QCOMPARE(engine.counters().complete, 1u);
        QCOMPARE(engine.series(engine.totalSeries()).stats().mean, 3e-6);
    }

    // Regression guard: a flood of samples that never complete must not grow memory.
    void memoryStaysBoundedWhateverArrives()
    {
        SampleJoiner j(4);
        j.setMaxPending(1000);
        std::vector<qint64> times;
        for (int topic = 0; topic < 4; ++topic)
            j.add(topic, -1'000'000'000, 0, 0, times);
        std::size_t worst = 0;
        for (qint64 s = 0; s < 300'000; ++s) {
            j.add(int(s % 3), s, s, s, times); // never topic 3: nothing completes
            j.add(0, -1 - s, 0, s, times);
            if (s % 10'000 == 0)
                worst = std::max(worst, j.bookkeeping());
        }
        QCOMPARE(j.pending(), 1000);
        QCOMPARE(j.counters().evicted, 600'000u - 1000u);
        QVERIFY2(worst < 30'000, qPrintable(QString::number(worst)));
        // Completing samples behind one that stays open leaves no trail either.
        SampleJoiner k(2);
        k.add(0, -5, 0, 0, times); // open for good
        for (qint64 s = 0; s < 200'000; ++s) {
            k.add(0, s, 1, s, times);
            k.add(1, s, 2, s, times);
        }
        QCOMPARE(k.counters().complete, 200'000u);
        QVERIFY2(k.bookkeeping() < 20'000, qPrintable(QString::number(k.bookkeeping())));
    }

    // A measurement starting: the subscriptions to later topics exist only after earlier samples
    // began. Those samples miss stamps without any loss, and are not counted as dropped.
    void samplesBegunBeforeEveryTopicDeliveredAreNoDrops()
    {
        SampleJoiner j(3);
        j.setTimeoutNs(kSec);
        std::vector<qint64> times;
        j.add(0, 1, 10, 0, times); // only topic 0 is heard yet
        j.add(0, 2, 10, 100, times);
        j.add(1, 2, 20, 110, times); // topic 1 now too
        QVERIFY(!j.allTopicsSeen());
        QVERIFY(j.topicSeen(1) && !j.topicSeen(2));
        QVERIFY(j.add(0, 3, 10, 200, times) == false);
        QVERIFY(j.add(1, 3, 20, 210, times) == false);
        QVERIFY(j.add(2, 3, 30, 220, times)); // sample 3 began before topic 2 was heard, yet completes
        QVERIFY(j.allTopicsSeen());
        j.add(0, 4, 10, 300, times); // begun after: a loss from here on is a drop
        j.add(1, 4, 20, 310, times);
        j.expire(10 * kSec);
        QCOMPARE(j.counters().complete, 1u);
        QCOMPARE(j.counters().beforeAllTopics, 2u); // samples 1 and 2
        QCOMPARE(j.counters().timedOut, 1u); // sample 4
        QCOMPARE(j.counters().dropped(), 1u);
        // A reset starts listening anew: samples in flight then miss their first stamps.
        j.reset(3);
        j.add(2, 5, 30, 11 * kSec, times);
        j.add(0, 6, 10, 11 * kSec, times);
        j.add(1, 6, 20, 11 * kSec, times);
        j.add(2, 6, 30, 11 * kSec, times);
        j.expire(20 * kSec);
        QCOMPARE(j.counters().complete, 1u);
        QCOMPARE(j.counters().beforeAllTopics, 1u);
        QCOMPARE(j.counters().dropped(), 0u);
        // A topic that never delivers: every sample waits for it, none is a drop; still counted.
        SampleJoiner k(2);
        k.setTimeoutNs(kSec);
        for (qint64 s = 0; s < 10; ++s)
            k.add(0, s, 0, s, times);
        k.expire(10 * kSec);
        QCOMPARE(k.counters().beforeAllTopics, 10u);
        QCOMPARE(k.counters().dropped(), 0u);
    }

    void engineDropsFollowTheJoiner()
    {
        LatencyEngine engine(Pipeline({u"/a"_s, u"/b"_s, u"/c"_s}));
        engine.setTimeoutNs(kSec);
        for (qint64 s = 0; s < 10; ++s) {
            engine.ingest(StampEvent {u"/a"_s, s, s * 10, s});
            engine.ingest(StampEvent {u"/b"_s, s, s * 10 + 1, s});
            if (s % 2 == 0)
                engine.ingest(StampEvent {u"/c"_s, s, s * 10 + 3, s});
        }
        QCOMPARE(engine.samples(), 5);
        QCOMPARE(engine.pending(), 5);
        engine.expire(2 * kSec);
        QCOMPARE(engine.counters().timedOut, 5u);
        QCOMPARE(engine.pending(), 0);
        QCOMPARE(engine.series(engine.totalSeries()).stats().count, 5);
    }
};

QTEST_GUILESS_MAIN(TestSampleJoiner)
#include "tst_samplejoiner.moc"
