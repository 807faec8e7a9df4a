// SPDX-License-Identifier: MIT
// The fleet view's source on a real fleet (issue 44): two `bridgescope watch` processes, each on its
// own "host" (WatchedHost), scraped by a real Prometheus. FleetSource lists every link of both
// watches with their host labels and the figures each watch serves itself, judges them, marks the
// host whose watch stopped as no longer reporting, and says its own outage when Prometheus goes.
#include "fleet/fleetsource.h"
#include "watchedfleet.h"

#include <QSignalSpy>
#include <QTest>

using namespace Qt::StringLiterals;

namespace {

const FleetLink* linkOf(const FleetSnapshot& s, const QString& host)
{
    for (const FleetLink& l : s.links)
        if (l.host == host && l.link == "fleet/stamped"_L1)
            return &l;
    return nullptr;
}

const FleetHost* hostOf(const FleetSnapshot& s, const QString& name)
{
    for (const FleetHost& h : s.hosts)
        if (h.name == name)
            return &h;
    return nullptr;
}

/// What `source`'s server answers now to the refresh's query `name`.
PrometheusAnswer answerTo(FleetSource& source, const QString& name)
{
    QString promql;
    for (const auto& [n, q] : FleetSnapshotBuilder::queries())
        if (n == name)
            promql = q;
    PrometheusAnswer answer;
    answer.error = u"no answer"_s;
    source.client()->query(promql, [&](const PrometheusAnswer& a) { answer = a; });
    if (!QTest::qWaitFor([&] { return answer.error != "no answer"_L1; }, 15000))
        answer.error = u"no answer within 15 s"_s;
    return answer;
}

/// The hosts of the series in `a`, sorted.
QStringList hostsOf(const PrometheusAnswer& a)
{
    QStringList hosts;
    for (const PrometheusAnswer::Series& s : a.series)
        hosts << s.label(u"host"_s);
    hosts.sort();
    return hosts;
}

/// One refresh, waited for.
bool refreshed(FleetSource& source)
{
    QSignalSpy spy(&source, &FleetSource::refreshed);
    source.refresh();
    return spy.wait(15000);
}
} // namespace

class TestFleetView : public QObject
{
    Q_OBJECT

    WatchedFleet m_fleet;
    FleetSource m_source;

    /// The watch's own figure of the link on `h`.
    static double own(const WatchedHost& h, const QString& name, const QStringList& labels = {})
    {
        return TestServers::metricSample(h.metrics(), name,
                                         QStringList {u"link=\"fleet/stamped\""_s} + labels);
    }

private slots:
    void initTestCase()
    {
        m_fleet.start();
        QVERIFY(!QTest::currentTestFailed());
        const Result<QUrl> url = PrometheusClient::checkUrl(u"http://"_s + m_fleet.prometheus.address());
        QVERIFY(url.ok());
        m_source.setServer(*url);
        // These tests compare the totals with each watch's own as they grow: asked at every
        // refresh (tst_fleetsnapshot pins down that they are not, by default).
        m_source.setTotalsSeconds(0);
    }

    void cleanupTestCase() { m_fleet.stop(); }

