// SPDX-License-Identifier: MIT
#include "watchmetrics.h"

#include "models/mqtttopictree.h"
#include "watch/linkmonitor.h"
#include "watch/metricsserver.h"

#include <algorithm>
#include <cmath>
#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <QSysInfo>

using namespace Qt::StringLiterals;

struct WatchMetrics::Private
{
    std::unique_ptr<MetricsServer> server;
    /// Each link's series in the monitor's order (and its id), kept between updates and shared with
    /// the snapshot published last: counters never go back, and the histogram grows by the samples
    /// taken since the last update. An update makes anew only the links that moved
    /// (LinkMonitor::takeMoved()); all of them only when the monitor's links change
    /// (LinkMonitor::linksVersion()).
    MetricsSnapshot::Links links;
    std::vector<QString> ids;
    quint64 linksVersion = ~quint64(0);
    quint64 activity = ~quint64(0); ///< LinkMonitor::activity() at the last update
    std::shared_ptr<const MetricsSnapshot> published;
    /// The label sets in use: two links whose bridge, topics and direction agree (the same link in two
    /// configs) would be one series twice, and Prometheus refuses a whole scrape for that.
    QSet<QByteArray> labelSets;
    QByteArray ownLabels; ///< `host="…",…`

    QByteArray labelsOf(const LinkDef& def)
    {
        using MetricsExposition::label;
        QByteArray labels = ownLabels + ',' + label("bridge", def.bridge().toUtf8()) + ','
            + label("link", def.name().toUtf8()) + ','
            + label("direction", directionName(def.direction).toUtf8());
        if (labelSets.contains(labels))
            labels += ',' + label("config", def.config.toUtf8());
        labelSets.insert(labels);
        return labels;
    }

    /// Takes the monitor's links: the series of links that stay are kept, new ones start at zero.
    void follow(const LinkMonitor& monitor)
    {
        std::vector<QString> now;
        now.reserve(std::size_t(monitor.linkCount()));
        QSet<QString> staying;
        for (int i = 0; i < monitor.linkCount(); ++i) {
            now.push_back(monitor.link(i).id());
            staying.insert(now.back());
        }
        QHash<QString, MetricsSnapshot::Links::Item> old;
        old.reserve(qsizetype(ids.size()));
        for (std::size_t i = 0; i < ids.size(); ++i) {
            if (staying.contains(ids[i]))
                old.insert(ids[i], std::move(links.items()[i]));
            else
                labelSets.remove(links[i].labels); // free before the new links take theirs
        }
        links.clear();
        links.reserve(now.size());
        for (int i = 0; i < monitor.linkCount(); ++i) {
            const LinkDef& def = monitor.link(i);
            const QString& id = now[std::size_t(i)];
            if (auto it = old.find(id); it != old.end()) {
                links.items().push_back(std::move(*it));
                old.erase(it);
            } else {
                MetricsSnapshot::Link l;
                l.labels = labelsOf(def);
                l.stage = stageOf(def);
                // A link that can have latency serves its histogram at zero from the start: a series
                // whose first scrape already counts has no rate() over those counts.
                l.hasLatency = def.stamped || !def.stampPrefix.isEmpty();
                links.push_back(std::move(l));
            }
        }
        ids = std::move(now);
        linksVersion = monitor.linksVersion();
    }

    /// Brings the series up to date with the links that moved (every link when the links changed).
    /// Whether a series changed.
    bool take(LinkMonitor& monitor)
    {
        const std::vector<int> moved = monitor.takeMoved();
        bool changed = false;
        if (linksVersion != monitor.linksVersion()) {
            follow(monitor);
            for (int i = 0; i < int(links.size()); ++i)
                refresh(monitor, i);
            return true;
        }
        for (int i : moved)
            changed = refresh(monitor, i) || changed;
        return changed;
    }

    /// Brings link `i`'s series up to date with the monitor: a new one when a figure moved, else the
    /// one the last snapshot serves. Whether it moved.
    bool refresh(LinkMonitor& monitor, int i)
    {
        MetricsSnapshot::Links::Item& item = links.items()[std::size_t(i)];
        MetricsSnapshot::Link l = *item;
        const auto counter = [](double& series, quint64 total) { series = std::max(series, double(total)); };
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
        if (f.observedSamples > 0) {
            l.hasObserved = true;
            // NaN once nothing matched for a window: a figure of the past is not served as today's
            l.observedP50 = f.observedP50Ms / 1000.0;
            l.observedP99 = f.observedP99Ms / 1000.0;
        }
        counter(l.observedLost, f.observedLost);
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
        if (l == *item)
            return false;
        item = std::make_shared<const MetricsSnapshot::Link>(std::move(l));
        return true;
    }

