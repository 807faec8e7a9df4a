// SPDX-License-Identifier: MIT
// Ros2TopicReaders: what the DDS child keeps of the topics it reads, without a domain (the
// samples are handed in as Cyclone's listener would).
#include "base/wallclock.h"
#include "dds/ros2topicreaders.h"

#include <cmath>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
void deliver(Ros2TopicReaders& readers, const QString& topic, const QByteArray& cdr)
{
    readers.onSample(topic, reinterpret_cast<const unsigned char*>(cdr.constData()), std::size_t(cdr.size()));
}

const QByteArray kCdr = QByteArray("\0\1\0\0", 4) + QByteArray("payload");
} // namespace

class TestRos2TopicReaders : public QObject
{
    Q_OBJECT
private slots:
    void aMonitoredTopicIsCountedAndArrives()
    {
        Ros2TopicReaders readers;
        readers.keepArrivals(10);
        readers.add(u"/chatter"_s, u"std_msgs/msg/String"_s, true);
        deliver(readers, u"/chatter"_s, kCdr);
        deliver(readers, u"/other"_s, kCdr); // not read: nothing
        QVERIFY(readers.isMonitored(u"/chatter"_s));
        const QHash<QString, Ros2MonitorStats> stats = readers.snapshot(0);
        QCOMPARE(stats.keys(), QList<QString> {u"/chatter"_s});
        QCOMPARE(stats[u"/chatter"_s].messages, quint64(1));
        QCOMPARE(stats[u"/chatter"_s].bytes, quint64(kCdr.size()));
        QCOMPARE(stats[u"/chatter"_s].type, u"std_msgs/msg/String"_s);
        QCOMPARE(stats[u"/chatter"_s].lastMessage, kCdr);
        const std::vector<SourceHead> arrivals = readers.takeArrivals();
        QCOMPARE(arrivals.size(), std::size_t(1));
        QCOMPARE(arrivals[0].topic, u"/chatter"_s);
        QCOMPARE(arrivals[0].head, QByteArray("payload")); // after the encapsulation header
        QVERIFY(readers.takeMessages(u"/chatter"_s).empty()); // not watched
    }

    // Issue 45: a ROS 2 topic's age, Header or not, from its samples' DDS source timestamps: the
    // median of the last 64, none without them, and a sort only after a sample came.
    void theAgeIsTheSourceTimestampsMedian()
    {
        Ros2TopicReaders readers;
        readers.add(u"/count"_s, u"std_msgs/msg/Int32"_s, true);
        deliver(readers, u"/count"_s, kCdr);
        QVERIFY(std::isnan(readers.snapshot(0)[u"/count"_s].ageMs)); // no source timestamp
        const auto at = [&](qint64 ageNs) {
            readers.onSample(u"/count"_s, reinterpret_cast<const unsigned char*>(kCdr.constData()),
                             std::size_t(kCdr.size()), wallClockNs() - ageNs);
        };
        for (int i = 0; i < 100; ++i) // 100 samples 2 ms old, then 40 that were 500 ms old: 64 kept
            at(2'000'000);
        for (int i = 0; i < 40; ++i)
            at(500'000'000);
        const double ms = readers.snapshot(0)[u"/count"_s].ageMs;
        QVERIFY2(ms >= 500 && ms < 600, qPrintable(QString::number(ms))); // 40 of the 64 are the old ones
        for (int i = 0; i < 64; ++i)
            at(2'000'000);
        const double fresh = readers.snapshot(0)[u"/count"_s].ageMs;
        QVERIFY2(fresh >= 2 && fresh < 100, qPrintable(QString::number(fresh)));
        QCOMPARE(readers.snapshot(0)[u"/count"_s].ageMs, fresh);
    }

    void aTopicOnlyWatchedIsQueuedNotShownNorAnArrival()
    {
        Ros2TopicReaders readers;
        readers.keepArrivals(10);
        readers.add(u"/image"_s, u"sensor_msgs/msg/Image"_s, false);
        QVERIFY(readers.watch(u"/image"_s, 2, 1 << 20));
        for (int i = 0; i < 3; ++i)
            deliver(readers, u"/image"_s, kCdr);
        QVERIFY(!readers.isMonitored(u"/image"_s));
        QVERIFY(readers.snapshot(0).isEmpty());
        QVERIFY(readers.takeArrivals().empty());
        QCOMPARE(readers.takeMessages(u"/image"_s).size(), std::size_t(2)); // the newest two
        QCOMPARE(readers.droppedMessages(u"/image"_s), quint64(1));
    }

    void aTopicIsReadUntilItsLastUseEnds()
    {
        Ros2TopicReaders readers;
        QVERIFY(!readers.markMonitored(u"/t"_s));
        QVERIFY(!readers.watch(u"/t"_s, 10, 1000));
        readers.add(u"/t"_s, u"std_msgs/msg/Empty"_s, false);
        QVERIFY(readers.watch(u"/t"_s, 10, 1000));
        QVERIFY(readers.markMonitored(u"/t"_s));
        readers.release(u"/t"_s, false); // the watch ends: still monitored
        QVERIFY(readers.isSubscribed(u"/t"_s));
        QVERIFY(readers.isMonitored(u"/t"_s));
        readers.release(u"/t"_s, true);
        QVERIFY(!readers.isSubscribed(u"/t"_s));
        deliver(readers, u"/t"_s, kCdr); // a callback after the end finds nothing
        QVERIFY(readers.snapshot(0).isEmpty());
    }

    void arrivalsAreBoundedAndClearedWithTheRest()
    {
        Ros2TopicReaders readers;
        readers.add(u"/t"_s, u"std_msgs/msg/Empty"_s, true);
        deliver(readers, u"/t"_s, kCdr);
        QVERIFY(readers.takeArrivals().empty()); // not asked for
        readers.keepArrivals(2);
        for (int i = 0; i < 3; ++i)
            deliver(readers, u"/t"_s, kCdr);
        QCOMPARE(readers.takeArrivals().size(), std::size_t(2));
        QCOMPARE(readers.droppedArrivals(), quint64(1));
        readers.clear();
        QVERIFY(!readers.isSubscribed(u"/t"_s));
        deliver(readers, u"/t"_s, kCdr);
        QVERIFY(readers.takeArrivals().empty());
        QCOMPARE(readers.droppedArrivals(), quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestRos2TopicReaders)
#include "tst_ros2topicreaders.moc"
