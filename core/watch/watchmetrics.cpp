// SPDX-License-Identifier: MIT
#include "watchmetrics.h"

#include "models/mqtttopictree.h"
#include "watch/linkmonitor.h"
#include "watch/metricsserver.h"

#include <algorithm>
#include <QHash>
#include <QSet>

using namespace Qt::StringLiterals;

struct WatchMetrics::Private
{
    std::unique_ptr<MetricsServer> server;
    /// Each link's series by link id, kept between updates: counters never go back, and the
    /// histogram grows by the samples taken since the last update.
    QHash<QString, MetricsSnapshot::Link> links;

    static QByteArray labelsOf(const LinkDef& def)
    {
        using MetricsExposition::label;
        return label("config", def.config.toUtf8()) + ',' + label("client", def.client.toUtf8()) + ','
            + label("direction", def.direction == Direction::Ros2Mqtt ? "ros2mqtt" : "mqtt2ros") + ','
            + label("topic", def.rosTopic.toUtf8()) + ',' + label("mqtt_topic", def.mqttTopic.toUtf8());
    }
};

WatchMetrics::WatchMetrics()
    : d(std::make_unique<Private>())
{ }

WatchMetrics::~WatchMetrics() = default;

Status WatchMetrics::checkAddress(const QString& hostPort)
{
    if (const Result<MetricsServer::Endpoint> endpoint = MetricsServer::parseHostPort(hostPort); !endpoint)
        return endpoint.error();
    return {};
}

Result<std::unique_ptr<WatchMetrics>> WatchMetrics::serve(const QString& hostPort)
{
    Result<std::unique_ptr<MetricsServer>> server = MetricsServer::listen(hostPort);
    if (!server)
        return server.error();
    std::unique_ptr<WatchMetrics> m(new WatchMetrics);
    m->d->server = std::move(server).value();
    m->d->server->publish(std::make_shared<MetricsSnapshot>());
    return m;
}

int WatchMetrics::port() const
{
    return d->server->port();
}

quint64 WatchMetrics::droppedClients() const
{
    return d->server->dropped();
}

void WatchMetrics::update(LinkMonitor& monitor, const MqttTopicTree* topics, int unwatchedLinks)
{
    auto snapshot = std::make_shared<MetricsSnapshot>();
    if (topics) {
        snapshot->historyEvicted = topics->topicData().store().evictedPayloads();
        snapshot->historyBytes = topics->topicData().store().historyBytes();
        snapshot->untrackedTopicMessages = topics->topicData().store().untrackedMessages();
    }
    snapshot->unwatchedLinks = unwatchedLinks;
    snapshot->droppedAnnouncements = monitor.reader().announcedTypes().dropped();
    snapshot->links.reserve(std::size_t(monitor.linkCount()));
    QSet<QString> alive;
    alive.reserve(monitor.linkCount());
    const auto counter = [](double& series, quint64 total) { series = std::max(series, double(total)); };
    for (int i = 0; i < monitor.linkCount(); ++i) {
        const LinkDef& def = monitor.link(i);
        const QString id = def.id();
        alive.insert(id);
        auto it = d->links.find(id);
        if (it == d->links.end()) {
            it = d->links.insert(id, {});
            it->labels = Private::labelsOf(def);
        }
        MetricsSnapshot::Link& l = *it;
        const LinkFigures f = monitor.figures(i);
        counter(l.sourceMessages, f.source.messages);
        counter(l.destinationMessages, f.destination.messages);
        counter(l.sourceBytes, f.source.bytes);
        counter(l.destinationBytes, f.destination.bytes);
        counter(l.lost, f.lost);
        counter(l.stalls, f.stalls);
        counter(l.seqGaps, f.seqGaps);
        l.hasSeqGaps = l.hasSeqGaps || f.seqGaps > 0;
        l.sourceRate = f.source.rateHz;
        l.destinationRate = f.destination.rateHz;
        l.state = int(monitor.level(i));
        l.seen = monitor.unknown(i).isEmpty();
        for (double ms : monitor.takeNewLatencies(i)) {
            const double s = ms / 1000.0;
            const auto& bounds = MetricsSnapshot::kLatencyBounds;
            const auto b = std::lower_bound(bounds.cbegin(), bounds.cend(), s); // le: s <= bound
            if (b != bounds.cend())
                ++l.buckets[std::size_t(b - bounds.cbegin())];
            ++l.latencyCount;
            l.latencySum += s;
            l.hasLatency = true;
        }
        snapshot->links.push_back(l);
    }
    if (alive.size() != d->links.size())
        for (auto it = d->links.begin(); it != d->links.end();)
            it = alive.contains(it.key()) ? std::next(it) : d->links.erase(it);
    for (const QString& name : monitor.bridges().names()) {
        const LinkMonitor::BridgeState s = monitor.bridges().state(name);
        if (s != LinkMonitor::BridgeState::Unknown)
            snapshot->bridges.push_back(
                {MetricsExposition::label("bridge", name.toUtf8()), s == LinkMonitor::BridgeState::Up});
    }
    d->server->publish(std::move(snapshot));
}
