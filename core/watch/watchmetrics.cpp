// SPDX-License-Identifier: MIT
#include "watchmetrics.h"

#include "watch/linkmonitor.h"

#include <exception>
#include <prometheus/counter.h>
#include <prometheus/exposer.h>
#include <prometheus/family.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>
#include <QHash>

using namespace Qt::StringLiterals;
using prometheus::Counter;
using prometheus::Gauge;
using prometheus::Histogram;

namespace {
/// A counter that follows a total kept elsewhere.
struct Total
{
    Counter* counter = nullptr;
    double pushed = 0;
    void set(double total)
    {
        if (total > pushed) {
            counter->Increment(total - pushed);
            pushed = total;
        }
    }
};

const Histogram::BucketBoundaries& latencyBuckets()
{
    static const Histogram::BucketBoundaries b {0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05,
                                                0.1,    0.2,   0.5,   1,     2,    5,    10};
    return b;
}
} // namespace

struct WatchMetrics::Private
{
    std::unique_ptr<prometheus::Exposer> exposer;
    std::shared_ptr<prometheus::Registry> registry = std::make_shared<prometheus::Registry>();
    prometheus::Family<Counter>& messages = prometheus::BuildCounter()
                                                .Name("bridgescope_link_messages_total")
                                                .Help("Messages seen at one side of a bridged link")
                                                .Register(*registry);
    prometheus::Family<Counter>& bytes = prometheus::BuildCounter()
                                             .Name("bridgescope_link_bytes_total")
                                             .Help("Payload bytes seen at one side of a bridged link")
                                             .Register(*registry);
    prometheus::Family<Counter>& lost
        = prometheus::BuildCounter()
              .Name("bridgescope_link_lost_total")
              .Help("Messages the source sent that never reached the destination")
              .Register(*registry);
    prometheus::Family<Counter>& stalls
        = prometheus::BuildCounter()
              .Name("bridgescope_link_stalls_total")
              .Help("Times the destination fell silent while the source published")
              .Register(*registry);
    prometheus::Family<Counter>& gaps = prometheus::BuildCounter()
                                            .Name("bridgescope_link_seq_gaps_total")
                                            .Help("Header.seq values skipped at the destination")
                                            .Register(*registry);
    prometheus::Family<Gauge>& rate
        = prometheus::BuildGauge()
              .Name("bridgescope_link_rate_hz")
              .Help("Messages per second at one side of a link, over the last 5 s")
              .Register(*registry);
    prometheus::Family<Gauge>& state = prometheus::BuildGauge()
                                           .Name("bridgescope_link_state")
                                           .Help("0 ok, 1 warning, 2 alert")
                                           .Register(*registry);
    prometheus::Family<Histogram>& latency = prometheus::BuildHistogram()
                                                 .Name("bridgescope_link_latency_seconds")
                                                 .Help("Latency of stamped messages over the link")
                                                 .Register(*registry);
    prometheus::Family<Gauge>& bridgeUp = prometheus::BuildGauge()
                                              .Name("bridgescope_bridge_up")
                                              .Help("1 while the bridge carries data, 0 when it is down")
                                              .Register(*registry);

    struct Link
    {
        Total sourceMessages, destinationMessages, sourceBytes, destinationBytes, lost, stalls, gaps;
        Gauge* sourceRate = nullptr;
        Gauge* destinationRate = nullptr;
        Gauge* state = nullptr;
        // Made on the first stamp and the first Header.seq gap: links without stamps or headers
        // (most of a fleet) keep their scrape short.
        Histogram* latency = nullptr;
        prometheus::Labels labels;
    };
    QHash<QString, Link> links; ///< by link id
    QHash<QString, Gauge*> bridges;

    Link add(const LinkDef& def)
    {
        const prometheus::Labels labels {
            {"config", def.config.toStdString()},
            {"client", def.client.toStdString()},
            {"direction", def.direction == Direction::Ros2Mqtt ? "ros2mqtt" : "mqtt2ros"},
            {"topic", def.rosTopic.toStdString()},
            {"mqtt_topic", def.mqttTopic.toStdString()}};
        const auto with = [&labels](const char* side) {
            prometheus::Labels l = labels;
            l.emplace("side", side);
            return l;
        };
        Link l;
        l.sourceMessages.counter = &messages.Add(with("source"));
        l.destinationMessages.counter = &messages.Add(with("destination"));
        l.sourceBytes.counter = &bytes.Add(with("source"));
        l.destinationBytes.counter = &bytes.Add(with("destination"));
        l.lost.counter = &lost.Add(labels);
        l.stalls.counter = &stalls.Add(labels);
        l.sourceRate = &rate.Add(with("source"));
        l.destinationRate = &rate.Add(with("destination"));
        l.state = &state.Add(labels);
        l.labels = labels;
        return l;
    }