    /// Every link of both watches, with its host, and the figures each watch serves itself.
    void listsEveryHostsLinksWithTheirOwnFigures()
    {
        // The link is discovered from its retained type announcement before anything is sent.
        m_fleet.awaitStampedLinks();
        m_fleet.hosts[0].send(kVehicleLatencies, 48);
        m_fleet.hosts[1].send(kEdgeLatencies, 72);
        // Until Prometheus has scraped the last message of both.
        QTRY_VERIFY_WITH_TIMEOUT(
            refreshed(m_source) && linkOf(m_source.snapshot(), u"vehicle-1"_s)
                && linkOf(m_source.snapshot(), u"edge-1"_s)
                && linkOf(m_source.snapshot(), u"vehicle-1"_s)->figures.destination.messages == 48
                && linkOf(m_source.snapshot(), u"edge-1"_s)->figures.destination.messages == 72,
            30000);
        const FleetSnapshot& s = m_source.snapshot();
        QVERIFY2(m_source.error().isEmpty(), qPrintable(m_source.error()));
        QCOMPARE(s.links.size(), 2);
        QCOMPARE(s.hosts.size(), 2);
        QCOMPARE(s.badSamples, 0);
        for (const WatchedHost& h : m_fleet.hosts) {
            const FleetHost* host = hostOf(s, h.name);
            QVERIFY(host);
            QVERIFY(host->reporting);
            QVERIFY(!host->version.isEmpty());
            const FleetLink* l = linkOf(s, h.name);
            QCOMPARE(l->host, h.name);
            QCOMPARE(l->direction, u"ros2mqtt"_s);
            QCOMPARE(double(l->figures.destination.messages),
                     own(h, u"bridgescope_link_messages_total"_s, {u"side=\"destination\""_s}));
            QCOMPARE(double(l->figures.source.messages),
                     own(h, u"bridgescope_link_messages_total"_s, {u"side=\"source\""_s}));
            QCOMPARE(double(l->figures.destination.bytes),
                     own(h, u"bridgescope_link_bytes_total"_s, {u"side=\"destination\""_s}));
            QCOMPARE(double(l->figures.lost), own(h, u"bridgescope_link_lost_total"_s));
            QCOMPARE(double(l->figures.stalls), own(h, u"bridgescope_link_stalls_total"_s));
            QVERIFY(!l->verdict.unknown);
            QVERIFY(l->hostReporting);
            // A discovered link (its MQTT topic only): no source side, no source rate, not 0.
            QVERIFY(l->def.discovered);
            QVERIFY2(std::isnan(l->figures.source.rateHz),
                     qPrintable(QString::number(l->figures.source.rateHz)));
        }
        // Issue 44, point 5: the hour's links are asked only of hosts not reporting; the links of
        // the others come from their state, and the answers carry only the labels the view reads.
        const PrometheusAnswer hour = answerTo(m_source, u"links"_s);
        QVERIFY2(hour.ok(), qPrintable(hour.error));
        QCOMPARE(hostsOf(hour), QStringList());
        const PrometheusAnswer state = answerTo(m_source, u"state"_s);
        QCOMPARE(hostsOf(state), (QStringList {u"edge-1"_s, u"vehicle-1"_s}));
        for (const PrometheusAnswer::Series& series : state.series) {
            QStringList names;
            for (const auto& [name, value] : series.labels)
                names << name;
            names.sort();
            QCOMPARE(names, (QStringList {u"bridge"_s, u"direction"_s, u"host"_s, u"link"_s}));
        }
        // The p99 from the histograms, in the bucket the backdates put it: 3 s in (2.5, 5], 6 s in (5, 10].
        const double vehicleP99 = linkOf(s, u"vehicle-1"_s)->figures.latencyP99Ms;
        const double edgeP99 = linkOf(s, u"edge-1"_s)->figures.latencyP99Ms;
        QVERIFY2(vehicleP99 > 2500 && vehicleP99 <= 5000, qPrintable(QString::number(vehicleP99)));
        QVERIFY2(edgeP99 > 5000 && edgeP99 <= 10000, qPrintable(QString::number(edgeP99)));
    }