    static QByteArray stageOf(const LinkDef& def)
    {
        QString stage = def.stampPrefix;
        while (stage.startsWith(u'/'))
            stage.remove(0, 1);
        while (stage.endsWith(u'/'))
            stage.chop(1);
        return MetricsExposition::label("stage", stage.isEmpty() ? "bridge" : stage.toUtf8());
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

Result<WatchMetrics::Label> WatchMetrics::parseLabel(const QString& text)
{
    const qsizetype eq = text.indexOf(u'=');
    if (eq < 0)
        return LocatedError {tr("label '%1' is not NAME=VALUE").arg(text.left(80))};
    const QString name = text.left(eq);
    const QString value = text.mid(eq + 1);
    static const QRegularExpression valid(u"^[a-zA-Z_][a-zA-Z0-9_]{0,63}$"_s);
    if (!valid.match(name).hasMatch() || name.startsWith(u"__"_s))
        return LocatedError {tr("label name '%1' is not a Prometheus label name (letters, digits and _, "
                                "not starting with a digit or __, at most 64)")
                                 .arg(name.left(80))};
    static const QStringList ours {u"bridge"_s, u"link"_s, u"direction"_s, u"side"_s,
                                   u"stage"_s,  u"le"_s,   u"version"_s,   u"config"_s};
    static const QStringList scrapers {u"job"_s, u"instance"_s};
    if (ours.contains(name))
        return LocatedError {tr("label '%1' is one the watch writes itself").arg(name)};
    if (scrapers.contains(name))
        return LocatedError {
            tr("label '%1' is one Prometheus sets when it scrapes; name the host with host=").arg(name)};
    if (value.isEmpty())
        return LocatedError {tr("label '%1' has no value (Prometheus drops an empty label)").arg(name)};
    if (value.toUtf8().size() > MetricsExposition::kMaxLabelValueBytes)
        return LocatedError {
            tr("label '%1' is longer than %2 bytes").arg(name).arg(MetricsExposition::kMaxLabelValueBytes)};
    return Label {name, value};
}

Result<std::unique_ptr<WatchMetrics>> WatchMetrics::serve(const QString& hostPort, const QList<Label>& labels)
{
    if (labels.size() > kMaxOwnLabels)
        return LocatedError {tr("at most %1 labels of a watch's own").arg(kMaxOwnLabels)};
    QList<Label> own {{u"host"_s, QSysInfo::machineHostName()}};
    for (const Label& l : labels) {
        if (const Result<Label> ok = parseLabel(l.first + u'=' + l.second); !ok)
            return ok.error();
        const auto same
            = std::find_if(own.begin(), own.end(), [&](const Label& o) { return o.first == l.first; });
        if (same != own.end())
            same->second = l.second; // the last one given wins, host included
        else
            own.push_back(l);
    }
    Result<std::unique_ptr<MetricsServer>> server = MetricsServer::listen(hostPort);
    if (!server)
        return server.error();
    std::unique_ptr<WatchMetrics> m(new WatchMetrics);
    for (const Label& l : std::as_const(own))
        m->d->ownLabels += QByteArray(m->d->ownLabels.isEmpty() ? "" : ",")
            + MetricsExposition::label(l.first.toUtf8().constData(), l.second.toUtf8());
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
    monitor.setKeepLatencies(true); // the histograms' samples, from now on
    auto snapshot = std::make_shared<MetricsSnapshot>();
    if (topics) {
        snapshot->historyEvicted = topics->topicData().store().evictedPayloads();
        snapshot->historyBytes = topics->topicData().store().historyBytes();
        snapshot->untrackedTopicMessages = topics->topicData().store().untrackedMessages();
    }
    snapshot->unwatchedLinks = unwatchedLinks;
    snapshot->ownLabels = d->ownLabels;
    snapshot->version = QByteArrayLiteral(BRIDGESCOPE_VERSION);
    snapshot->droppedAnnouncements = monitor.reader().announcedTypes().dropped();
    const quint64 activity = monitor.activity();
    const bool linksMoved = d->take(monitor);
    // Nothing of any link moved (a fleet of idle links): the last snapshot stands, or lends its
    // links when only the watch's own figures are new. No figure of every link four times a second.
    if (!linksMoved && activity == d->activity && d->published) {
        const MetricsSnapshot& last = *d->published;
        if (last.historyEvicted == snapshot->historyEvicted && last.historyBytes == snapshot->historyBytes
            && last.untrackedTopicMessages == snapshot->untrackedTopicMessages
            && last.unwatchedLinks == snapshot->unwatchedLinks
            && last.droppedAnnouncements == snapshot->droppedAnnouncements)
            return;
        snapshot->links = last.links;
        snapshot->bridges = last.bridges;
        d->published = snapshot;
        d->server->publish(std::move(snapshot));
        return;
    }
    d->activity = activity;
    snapshot->links = d->links; // the links that did not move are shared with the last snapshot
    for (const QString& name : monitor.bridges().names()) {
        const LinkMonitor::BridgeState s = monitor.bridges().state(name);
        if (s != LinkMonitor::BridgeState::Unknown)
            snapshot->bridges.push_back(
                {d->ownLabels + ',' + MetricsExposition::label("bridge", name.toUtf8()),
                 s == LinkMonitor::BridgeState::Up});
    }
    d->published = snapshot;
    d->server->publish(std::move(snapshot));
}
