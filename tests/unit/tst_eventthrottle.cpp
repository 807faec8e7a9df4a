// SPDX-License-Identifier: MIT
// The event storm bound (issue 44): a burst, then a rate; what it holds back is counted by kind and
// reason and said once a second, and nothing seen goes uncounted.
#include "watch/eventthrottle.h"

#include <QJsonArray>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kMs = 1'000'000;
constexpr qint64 kStart = 1'700'000'000'000'000'000LL;

WatchEvent watchEvent(const QString& reason, bool ended)
{
    WatchEvent e;
    e.subject = u"/fleet/t1 -> fleet/t1"_s;
    e.level = LinkLevel::Alert;
    e.reasons = {reason};
    e.startNs = kStart;
    e.endNs = ended ? kStart + 1 : 0;
    return e;
}
} // namespace

class TestEventThrottle : public QObject
{
    Q_OBJECT
private slots:
    void aStormIsBoundedAndCounted()
    {
        EventThrottle throttle(1000, 100);
        // 10,000 links stall within one second, then recover within the next.
        quint64 admitted = 0;
        quint64 said = 0;
        std::map<QString, double> reasons;
        double started = 0;
        double ended = 0;
        qint64 now = kStart;
        for (int second = 0; second < 2; ++second) {
            for (int i = 0; i < 10000; ++i) {
                now += kMs / 10;
                admitted
                    += throttle.admit(watchEvent(i % 10 ? u"stall"_s : u"loss"_s, second == 1), now) ? 1 : 0;
                if (const auto line = throttle.heldBackLine(now)) {
                    QCOMPARE(line->value(u"event"_s).toString(), u"held_back"_s);
                    started += line->value(u"started"_s).toDouble();
                    ended += line->value(u"ended"_s).toDouble();
                    for (const QString& r : line->value(u"reasons"_s).toObject().keys())
                        reasons[r] += line->value(u"reasons"_s).toObject().value(r).toDouble();
                    ++said;
                }
            }
        }
        if (const auto last = throttle.heldBackLine(now, EventThrottle::Line::Last)) {
            started += last->value(u"started"_s).toDouble();
            ended += last->value(u"ended"_s).toDouble();
            for (const QString& r : last->value(u"reasons"_s).toObject().keys())
                reasons[r] += last->value(u"reasons"_s).toObject().value(r).toDouble();
            ++said;
        }
        // The burst and two seconds' rate got their lines, no more.
        QVERIFY2(admitted >= 1000 && admitted <= 1000 + 2 * 100 + 1, qPrintable(QString::number(admitted)));
        // Everything else was counted, by kind and by reason, and said in a few lines.
        QCOMPARE(throttle.heldBack(), 20000 - admitted);
        QCOMPARE(quint64(started + ended), 20000 - admitted);
        // The burst went to the first second's starts; the second's ends had the rate alone.
        QVERIFY2(ended >= 10000 - 101 && ended < 10000, qPrintable(QString::number(ended)));
        QCOMPARE(quint64(reasons[u"stall"_s] + reasons[u"loss"_s]), 20000 - admitted);
        QVERIFY2(said >= 2 && said <= 3, qPrintable(QString::number(said)));
    }

    void aQuietWatchSaysNothingAndRecovers()
    {
        EventThrottle throttle(10, 5);
        qint64 now = kStart;
        QVERIFY(!throttle.heldBackLine(now, EventThrottle::Line::Last));
        for (int i = 0; i < 10; ++i)
            QVERIFY(throttle.admit(watchEvent(u"stall"_s, false), now));
        QVERIFY(!throttle.admit(watchEvent(u"stall"_s, false), now));
        QVERIFY(throttle.heldBackLine(now + 1000 * kMs));
        // Two seconds later the bucket holds 10 again (5 a second), not more.
        now += 2000 * kMs;
        for (int i = 0; i < 10; ++i)
            QVERIFY(throttle.admit(watchEvent(u"stall"_s, true), now));
        QVERIFY(!throttle.admit(watchEvent(u"stall"_s, true), now));
        QCOMPARE(throttle.heldBack(), quint64(2));
    }
};

QTEST_APPLESS_MAIN(TestEventThrottle)
#include "tst_eventthrottle.moc"
