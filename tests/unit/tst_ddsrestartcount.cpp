// SPDX-License-Identifier: MIT
// How DdsChildSupervisor counts the ends of its children, without a child: the backoff, the
// restarts caused by peers, and the restart loops it breaks (issue 41; split out in issue 42).
#include "ros2/ddschildsupervisor.h"

#include <QTest>

using namespace Qt::StringLiterals;

class TestDdsRestartCount : public QObject
{
    Q_OBJECT
private slots:
    void backoffDoublesUpToThirtySeconds();
    void aSteadyChildStartsTheBackoffAnew();
    void threeUnexplainedRestartsBreakALoopOnce();
    void aQuarantineExplainsARestart();
    void aNewStartCountsAnewButKeepsTheLoopsBroken();
};

void TestDdsRestartCount::backoffDoublesUpToThirtySeconds()
{
    QCOMPARE(DdsRestartCount::backoffMs(1), 250);
    QCOMPARE(DdsRestartCount::backoffMs(2), 500);
    QCOMPARE(DdsRestartCount::backoffMs(3), 1000);
    QCOMPARE(DdsRestartCount::backoffMs(8), 30000);
    QCOMPARE(DdsRestartCount::backoffMs(1000), 30000);
}

void TestDdsRestartCount::aSteadyChildStartsTheBackoffAnew()
{
    DdsRestartCount c;
    QCOMPARE(c.add(u"crashed (signal 11)"_s, 10, true, true), QString());
    QCOMPARE(c.nextBackoffMs(), 250);
    c.add(u"crashed (signal 11)"_s, 10, true, false);
    QCOMPARE(c.nextBackoffMs(), 500);
    c.add(u"ended with exit code 1"_s, DdsRestartCount::kStableMs + 1, true, false);
    QCOMPARE(c.nextBackoffMs(), 250);
    QCOMPARE(c.restarts(), quint64(3));
    QCOMPARE(c.peerRestarts(), quint64(1));
    QCOMPARE(c.lastReason(), u"ended with exit code 1"_s);
}

void TestDdsRestartCount::threeUnexplainedRestartsBreakALoopOnce()
{
    DdsRestartCount c;
    QVERIFY(c.add(u"crashed (signal 6)"_s, 10, false, true).isEmpty());
    QVERIFY(c.add(u"crashed (signal 6)"_s, 10, false, true).isEmpty());
    QCOMPARE(c.nextBackoffMs(), 500);
    const QString loop = c.add(u"crashed (signal 6)"_s, 10, false, true);
    QCOMPARE(
        loop,
        u"a restart loop: 3 restarts in a row, none explained by a request; the DDS process is started again "
        "with the graph limited (%1 endpoints a participant, %2 in all)"_s
            .arg(Ros2Options::kLimitedEndpointsPerParticipant)
            .arg(Ros2Options::kLimitedEndpoints));
    QVERIFY(c.limitedGraph());
    QCOMPARE(c.loopsBroken(), 1);
    QCOMPARE(c.nextBackoffMs(), 250); // the limited child starts at once
    for (int i = 0; i < 5; ++i)
        QVERIFY(c.add(u"crashed (signal 6)"_s, 10, false, true).isEmpty()); // limited already
    QCOMPARE(c.loopsBroken(), 1);
    QCOMPARE(c.restarts(), quint64(8));
}

void TestDdsRestartCount::aQuarantineExplainsARestart()
{
    DdsRestartCount c;
    c.add(u"crashed (signal 11)"_s, 10, false, false);
    c.add(u"crashed (signal 11)"_s, 10, false, false);
    c.add(u"crashed (signal 11)"_s, 10, true, true); // a request quarantined: no loop to break
    c.add(u"crashed (signal 11)"_s, 10, false, false);
    QVERIFY(c.add(u"crashed (signal 11)"_s, 10, false, false).isEmpty());
    QVERIFY(!c.limitedGraph());
    QCOMPARE(c.nextBackoffMs(), DdsRestartCount::backoffMs(5));
    QVERIFY(!c.add(u"crashed (signal 11)"_s, 10, false, false).isEmpty());
}

void TestDdsRestartCount::aNewStartCountsAnewButKeepsTheLoopsBroken()
{
    DdsRestartCount c;
    for (int i = 0; i < DdsRestartCount::kLoopRestarts; ++i)
        c.add(u"crashed (signal 6)"_s, 10, false, false);
    QCOMPARE(c.loopsBroken(), 1);
    c.newStart();
    QCOMPARE(c.restarts(), quint64(0));
    QCOMPARE(c.peerRestarts(), quint64(0));
    QVERIFY(!c.limitedGraph());
    QVERIFY(c.lastReason().isEmpty());
    QCOMPARE(c.loopsBroken(), 1);
    QCOMPARE(c.nextBackoffMs(), 250);
}

QTEST_GUILESS_MAIN(TestDdsRestartCount)
#include "tst_ddsrestartcount.moc"
