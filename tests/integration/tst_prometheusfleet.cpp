// SPDX-License-Identifier: MIT
// A fleet on Prometheus (issue 44): two `bridgescope watch` processes, each on its own "host" (its
// own mosquitto and rosmaster, its own --label host=…), scraped by a real Prometheus server. The
// latency histograms of the same link on both hosts add up in Prometheus to what numpy counts on
// the union of the samples the test sent (tests/scripts/histogram_reference.py), bucket by bucket,
// and the fleet's percentiles fall in the buckets numpy's do.
#include "pythonref.h"
#include "watch/metricsexposition.h"
#include "watchedfleet.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using namespace Qt::StringLiterals;

class TestPrometheusFleet : public QObject
{
    Q_OBJECT

    WatchedFleet m_fleet;
    WatchedHost (&m_hosts)[2] = m_fleet.hosts;
    PrometheusServer& m_prometheus = m_fleet.prometheus;

private slots:
    void initTestCase()
    {
        m_fleet.start(u"rule_files: ['" BRIDGESCOPE_SOURCE_DIR
                      "/resources/prometheus/bridgescope-rules.yml']\n"_s);
    }

    void cleanupTestCase() { m_fleet.stop(); }

    /// Buckets from two watches added by Prometheus equal numpy's counts on the union of the
    /// samples; the count is the union's, the sum within the transit time of each sample.
    void histogramsAddUpAcrossHosts()
    {
        // The link is discovered from its retained type announcement before anything is sent.
        m_fleet.awaitStampedLinks();
        m_hosts[0].send(kVehicleLatencies, 48);
        m_hosts[1].send(kEdgeLatencies, 72);
        const QString link = u"{link=\"fleet/stamped\",site=\"garage\"}"_s;
        QTRY_COMPARE_WITH_TIMEOUT(
            m_prometheus.value(u"sum(bridgescope_link_latency_seconds_count%1)"_s.arg(link)), 120.0, 30000);
        // Each host's own series, told apart by its label.
        QCOMPARE(
            m_prometheus.value(
                u"sum(bridgescope_link_latency_seconds_count{host=\"vehicle-1\",link=\"fleet/stamped\"})"_s),
            48.0);
        QCOMPARE(
            m_prometheus.value(
                u"sum(bridgescope_link_latency_seconds_count{host=\"edge-1\",link=\"fleet/stamped\"})"_s),
            72.0);

        // numpy on the union of what was sent.
        QFile samples(m_hosts[0].servers.tempPath() + u"/union.txt"_s);
        QVERIFY(samples.open(QIODevice::WriteOnly));
        for (const WatchedHost& h : m_hosts)
            for (double s : h.sent)
                samples.write(QByteArray::number(s, 'g', 17) + '\n');
        samples.close();
        QStringList bounds;
        for (double b : MetricsSnapshot::kLatencyBounds)
            bounds << QString::number(b, 'g', 17);
        const QJsonObject want
            = PythonRef::run(u"histogram_reference.py"_s, {samples.fileName(), bounds.join(u',')}).object();
        QCOMPARE(want.value(u"count"_s).toInt(), 120);

        const QJsonArray buckets
            = m_prometheus.query(u"sum by (le) (bridgescope_link_latency_seconds_bucket%1)"_s.arg(link));
        QCOMPARE(buckets.size(), int(MetricsSnapshot::kLatencyBounds.size()) + 1);
        const QJsonObject wantLe = want.value(u"le"_s).toObject();
        int compared = 0;
        for (const QJsonValue& v : buckets) {
            const QJsonObject series = v.toObject();
            const QString le = series.value(u"metric"_s).toObject().value(u"le"_s).toString();
            const double got = series.value(u"value"_s).toArray().at(1).toString().toDouble();
            if (le == u"+Inf"_s) {
                QCOMPARE(got, 120.0);
                continue;
            }
            for (auto it = wantLe.begin(); it != wantLe.end(); ++it)
                if (it.key().toDouble() == le.toDouble()) {
                    QVERIFY2(got == it.value().toDouble(),
                             qPrintable(u"le %1: Prometheus %2, numpy %3"_s.arg(le).arg(got).arg(
                                 it.value().toInt())));
                    ++compared;
                }
        }
        QCOMPARE(compared, int(MetricsSnapshot::kLatencyBounds.size()));
        // The sum: the backdates plus each message's transit from this test to the watch.
        const double sum = m_prometheus.value(u"sum(bridgescope_link_latency_seconds_sum%1)"_s.arg(link));
        const double wantSum = want.value(u"sum"_s).toDouble();
        QVERIFY2(sum >= wantSum && sum < wantSum + 120 * 0.049,
                 qPrintable(u"%1 vs %2"_s.arg(sum).arg(wantSum)));
        // The fleet's percentiles: Prometheus interpolates inside the bucket numpy's value is in.
        for (const char* q : {"50", "99"}) {
            const double got = m_prometheus.value(
                u"histogram_quantile(0.%1, sum by (le) (bridgescope_link_latency_seconds_bucket%2))"_s.arg(
                    QString::fromLatin1(q), link));
            const QJsonArray bucket = want.value(u"p%1_bucket"_s.arg(QString::fromLatin1(q))).toArray();
            QVERIFY2(got > bucket.at(0).toDouble() && got <= bucket.at(1).toDouble(),
                     qPrintable(u"p%1: Prometheus %2, numpy %3 in (%4, %5]"_s.arg(QString::fromLatin1(q))
                                    .arg(got)
                                    .arg(want.value(u"p%1"_s.arg(QString::fromLatin1(q))).toDouble())
                                    .arg(bucket.at(0).toDouble())
                                    .arg(bucket.at(1).toDouble())));
        }
    }

