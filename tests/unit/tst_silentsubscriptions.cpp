// SPDX-License-Identifier: MIT
// Issue 44: ROS 1 subscriptions that roscpp left silent (its one requestTopic to a listed publisher
// failed) are asked about again after 10 s, then less and less often, a bounded number a pass; a topic
// with a publisher connected, or none listed, is left alone.
#include "ros/silentsubscriptions.h"

#include <QTest>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kS = 1'000'000'000;
constexpr qint64 kStart = 1'700'000'000LL * kS;
} // namespace

class TestSilentSubscriptions : public QObject
{
    Q_OBJECT
private slots:
    void aListedTopicWithNoPublisherConnectedIsAskedAgainThenBackedOff()
    {
        SilentSubscriptions s;
        s.setListed({u"/a"_s, u"/b"_s});
        QHash<QString, int> connected {{u"/a"_s, 0}, {u"/b"_s, 1}, {u"/c"_s, 0}};
        const auto ask = [&](const QString& t) { return connected.value(t); };
        const QList<QString> subscribed {u"/a"_s, u"/b"_s, u"/c"_s};
        QVERIFY(s.pass(kStart, subscribed, ask).isEmpty()); // silent since now
        QVERIFY(s.pass(kStart + 9 * kS, subscribed, ask).isEmpty());
        QCOMPARE(s.silent(), 0);
        // /b has its publisher, /c none listed: only /a, after 10 s.
        QCOMPARE(s.pass(kStart + 10 * kS, subscribed, ask), QList<QString> {u"/a"_s});
        QCOMPARE(s.silent(), 1);
        QCOMPARE(s.made(), 1u);
        QCOMPARE(s.tries(u"/a"_s), 1); // the caller asks at first, subscribes anew after some tries
        QCOMPARE(s.tries(u"/b"_s), 0);
        // Still silent: again after 20 s more, then 40 s more.
        QVERIFY(s.pass(kStart + 29 * kS, subscribed, ask).isEmpty());
        QCOMPARE(s.pass(kStart + 30 * kS, subscribed, ask), QList<QString> {u"/a"_s});
        QVERIFY(s.pass(kStart + 69 * kS, subscribed, ask).isEmpty());
        QCOMPARE(s.pass(kStart + 70 * kS, subscribed, ask), QList<QString> {u"/a"_s});
        // A publisher that refuses forever costs one subscription every 5 minutes at most.
        qint64 now = kStart + 70 * kS;
        quint64 made = s.made();
        for (int i = 0; i < 3600; ++i) {
            now += kS;
            s.pass(now, subscribed, ask);
        }
        QVERIFY2(s.made() - made <= 3600 / 300 + 2, qPrintable(QString::number(s.made() - made)));
        QVERIFY(s.made() - made >= 3600 / 300 - 1);
        // Connected: found so at its next check (at most 5 minutes on), not asked, silent no more;
        // then checked every 10 s (roscpp's count is dear: only when due), never asked.
        connected[u"/a"_s] = 1;
        made = s.made();
        for (int i = 0; i < 310; ++i) {
            now += kS;
            QVERIFY(s.pass(now, subscribed, ask).isEmpty());
        }
        QCOMPARE(s.made(), made);
        QCOMPARE(s.silent(), 0);
        // Silent again: asked within 10 s.
        connected[u"/a"_s] = 0;
        int asked = 0;
        for (int i = 0; i < 10; ++i) {
            now += kS;
            asked += int(s.pass(now, subscribed, ask).size());
        }
        QCOMPARE(asked, 1);
    }

    void roscppIsAskedOnlyForWhatIsDueAndBounded()
    {
        // roscpp's count walks every subscription: asked only when a topic is due, at most
        // kMaxChecksPerPass a pass, in turn.
        SilentSubscriptions s;
        QSet<QString> listed;
        QList<QString> candidates;
        for (int i = 0; i < 1000; ++i) {
            candidates.append(u"/q%1"_s.arg(i));
            listed.insert(candidates.last());
        }
        s.setListed(listed);
        int calls = 0;
        const auto connectedQuiet = [&calls](const QString&) {
            ++calls;
            return 1; // connected, just quiet
        };
        s.pass(kStart, candidates, connectedQuiet);
        QCOMPARE(calls, 0); // nothing due yet
        QSet<int> perPass;
        for (int p = 1; p <= 10; ++p) {
            calls = 0;
            QVERIFY(s.pass(kStart + 10 * kS + p * 2 * kS, candidates, connectedQuiet).isEmpty());
            QVERIFY2(calls <= SilentSubscriptions::kMaxChecksPerPass, qPrintable(QString::number(calls)));
            perPass.insert(calls);
        }
        QVERIFY(perPass.contains(SilentSubscriptions::kMaxChecksPerPass)); // the due ones, in turn
        QCOMPARE(s.made(), 0u);
    }

    void aPassMakesAtMostItsBoundAndTheRestComeNext()
    {
        SilentSubscriptions s;
        QSet<QString> listed;
        QList<QString> subscribed;
        for (int i = 0; i < 3 * SilentSubscriptions::kMaxPerPass; ++i) {
            subscribed.append(u"/t%1"_s.arg(i));
            listed.insert(subscribed.last());
        }
        s.setListed(listed);
        const auto none = [](const QString&) { return 0; };
        s.pass(kStart, subscribed, none);
        QSet<QString> made;
        for (int p = 0; p < 3; ++p) {
            const QList<QString> again = s.pass(kStart + 10 * kS + p * 2 * kS, subscribed, none);
            QCOMPARE(again.size(), SilentSubscriptions::kMaxPerPass);
            for (const QString& t : again)
                made.insert(t);
        }
        QCOMPARE(made.size(), 3 * SilentSubscriptions::kMaxPerPass); // each once, none twice
        QCOMPARE(s.silent(), 3 * SilentSubscriptions::kMaxPerPass);
    }

    void aTopicNoLongerListedOrSubscribedIsForgotten()
    {
        SilentSubscriptions s;
        s.setListed({u"/a"_s});
        const auto none = [](const QString&) { return 0; };
        s.pass(kStart, {u"/a"_s}, none);
        QCOMPARE(s.pass(kStart + 10 * kS, {u"/a"_s}, none).size(), 1);
        s.setListed({});
        QVERIFY(s.pass(kStart + 40 * kS, {u"/a"_s}, none).isEmpty());
        QCOMPARE(s.silent(), 0);
        s.setListed({u"/a"_s}); // listed again: a new silence, its 10 s from now
        QVERIFY(s.pass(kStart + 41 * kS, {u"/a"_s}, none).isEmpty());
        QCOMPARE(s.pass(kStart + 51 * kS, {u"/a"_s}, none).size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestSilentSubscriptions)
#include "tst_silentsubscriptions.moc"