    /// The table's rate is the chart's: once the watch's own 5-s rate of the edge's burst is 0 (a
    /// link slower than a message in 5 s), the table still shows what the chart draws, not 0.0.
    void theTablesRateIsTheChartsRate()
    {
        const QString fiveSeconds
            = u"bridgescope_link_rate_hz{host=\"edge-1\",link=\"fleet/stamped\",side=\"destination\"}"_s;
        QTRY_COMPARE_WITH_TIMEOUT(m_fleet.prometheus.value(fiveSeconds), 0.0, 20000);
        QVERIFY(refreshed(m_source));
        const double now = double(QDateTime::currentMSecsSinceEpoch()) / 1000.0;
        const FleetLink link = *linkOf(m_source.snapshot(), u"edge-1"_s);
        FleetHistory history;
        bool done = false;
        m_source.history(link, now, 5, 1, [&](const FleetHistory& h) {
            history = h;
            done = true;
        });
        QTRY_VERIFY_WITH_TIMEOUT(done, 15000);
        QVERIFY2(history.error.isEmpty(), qPrintable(history.error));
        QVERIFY(!history.destinationRateHz.isEmpty());
        const double table = link.figures.destination.rateHz;
        const double chart = history.destinationRateHz.constLast().value;
        QVERIFY2(table > 0, "the minute still holds the 72 messages");
        // The same window a moment apart: within a scrape's share of it.
        QVERIFY2(std::abs(table - chart) <= 0.25 * chart,
                 qPrintable(u"table %1 Hz, chart %2 Hz"_s.arg(table).arg(chart)));
    }

    /// The link's history from query_range: the destination's rate over the last minutes.
    void historyComesFromQueryRange()
    {
        const FleetLink link = *linkOf(m_source.snapshot(), u"edge-1"_s);
        FleetHistory history;
        bool done = false;
        m_source.history(link, double(QDateTime::currentMSecsSinceEpoch()) / 1000.0, 5, 1,
                         [&](const FleetHistory& h) {
                             history = h;
                             done = true;
                         });
        QTRY_VERIFY_WITH_TIMEOUT(done, 15000);
        QVERIFY2(history.error.isEmpty(), qPrintable(history.error));
        QVERIFY(!history.destinationRateHz.isEmpty());
        double peak = 0;
        for (const PrometheusAnswer::Point& p : history.destinationRateHz)
            peak = std::max(peak, p.value);
        QVERIFY2(peak > 0, "the 72 messages show in the rate");
        QVERIFY(!history.latencyP99Ms.isEmpty());
    }

    /// A watch that stops: its host is not reporting, its links unknown, never ok.
    void aStoppedWatchsHostStoppedReporting()
    {
        QVERIFY(m_fleet.hosts[1].stop());
        QTRY_VERIFY_WITH_TIMEOUT(refreshed(m_source) && hostOf(m_source.snapshot(), u"edge-1"_s)
                                     && !hostOf(m_source.snapshot(), u"edge-1"_s)->reporting,
                                 20000);
        const FleetSnapshot& s = m_source.snapshot();
        const FleetLink* edge = linkOf(s, u"edge-1"_s);
        QVERIFY2(edge, "the stopped host's link stays listed");
        QVERIFY(!edge->hostReporting);
        QVERIFY(edge->verdict.unknown);
        QVERIFY2(edge->verdict.detail.startsWith(u"host stopped reporting since "_s),
                 qPrintable(edge->verdict.detail));
        const FleetLink* vehicle = linkOf(s, u"vehicle-1"_s);
        QVERIFY(vehicle && vehicle->hostReporting && !vehicle->verdict.unknown);
        QVERIFY(hostOf(s, u"vehicle-1"_s)->reporting);
        QCOMPARE(hostsOf(answerTo(m_source, u"links"_s)), QStringList {u"edge-1"_s});
    }

    /// Prometheus gone: the window's own outage is said, the links stay as they were.
    void ourOwnOutageIsSaidNotDrawnAsLinksDown()
    {
        QStringList before;
        for (const FleetLink& l : m_source.snapshot().links)
            before << l.key() + u' ' + l.verdict.detail;
        const QString address = m_fleet.prometheus.address();
        m_fleet.prometheus.stop();
        QVERIFY(refreshed(m_source));
        QVERIFY2(m_source.error().startsWith(u"cannot read the fleet from http://%1: "_s.arg(address)),
                 qPrintable(m_source.error()));
        QStringList after;
        for (const FleetLink& l : m_source.snapshot().links)
            after << l.key() + u' ' + l.verdict.detail;
        QCOMPARE(after, before);
    }
};

QTEST_GUILESS_MAIN(TestFleetView)
#include "tst_fleetview.moc"
