// SPDX-License-Identifier: MIT
// NewestQueue, the plotters' hand-over of whole messages (RosMonitor, Ros2Participant): it keeps
// the newest within a count and a byte bound, drops the oldest and counts every drop.
#include "base/newestqueue.h"

#include <QByteArray>
#include <QTest>

class TestNewestQueue : public QObject
{
    Q_OBJECT

    static std::vector<int> taken(NewestQueue<int>& q) { return q.take(); }

private slots:
    void keepsTheNewestWithinTheBounds_data()
    {
        QTest::addColumn<int>("maxItems");
        QTest::addColumn<int>("maxBytes");
        QTest::addColumn<int>("pushed"); // items 1..pushed of 10 bytes each
        QTest::addColumn<std::vector<int>>("kept");
        QTest::addColumn<int>("dropped");
        QTest::newRow("within both") << 5 << 1000 << 3 << std::vector<int> {1, 2, 3} << 0;
        QTest::newRow("count bound") << 3 << 1000 << 7 << std::vector<int> {5, 6, 7} << 4;
        QTest::newRow("byte bound") << 100 << 25 << 7 << std::vector<int> {6, 7} << 5;
        QTest::newRow("exactly full") << 3 << 30 << 3 << std::vector<int> {1, 2, 3} << 0;
        QTest::newRow("an item larger than the bytes") << 100 << 5 << 2 << std::vector<int> {} << 2;
        QTest::newRow("nothing allowed") << 0 << 1000 << 4 << std::vector<int> {} << 4;
    }
    void keepsTheNewestWithinTheBounds()
    {
        QFETCH(int, maxItems);
        QFETCH(int, maxBytes);
        QFETCH(int, pushed);
        QFETCH(std::vector<int>, kept);
        QFETCH(int, dropped);
        NewestQueue<int> q(std::size_t(maxItems), maxBytes);
        for (int i = 1; i <= pushed; ++i)
            q.push(i, 10);
        QCOMPARE(q.size(), kept.size());
        QCOMPARE(taken(q), kept);
        QCOMPARE(q.dropped(), quint64(dropped));
    }

    void takeEmptiesAndFreesTheBytes()
    {
        NewestQueue<QByteArray> q(10, 100);
        q.push(QByteArray(60, 'a'), 60);
        QCOMPARE(q.take().size(), 1u);
        QCOMPARE(q.size(), 0u);
        q.push(QByteArray(60, 'b'), 60); // the taken bytes no longer count
        QCOMPARE(q.take(), std::vector<QByteArray> {QByteArray(60, 'b')});
        QCOMPARE(q.dropped(), 0u);
        QVERIFY(q.take().empty());
    }

    void dropsAreCountedAcrossTakes()
    {
        NewestQueue<int> q(2, 1000);
        for (int i = 0; i < 5; ++i)
            q.push(i, 1);
        q.take();
        for (int i = 0; i < 4; ++i)
            q.push(i, 1);
        QCOMPARE(q.dropped(), 5u);
    }

    void smallerLimitsDropAtOnce()
    {
        NewestQueue<int> q(10, 1000);
        for (int i = 1; i <= 6; ++i)
            q.push(i, 10);
        q.setLimits(10, 35);
        QCOMPARE(q.dropped(), 3u);
        QCOMPARE(taken(q), (std::vector<int> {4, 5, 6}));
    }
};

QTEST_APPLESS_MAIN(TestNewestQueue)
#include "tst_newestqueue.moc"
