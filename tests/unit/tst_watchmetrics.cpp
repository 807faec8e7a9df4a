// SPDX-License-Identifier: MIT
// WatchMetrics over a LinkMonitor the test drives: an update after one link moved makes anew that
// link's series only (issue 44: the watch copied all 10,000 links four times a second), serves every
// link still, and serves what a watch that reads every link would.
#include "resulttext.h"
#include "testservers.h"
#include "watch/linkmonitor.h"
#include "watch/watchmetrics.h"
#include "wire/sourcemessage.h"

#include <QSet>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = 1'000'000'000;
constexpr qint64 kStart = 1'700'000'000'000'000'000LL;
constexpr int kLinks = 200;

QList<LinkDef> links()
{
    QList<LinkDef> out;
    for (int i = 0; i < kLinks; ++i) {
        LinkDef l;
        l.config = u"fleet"_s;
        l.client = u"fleet_bridge"_s;
        l.direction = Direction::Mqtt2Ros;
        l.rosTopic = u"/fleet/%1"_s.arg(i);
        l.mqttTopic = u"fleet/%1"_s.arg(i);
        out << l;
    }
    return out;
}

SourceHead mqttHead(int link, qint64 ns)
{
    return SourceHead {SourceGraph::Mqtt, u"fleet/%1"_s.arg(link), ns, 12, QByteArray(12, 'x'), std::nullopt};
}

/// The exposition's lines that are in `a` and not in `b`.
QStringList only(const QByteArray& a, const QByteArray& b)
{
    const QList<QByteArray> bs = b.split('\n');
    const QSet<QByteArray> theirs(bs.cbegin(), bs.cend());
    QStringList out;
    for (const QByteArray& line : a.split('\n'))
        if (!theirs.contains(line))
            out << QString::fromUtf8(line);
    return out;
}

std::unique_ptr<WatchMetrics> serve()
{
    QString error;
    std::unique_ptr<WatchMetrics> m
        = noted(WatchMetrics::serve(u"127.0.0.1:0"_s, {{u"host"_s, u"lab"_s}}), &error).value_or(nullptr);
    if (!m)
        qWarning("%s", qPrintable(error));
    return m;
}
} // namespace

class TestWatchMetrics : public QObject
{
    Q_OBJECT
private slots:
    /// Regression (issue 44): one link heard one message; the next answer differs in that link's
    /// source counters only, every link is still served, and the answer is the one a watch that
    /// reads every link gives.
    void anUpdateAfterOneLinkMovedChangesOnlyItsSeries()
    {
        LinkMonitor monitor;
        monitor.setHistoryPoints(0);
        monitor.setLinks(links(), kStart);
        std::vector<SourceHead> all;
        for (int i = 0; i < kLinks; ++i)
            all.push_back(mqttHead(i, kStart + kSecond / 2));
        monitor.reader().add(all);
        monitor.tick(kStart + kSecond); // rates refreshed, every link judged
        const std::unique_ptr<WatchMetrics> metrics = serve();
        QVERIFY(metrics);
        metrics->update(monitor);
        const QByteArray before = TestServers::httpGet(quint16(metrics->port()), u"/metrics"_s);
        QCOMPARE(before.count("\nbridgescope_link_state{"), kLinks);

        monitor.reader().add({mqttHead(7, kStart + kSecond + 1)});
        QCOMPARE(monitor.takeMoved(), std::vector<int> {7});
        monitor.reader().add({mqttHead(7, kStart + kSecond + 2)}); // taken by the metrics below
        metrics->update(monitor);
        const QByteArray after = TestServers::httpGet(quint16(metrics->port()), u"/metrics"_s);
        QCOMPARE(after.count("\nbridgescope_link_state{"), kLinks);
        const QString seven = u"link=\"fleet/7 → /fleet/7\""_s;
        const QStringList gone = only(before, after), come = only(after, before);
        QCOMPARE(gone.size(), 2);
        QCOMPARE(come.size(), 2);
        for (const QString& line : gone + come)
            QVERIFY2(line.contains(seven) && line.contains(u"side=\"source\""_s), qPrintable(line));
        QVERIFY(come.join(u'\n').contains(u"bridgescope_link_messages_total{"_s));
        QVERIFY2(come.filter(u"bridgescope_link_messages_total"_s).value(0).endsWith(u" 3"_s),
                 qPrintable(come.join(u'\n')));

        // A watch whose metrics read every link (they start with the links) serves the same.
        const std::unique_ptr<WatchMetrics> whole = serve();
        QVERIFY(whole);
        whole->update(monitor);
        QCOMPARE(TestServers::httpGet(quint16(whole->port()), u"/metrics"_s), after);
    }

    /// Nothing moved: no link is read again, and the answer stands.
    void nothingMovedServesTheSameAnswer()
    {
        LinkMonitor monitor;
        monitor.setLinks(links(), kStart);
        monitor.tick(kStart + kSecond);
        const std::unique_ptr<WatchMetrics> metrics = serve();
        QVERIFY(metrics);
        metrics->update(monitor);
        const QByteArray first = TestServers::httpGet(quint16(metrics->port()), u"/metrics"_s);
        monitor.tick(kStart + 2 * kSecond);
        QVERIFY(monitor.takeMoved().empty()); // a silent fleet is neither refreshed nor judged
        metrics->update(monitor);
        QCOMPARE(TestServers::httpGet(quint16(metrics->port()), u"/metrics"_s), first);
        QCOMPARE(first.count("\nbridgescope_link_state{"), kLinks);
    }
};

QTEST_GUILESS_MAIN(TestWatchMetrics)
#include "tst_watchmetrics.moc"
