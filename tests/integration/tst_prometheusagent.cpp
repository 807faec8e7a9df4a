// SPDX-License-Identifier: MIT
// A fleet on Prometheus (issue 44), the hosts that go offline and the central view:
// - a vehicle's Prometheus in agent mode (the shipped resources/prometheus/agent.yml) scrapes its
//   watch and remote-writes to the lab's server through a TCP relay the test cuts for 20 s: after
//   the link is back, the lab holds one sample per scrape interval over the whole outage and the
//   message counters the watch counted meanwhile, nothing lost inside the agent's buffer;
// - two lab servers scrape one watch each and a central one federates bridgescope_* from both (the
//   shipped federation.yml): it holds every link of both watches, with their host and counts.
#include "prometheusserver.h"
#include "tcprelay.h"
#include "watchedhost.h"

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>

using namespace Qt::StringLiterals;

namespace {
constexpr int kOutageMs = 20000;

/// A shipped file of resources/prometheus with `replace` (pairs: text, by) done; empty when one
/// of the texts is not in it (the test then fails instead of testing something else).
QString shipped(const QString& file, const QList<std::pair<QString, QString>>& replace)
{
    QFile f(QStringLiteral(BRIDGESCOPE_SOURCE_DIR) + u"/resources/prometheus/"_s + file);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QString text = QString::fromUtf8(f.readAll());
    for (const auto& [from, to] : replace) {
        if (!text.contains(from))
            return {};
        text.replace(from, to);
    }
    return text;
}

/// The raw samples (timestamp s, value) of the one series `selector` selects, over `range` up to `at`.
QList<std::pair<double, double>> samples(const PrometheusServer& server, const QString& selector,
                                         const QString& range, double at)
{
    const QJsonArray result
        = server.query(u"%1[%2] @ %3"_s.arg(selector, range, QString::number(at, 'f', 3)));
    QList<std::pair<double, double>> out;
    if (result.size() != 1)
        return out;
    for (const QJsonValue& v : result.first().toObject().value(u"values"_s).toArray())
        out.append({v.toArray().at(0).toDouble(), v.toArray().at(1).toString().toDouble()});
    return out;
}

double nowS()
{
    return double(QDateTime::currentMSecsSinceEpoch()) / 1000;
}
} // namespace

class TestPrometheusAgent : public QObject
{
    Q_OBJECT

    WatchedHost m_hosts[2];
    const QStringList m_links[2] {{u"fleet/stamped"_s, u"fleet/pose"_s, u"fleet/scan"_s},
                                  {u"fleet/stamped"_s, u"fleet/map"_s}};

    /// Publishes `n` messages on every link of host `i`, one every 20 ms.
    void publish(int i, int n)
    {
        for (int k = 0; k < n; ++k)
            for (const QString& link : m_links[i]) {
                QVERIFY(m_hosts[i].publishStamped(link, 0.01));
                QTest::qWait(20); // a paced source
            }
    }

    /// publish(), then waits until host `i`'s watch has counted the `n` messages on each link.
    void publishAndCount(int i, int n)
    {
        const QList<double> before = counts(i);
        publish(i, n);
        for (int l = 0; l < m_links[i].size(); ++l)
            QTRY_COMPARE_WITH_TIMEOUT(m_hosts[i].watchCount(m_links[i][l]), before[l] + n, 10000);
    }

    QList<double> counts(int i) const
    {
        QList<double> out;
        for (const QString& link : m_links[i])
            out << m_hosts[i].watchCount(link);
        return out;
    }

    /// `server` holds host `i`'s own count of every link (once the watch has counted what was sent).
    void compareCounts(const PrometheusServer& server, int i)
    {
        for (const QString& link : m_links[i]) {
            const double own = m_hosts[i].watchCount(link);
            QTRY_COMPARE_WITH_TIMEOUT(
                server.value(
                    u"bridgescope_link_messages_total{host=\"%1\",link=\"%2\",side=\"destination\"}"_s.arg(
                        m_hosts[i].name, link)),
                own, 15000);
        }
    }

private slots:
    void initTestCase()
    {
        m_hosts[0].start(u"vehicle-1"_s, m_links[0]);
        QVERIFY(!QTest::currentTestFailed());
        m_hosts[1].start(u"edge-1"_s, m_links[1]);
        QVERIFY(!QTest::currentTestFailed());
        // Every announced link is discovered, at 0, before anything is sent.
        for (int i = 0; i < 2; ++i)
            for (const QString& link : m_links[i])
                QTRY_VERIFY2_WITH_TIMEOUT(m_hosts[i].watchCount(link) == 0, qPrintable(link), 15000);
    }