    /// Every series carries the host's labels: the bridges, the watch's own figures and its info.
    void everySeriesSaysItsHost()
    {
        for (const WatchedHost& h : m_hosts) {
            const QString selector = u"{host=\"%1\",site=\"garage\"}"_s.arg(h.name);
            QTRY_COMPARE_WITH_TIMEOUT(m_prometheus.value(u"bridgescope_watch_info%1"_s.arg(selector)), 1.0,
                                      10000);
            QCOMPARE(m_prometheus.value(u"bridgescope_metrics_truncated%1"_s.arg(selector)), 0.0);
            QCOMPARE(m_prometheus.value(u"count(bridgescope_link_state%1)"_s.arg(selector)), 1.0);
        }
        QCOMPARE(m_prometheus.value(u"count(bridgescope_link_state{link=\"fleet/stamped\"})"_s), 2.0);
    }

    /// The rules that ship (`bridgescope rules`) read the series a real watch serves: each host's
    /// recorded message rate and p99, and a watch that stops is an alert naming its host.
    void theShippedRulesReadTheWatches()
    {
        for (const WatchedHost& h : m_hosts)
            QTRY_VERIFY2_WITH_TIMEOUT(
                m_prometheus.value(
                    u"host:bridgescope_link_messages:rate5m{host=\"%1\",side=\"destination\"}"_s.arg(h.name))
                    > 0,
                qPrintable(h.name), 15000);
        // The rule evaluates every second: until an evaluation after the last scrape it may hold the
        // p99 of the first messages only (0.0995 in a CI run). The 5.01 s backdates: (5, 10].
        double p99 = qQNaN();
        QTRY_VERIFY2_WITH_TIMEOUT(
            (p99 = m_prometheus.value(u"host_bridge_link:bridgescope_link_latency_seconds:p99_rate5m"
                                      u"{host=\"edge-1\",link=\"fleet/stamped\"}"_s))
                    > 5
                && p99 <= 10,
            qPrintable(QString::number(p99)), 15000);
        QVERIFY(m_prometheus.query(u"ALERTS{alertname=\"BridgescopeWatchDown\"}"_s).isEmpty());
        WatchedHost& stopped = m_hosts[1];
        QVERIFY(stopped.stop());
        // Pending first (its `for:` is 2 minutes): the alert is there and names the stopped host.
        QTRY_VERIFY_WITH_TIMEOUT(
            !m_prometheus.query(u"ALERTS{alertname=\"BridgescopeWatchDown\"}"_s).isEmpty(), 15000);
        const QJsonArray alerts = m_prometheus.query(u"ALERTS{alertname=\"BridgescopeWatchDown\"}"_s);
        QCOMPARE(alerts.size(), 1);
        QCOMPARE(alerts.first().toObject().value(u"metric"_s).toObject().value(u"instance"_s).toString(),
                 u"127.0.0.1:%1"_s.arg(stopped.metricsPort));
    }

    /// --label refuses what would break the fleet's series, before anything starts.
    void badLabelsAreRefused()
    {
        const QStringList bad {u"le=1"_s,
                               u"job=x"_s,
                               u"2x=y"_s,
                               u"__name=x"_s,
                               u"site="_s,
                               u"novalue"_s,
                               u"site="_s + QString(300, u'x')};
        for (const QString& label : bad) {
            QProcess watch;
            watch.start(QStringLiteral(BRIDGESCOPE_BINARY),
                        {u"watch"_s, u"--broker"_s, m_hosts[0].servers.brokerUrl(), u"--metrics"_s,
                         u"127.0.0.1:0"_s, u"--label"_s, label, u"--seconds"_s, u"1"_s});
            QVERIFY(watch.waitForFinished(10000));
            const QString said = QString::fromUtf8(watch.readAllStandardError());
            QVERIFY2(watch.exitCode() == 2 && said.contains(u"label"_s), qPrintable(label + u": "_s + said));
        }
    }
};

QTEST_GUILESS_MAIN(TestPrometheusFleet)
#include "tst_prometheusfleet.moc"
