// SPDX-License-Identifier: MIT
// The /metrics exposition of 1,000 watched links (about 9,000 series, a latency histogram on a
// tenth of them): our snapshot formatted by MetricsExposition, in both formats, against the same
// series in prometheus-cpp (Debian's prometheus-cpp-dev: Registry::Collect and TextSerializer),
// the peer that served them before, in the same run. And a whole scrape over HTTP on loopback.
//
//   scripts/bench.sh bench_metrics          (BENCH_LINKS overrides the 1,000 links)
#include "benchutil.h"
#include "testservers.h"
#include "watch/metricsserver.h"

#include <prometheus/counter.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>
#include <prometheus/text_serializer.h>
#include <QCoreApplication>

using namespace Qt::StringLiterals;

namespace {
MetricsSnapshot snapshotOf(int links)
{
    using MetricsExposition::label;
    MetricsSnapshot s;
    s.ownLabels = label("host", "vehicle-1");
    for (int i = 0; i < links; ++i) {
        MetricsSnapshot::Link l;
        const QByteArray n = QByteArray::number(i);
        l.labels = s.ownLabels + ',' + label("bridge", "fleet_bridge") + ','
            + label("link", "fleet/t" + n + " → /fleet/t" + n) + ',' + label("direction", "mqtt2ros");
        l.stage = label("stage", "bridge");
        l.sourceMessages = 12345 + i;
        l.destinationMessages = 12340 + i;
        l.sourceBytes = 1234567.0 * i;
        l.destinationBytes = 1234000.0 * i;
        l.lost = i % 7;
        l.sourceRate = 9.87;
        l.destinationRate = 9.81;
        l.state = i % 3;
        if (i % 10 == 0) {
            l.hasLatency = true;
            l.buckets[6] = 100; // 8 ms
            l.buckets[7] = 20; // 15 ms
            l.latencyCount = 120;
            l.latencySum = 1.234;
        }
        s.links.push_back(l);
    }
    s.bridges.push_back({s.ownLabels + ',' + label("bridge", "fleet_bridge"), true});
    return s;
}

/// The same series in prometheus-cpp, as watchmetrics.cpp registered them before.
std::shared_ptr<prometheus::Registry> registryOf(int links)
{
    using namespace prometheus;
    auto r = std::make_shared<Registry>();
    auto& messages = BuildCounter().Name("bridgescope_link_messages_total").Help("m").Register(*r);
    auto& bytes = BuildCounter().Name("bridgescope_link_bytes_total").Help("b").Register(*r);
    auto& lost = BuildCounter().Name("bridgescope_link_lost_total").Help("l").Register(*r);
    auto& stalls = BuildCounter().Name("bridgescope_link_stalls_total").Help("s").Register(*r);
    auto& rate = BuildGauge().Name("bridgescope_link_rate_hz").Help("r").Register(*r);
    auto& state = BuildGauge().Name("bridgescope_link_state").Help("s").Register(*r);
    auto& latency = BuildHistogram().Name("bridgescope_link_latency_seconds").Help("l").Register(*r);
    auto& up = BuildGauge().Name("bridgescope_bridge_up").Help("u").Register(*r);
    const Histogram::BucketBoundaries bounds(MetricsSnapshot::kLatencyBounds.cbegin(),
                                             MetricsSnapshot::kLatencyBounds.cend());
    for (int i = 0; i < links; ++i) {
        const std::string n = std::to_string(i);
        const Labels labels {{"host", "vehicle-1"},
                             {"bridge", "fleet_bridge"},
                             {"link", "fleet/t" + n + " → /fleet/t" + n},
                             {"direction", "mqtt2ros"}};
        for (const char* side : {"source", "destination"}) {
            Labels l = labels;
            l.emplace("side", side);
            messages.Add(l).Increment(12345 + i);
            bytes.Add(l).Increment(1234567.0 * i);
            rate.Add(l).Set(9.87);
        }
        lost.Add(labels).Increment(i % 7);
        stalls.Add(labels);
        state.Add(labels).Set(i % 3);
        if (i % 10 == 0) {
            Labels staged = labels;
            staged.emplace("stage", "bridge");
            Histogram& h = latency.Add(staged, bounds);
            for (int k = 0; k < 120; ++k)
                h.Observe(k < 100 ? 0.008 : 0.015);
        }
    }
    up.Add({{"host", "vehicle-1"}, {"bridge", "fleet_bridge"}}).Set(1);
    return r;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int links = Bench::envInt("BENCH_LINKS", 1000);
    const int runs = 15;
    const MetricsSnapshot snapshot = snapshotOf(links);
    const auto registry = registryOf(links);
    qsizetype ours = 0;
    std::size_t theirs = 0;
    qsizetype om = 0;
    const double text = Bench::medianMs(
        runs, [&] { ours = MetricsExposition::write(snapshot, MetricsFormat::Text).size(); });
    const double openMetrics = Bench::medianMs(
        runs, [&] { om = MetricsExposition::write(snapshot, MetricsFormat::OpenMetrics).size(); });
    const double peer = Bench::medianMs(runs, [&] {
        const prometheus::TextSerializer serializer;
        theirs = serializer.Serialize(registry->Collect()).size();
    });
    Result<std::unique_ptr<MetricsServer>> listening = MetricsServer::listen(u"127.0.0.1:0"_s);
    if (!listening) {
        qCritical("%s", qPrintable(listening.error().toString()));
        return 1;
    }
    const std::unique_ptr<MetricsServer> server = std::move(listening).value();
    server->publish(std::make_shared<MetricsSnapshot>(snapshot));
    qsizetype scraped = 0;
    const double http = Bench::medianMs(runs, [&] {
        scraped = TestServers::httpRequest(server->port(),
                                           "GET /metrics HTTP/1.1\r\nAccept: application/"
                                           "openmetrics-text;version=1.0.0,text/plain;q=0.5\r\n\r\n")
                      .size();
    });

    Bench::header("value");
    Bench::row(u"links"_s, links);
    Bench::row(u"exposition, text format (MB)"_s, double(ours) / 1e6);
    Bench::row(u"exposition, prometheus-cpp text format (MB)"_s, double(theirs) / 1e6);
    Bench::row(u"write, text format (ms, median of %1)"_s.arg(runs), text);
    Bench::row(u"write, OpenMetrics (ms)"_s, openMetrics, u"%1 MB"_s.arg(double(om) / 1e6, 0, 'f', 2));
    Bench::row(u"peer: prometheus-cpp Collect + Serialize (ms)"_s, peer);
    Bench::row(u"prometheus-cpp / ours, text format (x)"_s, peer / text);
    Bench::gate("metrics_prometheus_cpp_vs_ours", peer / text);
    Bench::row(u"whole scrape over HTTP on loopback, OpenMetrics (ms)"_s, http, u"%1 bytes"_s.arg(scraped));
    return 0;
}