    void cleanupTestCase()
    {
        for (WatchedHost& h : m_hosts)
            h.stop();
    }

    /// The agent scrapes every second; the link to the lab is cut for 20 s while the watch counts
    /// messages; once it is back, the lab holds every scrape of the outage and the watch's counts.
    void agentKeepsTheOutageForTheLab()
    {
        WatchedHost& vehicle = m_hosts[0];
        PrometheusServer lab;
        QVERIFY2(lab.start(u"global:\n  scrape_interval: 1s\n"_s, {u"--web.enable-remote-write-receiver"_s}),
                 qPrintable(lab.errorString()));
        TcpRelay link;
        QVERIFY(link.start(lab.port()));
        // The shipped agent.yml, pointed at this vehicle's watch and at the lab through the relay.
        const QString config
            = shipped(u"agent.yml"_s,
                      {{u"scrape_interval: 5s"_s, u"scrape_interval: 1s"_s},
                       {u"127.0.0.1:9464"_s, u"127.0.0.1:%1"_s.arg(vehicle.metricsPort)},
                       {u"http://lab-prometheus.example:9090"_s, u"http://127.0.0.1:%1"_s.arg(link.port())},
                       {u"max_backoff: 5s"_s, u"max_backoff: 1s"_s}});
        QVERIFY(!config.isEmpty());
        PrometheusServer agent;
        QVERIFY2(agent.start(config, {u"--enable-feature=agent"_s}), qPrintable(agent.errorString()));

        const QString info = u"bridgescope_watch_info{host=\"vehicle-1\"}"_s;
        QTRY_COMPARE_WITH_TIMEOUT(lab.value(info), 1.0, 20000);
        publishAndCount(0, 5);
        compareCounts(lab, 0);
        if (QTest::currentTestFailed())
            return;

        // The link goes down; the watch goes on counting what the vehicle's bridges carry.
        const double cutAt = nowS();
        link.cut();
        const QList<double> before = counts(0);
        int sentInOutage = 0;
        while (nowS() < cutAt + kOutageMs / 1000.0) { // the outage itself: a deliberate duration
            QVERIFY(vehicle.publishStamped(m_links[0][sentInOutage % m_links[0].size()], 0.01));
            ++sentInOutage;
            QTest::qWait(100);
        }
        // Nothing scraped after the cut reached the lab.
        const double newestAtLab = lab.value(u"timestamp(%1)"_s.arg(info));
        QVERIFY2(newestAtLab < cutAt + 1.0 && newestAtLab > cutAt - 5,
                 qPrintable(u"newest sample at the lab %1 s after the cut"_s.arg(newestAtLab - cutAt)));
        QVERIFY(sentInOutage > 100);
        // The watch counted every message of the outage.
        const auto countedInOutage = [&] {
            double n = 0;
            for (int l = 0; l < m_links[0].size(); ++l)
                n += vehicle.watchCount(m_links[0][l]) - before[l];
            return n;
        };
        QTRY_COMPARE_WITH_TIMEOUT(countedInOutage(), double(sentInOutage), 10000);

        const double restoredAt = nowS();
        QVERIFY(link.restore());
        publishAndCount(0, 3);
        if (QTest::currentTestFailed())
            return;
        // Caught up: the lab has samples scraped after the link came back.
        QTRY_VERIFY_WITH_TIMEOUT(lab.value(u"timestamp(%1)"_s.arg(info)) > restoredAt, 30000);
        const double caughtUpAfter = nowS() - restoredAt;
        // And the watch's own counts of everything sent, the outage's messages among them.
        compareCounts(lab, 0);
        if (QTest::currentTestFailed())
            return;

        // Every scrape of the outage at the lab: one sample a second, no gap, from before the cut
        // to after the restore (the timestamps are the agent's scrapes).
        const auto scrapes = samples(lab, info, u"%1s"_s.arg(kOutageMs / 1000 + 10), restoredAt + 3);
        QVERIFY(!scrapes.isEmpty());
        QVERIFY2(scrapes.first().first < cutAt && scrapes.last().first > restoredAt,
                 qPrintable(u"samples from %1 s to %2 s after the cut"_s.arg(scrapes.first().first - cutAt)
                                .arg(scrapes.last().first - cutAt)));
        int inOutage = 0;
        double maxGap = 0;
        for (qsizetype k = 0; k < scrapes.size(); ++k) {
            const double t = scrapes[k].first;
            if (k > 0)
                maxGap = std::max(maxGap, t - scrapes[k - 1].first);
            inOutage += t >= cutAt && t <= restoredAt ? 1 : 0;
        }
        const double outageS = restoredAt - cutAt;
        qInfo("outage %.1f s: %d samples of bridgescope_watch_info at the lab inside it, largest gap %.2f s; "
              "caught up %.1f s after the link came back; %d messages sent in the outage",
              outageS, inOutage, maxGap, caughtUpAfter, sentInOutage);
        QVERIFY2(maxGap > 0 && maxGap < 1.5, qPrintable(QString::number(maxGap)));
        QVERIFY2(inOutage >= int(outageS) - 1 && inOutage <= int(outageS) + 1,
                 qPrintable(QString::number(inOutage)));
        // The counter of a link over the outage: it rose at the lab while the link was down.
        const auto counter = samples(
            lab,
            u"bridgescope_link_messages_total{host=\"vehicle-1\",link=\"fleet/stamped\",side=\"destination\"}"_s,
            u"%1s"_s.arg(kOutageMs / 1000 + 10), restoredAt);
        double first = qQNaN();
        double last = qQNaN();
        for (const auto& [t, v] : counter)
            if (t >= cutAt + 1 && t <= restoredAt - 1) {
                first = qIsNaN(first) ? v : first;
                last = v;
            }
        // (a third of the messages went to this link, 18 of the outage's 20 s are compared)
        QVERIFY2(last - first >= sentInOutage / 3 * 0.5, qPrintable(u"%1 .. %2"_s.arg(first).arg(last)));
        QVERIFY(link.connections() >= 2); // the agent connected again after the cut
    }