    void remove(Link& l)
    {
        for (Total* t : {&l.sourceMessages, &l.destinationMessages})
            messages.Remove(t->counter);
        for (Total* t : {&l.sourceBytes, &l.destinationBytes})
            bytes.Remove(t->counter);
        lost.Remove(l.lost.counter);
        stalls.Remove(l.stalls.counter);
        if (l.gaps.counter)
            gaps.Remove(l.gaps.counter);
        rate.Remove(l.sourceRate);
        rate.Remove(l.destinationRate);
        state.Remove(l.state);
        if (l.latency)
            latency.Remove(l.latency);
    }
};

WatchMetrics::WatchMetrics()
    : d(std::make_unique<Private>())
{ }

WatchMetrics::~WatchMetrics() = default;

std::unique_ptr<WatchMetrics> WatchMetrics::serve(const QString& hostPort, QString* error)
{
    std::unique_ptr<WatchMetrics> m(new WatchMetrics);
    try {
        // One thread answers scrapes: they are rare, and serialising 1,000 links is quick.
        m->d->exposer = std::make_unique<prometheus::Exposer>(hostPort.toStdString(), 1);
    } catch (const std::exception& e) {
        if (error)
            *error = tr("cannot serve metrics on %1: %2").arg(hostPort, QString::fromLocal8Bit(e.what()));
        return nullptr;
    }
    m->d->exposer->RegisterCollectable(m->d->registry);
    return m;
}

int WatchMetrics::port() const
{
    const std::vector<int> ports = d->exposer->GetListeningPorts();
    return ports.empty() ? 0 : ports.front();
}

void WatchMetrics::update(LinkMonitor& monitor)
{
    QSet<QString> alive;
    for (int i = 0; i < monitor.linkCount(); ++i) {
        const LinkDef& def = monitor.link(i);
        const QString id = def.id();
        alive.insert(id);
        auto it = d->links.find(id);
        if (it == d->links.end())
            it = d->links.insert(id, d->add(def));
        Private::Link& l = *it;
        const LinkFigures f = monitor.figures(i);
        l.sourceMessages.set(double(f.source.messages));
        l.destinationMessages.set(double(f.destination.messages));
        l.sourceBytes.set(double(f.source.bytes));
        l.destinationBytes.set(double(f.destination.bytes));
        l.lost.set(double(f.lost));
        l.stalls.set(double(f.stalls));
        if (f.seqGaps > 0 && !l.gaps.counter)
            l.gaps.counter = &d->gaps.Add(l.labels);
        if (l.gaps.counter)
            l.gaps.set(double(f.seqGaps));
        l.sourceRate->Set(f.source.rateHz);
        l.destinationRate->Set(f.destination.rateHz);
        l.state->Set(double(int(monitor.level(i))));
        const std::vector<double> latencies = monitor.takeNewLatencies(i);
        if (!latencies.empty() && !l.latency)
            l.latency = &d->latency.Add(l.labels, latencyBuckets());
        for (double ms : latencies)
            l.latency->Observe(ms / 1000.0);
    }
    for (auto it = d->links.begin(); it != d->links.end();) {
        if (alive.contains(it.key())) {
            ++it;
            continue;
        }
        d->remove(*it);
        it = d->links.erase(it);
    }
    for (const QString& name : monitor.bridges()) {
        const LinkMonitor::BridgeState s = monitor.bridgeState(name);
        Gauge*& g = d->bridges[name];
        if (s == LinkMonitor::BridgeState::Unknown) {
            if (g)
                d->bridgeUp.Remove(g);
            g = nullptr;
            continue;
        }
        if (!g)
            g = &d->bridgeUp.Add({{"bridge", name.toStdString()}});
        g->Set(s == LinkMonitor::BridgeState::Up ? 1 : 0);
    }
}