    /// Two lab servers scrape one watch each, a central one federates both: every link of both
    /// watches, with its host, and each link's count as the watch's own.
    void federationCarriesEveryLink()
    {
        PrometheusServer labs[2];
        for (int i = 0; i < 2; ++i)
            QVERIFY2(
                labs[i].start(u"global:\n  scrape_interval: 1s\nscrape_configs:\n  - job_name: bridgescope\n"
                              u"    static_configs:\n      - targets: ['127.0.0.1:%1']\n"_s.arg(
                                  m_hosts[i].metricsPort)),
                qPrintable(labs[i].errorString()));
        const QString config
            = shipped(u"federation.yml"_s,
                      {{u"scrape_interval: 15s"_s, u"scrape_interval: 1s"_s},
                       {u"evaluation_interval: 15s"_s, u"evaluation_interval: 1s"_s},
                       {u"- bridgescope-rules.yml"_s,
                        u"- " BRIDGESCOPE_SOURCE_DIR "/resources/prometheus/bridgescope-rules.yml"_s},
                       {u"'lab-1.example:9090', 'lab-2.example:9090'"_s,
                        u"'%1', '%2'"_s.arg(labs[0].address(), labs[1].address())}});
        QVERIFY(!config.isEmpty());
        PrometheusServer central;
        QVERIFY2(central.start(config), qPrintable(central.errorString()));

        for (int i = 0; i < 2; ++i)
            publishAndCount(i, 4 + i);
        for (int i = 0; i < 2; ++i) {
            const WatchedHost& h = m_hosts[i];
            QCOMPARE(h.watchLinks(), int(m_links[i].size()));
            QTRY_COMPARE_WITH_TIMEOUT(
                central.value(u"count by (host) (bridgescope_link_state{host=\"%1\"})"_s.arg(h.name)),
                double(h.watchLinks()), 20000);
            compareCounts(central, i);
            // honor_labels: the lab's own job and instance, not the federation's.
            QCOMPARE(
                central.value(
                    u"count(bridgescope_watch_info{host=\"%1\",job=\"bridgescope\",instance=\"127.0.0.1:%2\"})"_s
                        .arg(h.name)
                        .arg(h.metricsPort)),
                1.0);
        }
        QCOMPARE(central.value(u"count(bridgescope_link_state)"_s), 5.0);
        // The shipped rules add the fleet up at the central server.
        QTRY_VERIFY_WITH_TIMEOUT(
            central.value(u"count(host:bridgescope_link_messages:rate5m{side=\"destination\"})"_s) == 2,
            15000);
    }
};

QTEST_GUILESS_MAIN(TestPrometheusAgent)
#include "tst_prometheusagent.moc"
