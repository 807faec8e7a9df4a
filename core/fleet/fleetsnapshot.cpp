// SPDX-License-Identifier: MIT
#include "fleetsnapshot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <QDateTime>
#include <tuple>
#include <vector>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecondNs = 1'000'000'000LL;
/// The window of the watch's bridgescope_link_rate_hz.
constexpr qint64 kRateWindowNs = 5 * kSecondNs;
/// The window of the increase() queries.
constexpr qint64 kRecentWindowNs = FleetSnapshotBuilder::kRateWindowSeconds * kSecondNs;

/// The labels of a link's series, found in one pass over its labels (empty when absent).
struct LinkLabels
{
    enum { Host, Bridge, Link, Direction, Side, Count };
    std::array<const QString*, Count> at {};

    explicit LinkLabels(const PrometheusAnswer::Series& s)
    {
        static const QString none;
        static const std::array<QString, Count> names {u"host"_s, u"bridge"_s, u"link"_s, u"direction"_s,
                                                       u"side"_s};
        at.fill(&none);
        for (const PrometheusAnswer::Label& l : s.labels)
            for (int i = 0; i < Count; ++i)
                if (l.first == names[i]) {
                    at[i] = &l.second;
                    break;
                }
    }
    const QString& operator[](int i) const { return *at[i]; }
    QString key() const
    {
        return (*this)[Host] + u'|' + (*this)[Bridge] + u'|' + (*this)[Link] + u'|' + (*this)[Direction];
    }
};

/// A link's four label strings by their data: the answers of a refresh are read with one label
/// pool (PrometheusClient), so the series of one link in every answer share these strings.
struct LabelData
{
    std::array<const QChar*, 4> data {};
    std::array<qsizetype, 4> size {};

    explicit LabelData(const LinkLabels& l)
    {
        for (int i = 0; i < 4; ++i) {
            data[i] = l[i].constData();
            size[i] = l[i].size();
        }
    }
    bool operator==(const LabelData& o) const { return data == o.data && size == o.size; }
};

size_t qHash(const LabelData& d, size_t seed = 0)
{
    return qHashBits(&d, sizeof d, seed);
}

/// One id for each link (host, bridge, link, direction) a refresh's answers name. A series finds
/// its id by the data of its list of labels, shared by the series of the same metric object in
/// every answer (PrometheusLabelPool), else by the data of its label strings, shared across the
/// answers: the text of its labels is only built and hashed the first time a string is met (once
/// per refresh for a link, with one pool), not for every series of every answer.
class LinkIndex
{
public:
    struct Entry
    {
        int id = -1; ///< -1: a link not met yet
        bool source = true; ///< the series is not of the destination side
    };
    /// The link the series `s` names; a new id when `add`, else -1 for a link not met yet.
    Entry of(const PrometheusAnswer::Series& s, bool add)
    {
        const void* list = s.labels.constData();
        if (const auto it = m_byList.constFind(list); it != m_byList.cend())
            return *it;
        const LinkLabels l(s);
        const Entry e {id(l, add), l[LinkLabels::Side] != "destination"_L1};
        if (e.id >= 0)
            m_byList.insert(list, e); // the lists live as long as the answers, past build()'s use
        return e;
    }
    int size() const { return int(m_byKey.size()); }

private:
    int id(const LinkLabels& l, bool add)
    {
        const LabelData data(l);
        if (const auto it = m_byData.constFind(data); it != m_byData.cend())
            return *it;
        const QString key = l.key();
        auto it = m_byKey.constFind(key);
        if (it == m_byKey.cend()) {
            if (!add)
                return -1;
            it = m_byKey.insert(key, int(m_byKey.size()));
        }
        m_byData.insert(data, *it); // the strings live as long as the answers, past build()'s use
        return *it;
    }

    QHash<const void*, Entry> m_byList;
    QHash<LabelData, int> m_byData;
    QHash<QString, int> m_byKey;
};

double valueOf(const PrometheusAnswer::Series& s)
{
    return s.points.isEmpty() ? qQNaN() : s.points.constLast().value;
}

/// A finite, non-negative count (what a hostile server sends otherwise counts as nothing).
double count(double v)
{
    return std::isfinite(v) && v > 0 ? v : 0;
}

/// The figures of every link a query names, by key and side.
struct Figures
{
    double sourceRate = 0, destinationRate = 0;
    double sourceMessages = 0, destinationMessages = 0;
    double sourceBytes = 0, destinationBytes = 0;
    double sourceRecent = 0, destinationRecent = 0;
    double lost = 0, recentLost = 0, stalls = 0;
    double p50 = qQNaN(), p99 = qQNaN();
    int state = -1;
    bool seen = true;
};

/// A quantile in ms, NaN unless a finite non-negative number.
double latencyMs(double v)
{
    return std::isfinite(v) && v >= 0 ? v : qQNaN();
}

/// A count as the figures keep it.
quint64 whole(double v)
{
    return quint64(std::min(v, 1.8e19));
}

/// The links listed in a snapshot: their ids and, for each id, its row in `links` (-1: not listed).
struct LinkTable
{
    LinkIndex index;
    QList<FleetLink> links;
    std::vector<int> rowOf;
    std::vector<Figures> figures; ///< by row

    /// The row of the link a series names, -1 when it is not listed; `source`: of its source side.
    int row(const PrometheusAnswer::Series& s, bool* source)
    {
        const LinkIndex::Entry e = index.of(s, false);
        *source = e.source;
        return e.id >= 0 && e.id < int(rowOf.size()) ? rowOf[size_t(e.id)] : -1;
    }
};

using Setter = void (*)(Figures&, bool source, double value);

void collect(const QHash<QString, PrometheusAnswer>& answers, const QString& name, LinkTable* table,
             Setter set)
{
    const auto answer = answers.constFind(name);
    if (answer == answers.cend())
        return;
    for (const PrometheusAnswer::Series& s : answer->series) {
        bool source = true;
        if (const int row = table->row(s, &source); row >= 0)
            set(table->figures[size_t(row)], source, valueOf(s));
    }
}

/// The side's silence as far as Prometheus tells: none while the watch's 5-second rate is above
/// zero, at most a period when it counted messages over the last minute, else the whole minute.
qint64 silenceNs(double rate, double recent, double total, qint64 periodNs)
{
    if (rate > 0)
        return 0;
    if (recent > 0)
        return std::min(kRateWindowNs, std::max(periodNs, kSecondNs / 2));
    return total > 0 ? kRecentWindowNs : -1;
}

LinkJudge::Verdict judge(const LinkRules& rules, const FleetLink& link, const Figures& f)
{
    LinkJudge::Input in;
    in.figures = link.figures;
    const double sourceHz
        = f.sourceRate > 0 ? f.sourceRate : f.sourceRecent / FleetSnapshotBuilder::kRateWindowSeconds;
    in.periodNs = sourceHz > 0 ? qint64(1e9 / sourceHz) : 0;
    in.sourceSilenceNs = silenceNs(f.sourceRate, f.sourceRecent, f.sourceMessages, in.periodNs);
    in.destinationSilenceNs
        = silenceNs(f.destinationRate, f.destinationRecent, f.destinationMessages, in.periodNs);
    if (in.destinationSilenceNs < 0)
        in.destinationSilenceNs = in.sourceSilenceNs >= 0 ? kRecentWindowNs : 0;
    in.settled = f.sourceRecent > 0;
    return LinkJudge::judge(rules, link.def, in);
}
/// The hosts: reporting now, seen within the hour, or seen by an earlier refresh (`hostsSeen`, updated).
QHash<QString, FleetHost> hostsOf(const QHash<QString, PrometheusAnswer>& answers, double now,
                                  QHash<QString, double>* hostsSeen)
{
    QHash<QString, FleetHost> hosts;
    for (const PrometheusAnswer::Series& s : answers.value(u"lastSeen"_s).series) {
        const QString name = s.label(u"host"_s);
        const double t = valueOf(s);
        if (!name.isEmpty())
            hosts[name] = FleetHost {name, {}, false, std::isfinite(t) ? t : 0};
    }
    for (auto it = hostsSeen->cbegin(); it != hostsSeen->cend(); ++it) {
        FleetHost& h = hosts[it.key()];
        h.name = it.key();
        h.lastSeen = std::max(h.lastSeen, it.value());
    }
    for (const PrometheusAnswer::Series& s : answers.value(u"info"_s).series) {
        const QString name = s.label(u"host"_s);
        if (name.isEmpty())
            continue;
        FleetHost& h = hosts[name];
        h.name = name;
        h.version = s.label(u"version"_s);
        h.reporting = true;
        h.lastSeen = now;
    }
    for (const FleetHost& h : std::as_const(hosts))
        hostsSeen->insert(h.name, h.lastSeen);

    return hosts;
}

/// The links: every link of a reporting host that its watch serves now; a silent host's last ones.
void linksOf(const QHash<QString, PrometheusAnswer>& answers, QHash<QString, FleetHost>& hosts, double now,
             LinkTable* table)
{
    const QList<PrometheusAnswer::Series> state = answers.value(u"state"_s).series;
    std::vector<char> current;
    for (const PrometheusAnswer::Series& s : state) {
        const size_t id = size_t(table->index.of(s, true).id);
        current.resize(std::max(current.size(), id + 1));
        current[id] = 1;
    }
    std::vector<int>& rowOf = table->rowOf;
    // `links` holds the hour's links of the hosts not reporting (all of them, from an older
    // server's answer), `state` those served now.
    const QList<PrometheusAnswer::Series> hour = answers.value(u"links"_s).series;
    for (const QList<PrometheusAnswer::Series>* named : {&hour, &state}) {
        for (const PrometheusAnswer::Series& s : *named) {
            const LinkLabels labels(s);
            const QString& host = labels[LinkLabels::Host];
            if (host.isEmpty() || labels[LinkLabels::Link].isEmpty())
                continue;
            const size_t id = size_t(table->index.of(s, true).id);
            current.resize(std::max(current.size(), id + 1));
            rowOf.resize(current.size(), -1);
            auto h = hosts.find(host);
            if (h == hosts.end()) {
                // Links of a host whose info was never seen: taken as reporting while they are served.
                h = hosts.insert(host, FleetHost {host, {}, current[id] != 0, now});
            }
            if ((h->reporting && !current[id]) || rowOf[id] >= 0)
                continue; // the watch no longer watches it, or it is listed already
            FleetLink l;
            l.host = host;
            l.bridge = labels[LinkLabels::Bridge];
            l.link = labels[LinkLabels::Link];
            l.direction = labels[LinkLabels::Direction];
            l.hostReporting = h->reporting;
            l.def = FleetSnapshotBuilder::linkDef(l.bridge, l.link, l.direction);
            rowOf[id] = int(table->links.size());
            table->links.append(std::move(l));
        }
    }
}

/// The figures of the table's links from the answers.
void figuresOf(const QHash<QString, PrometheusAnswer>& answers, LinkTable* table)
{
    table->figures.assign(size_t(table->links.size()), Figures {});
    collect(answers, u"state"_s, table,
            [](Figures& f, bool, double v) { f.state = std::isfinite(v) && v >= 0 && v <= 2 ? int(v) : -1; });
    collect(answers, u"seen"_s, table, [](Figures& f, bool, double v) { f.seen = !(v == 0); });
    collect(answers, u"rate"_s, table, [](Figures& f, bool source, double v) {
        (source ? f.sourceRate : f.destinationRate) = count(v);
    });
    collect(answers, u"messages"_s, table, [](Figures& f, bool source, double v) {
        (source ? f.sourceMessages : f.destinationMessages) = count(v);
    });
    collect(answers, u"bytes"_s, table, [](Figures& f, bool source, double v) {
        (source ? f.sourceBytes : f.destinationBytes) = count(v);
    });
    collect(answers, u"recent"_s, table, [](Figures& f, bool source, double v) {
        (source ? f.sourceRecent : f.destinationRecent) = count(v);
    });
    collect(answers, u"lost"_s, table, [](Figures& f, bool, double v) { f.lost = count(v); });
    collect(answers, u"recentLost"_s, table, [](Figures& f, bool, double v) { f.recentLost = count(v); });
    collect(answers, u"stalls"_s, table, [](Figures& f, bool, double v) { f.stalls = count(v); });
    collect(answers, u"p50"_s, table, [](Figures& f, bool, double v) { f.p50 = latencyMs(v); });
    collect(answers, u"p99"_s, table, [](Figures& f, bool, double v) { f.p99 = latencyMs(v); });
}

} // namespace

QList<std::pair<QString, QString>> FleetSnapshotBuilder::queries()
{
    // Each answer carries the labels the view reads and nothing else: the scrapers' `job` and
    // `instance` (and a watch's own --label's) are aggregated away on the server, so a series is a
    // few short labels (a refresh reads tens of thousands of them).
    const QString perLink = u"host, bridge, link, direction"_s;
    const QString perSide = perLink + u", side"_s;
    const auto by = [](const QString& op, const QString& labels, const QString& expr) {
        return u"%1 by (%2) (%3)"_s.arg(op, labels, expr);
    };
    // A link's series that says only what its absence says is not asked for: a loss or stall
    // count where it is above 0 (build() takes any other as 0, NaN too), a quantile where it is a
    // number (NaN otherwise), `seen` where it is 0 (a link is seen otherwise). A healthy fleet's
    // losses, stalls and blind links are then empty answers, and so are the quantiles of links
    // without stamps, not one series a link each. The per-side answers stay whole: both sides of
    // a working link count.
    const QString quantile = u"1000 * histogram_quantile(%1, sum by (host, bridge, link, direction, le) "
                             "(rate(bridgescope_link_latency_seconds_bucket[1m]))) >= 0"_s;
    const auto above0 = [&](const QString& labels, const QString& expr) -> QString {
        return by(u"sum"_s, labels, expr) + u" > 0"_s;
    };
    return {
        // The last hour's links only of hosts not reporting now: the others' are in `state`.
        {u"links"_s,
         by(u"max"_s, perLink, u"last_over_time(bridgescope_link_state[1h])"_s)
             + u" unless on (host) bridgescope_watch_info"_s},
        {u"state"_s, by(u"max"_s, perLink, u"bridgescope_link_state"_s)},
        {u"seen"_s, by(u"min"_s, perLink, u"bridgescope_link_seen"_s) + u" == 0"_s},
        {u"rate"_s, by(u"sum"_s, perSide, u"bridgescope_link_rate_hz"_s)},
        {u"messages"_s, by(u"sum"_s, perSide, u"bridgescope_link_messages_total"_s)},
        {u"bytes"_s, by(u"sum"_s, perSide, u"bridgescope_link_bytes_total"_s)},
        {u"lost"_s, above0(perLink, u"bridgescope_link_lost_total"_s)},
        {u"stalls"_s, above0(perLink, u"bridgescope_link_stalls_total"_s)},
        {u"recent"_s,
         by(u"sum"_s, perSide, u"increase(bridgescope_link_messages_total%1)"_s.arg(rateRange()))},
        {u"recentLost"_s, above0(perLink, u"increase(bridgescope_link_lost_total%1)"_s.arg(rateRange()))},
        {u"p50"_s, quantile.arg(u"0.5"_s)},
        {u"p99"_s, quantile.arg(u"0.99"_s)},
        {u"bridges"_s, by(u"min"_s, u"host, bridge"_s, u"bridgescope_bridge_up"_s)},
        {u"info"_s, by(u"max"_s, u"host, version"_s, u"bridgescope_watch_info"_s)},
        {u"lastSeen"_s, u"max by (host) (max_over_time(timestamp(bridgescope_watch_info)[1h:15s]))"_s},
    };
}

QString FleetSnapshotBuilder::rateRange()
{
    return u"[%1s]"_s.arg(kRateWindowSeconds);
}

LinkDef FleetSnapshotBuilder::linkDef(const QString& bridge, const QString& link, const QString& direction)
{
    LinkDef d;
    d.config = bridge;
    d.client = bridge;
    d.direction = direction == "mqtt2ros"_L1 ? Direction::Mqtt2Ros : Direction::Ros2Mqtt;
    const qsizetype arrow = link.indexOf(u" → "_s);
    if (arrow < 0) {
        d.mqttTopic = link; // a discovered link: only its MQTT topic is known
        d.discovered = true;
        return d;
    }
    const QString source = link.left(arrow);
    const QString destination = link.mid(arrow + 3);
    d.rosTopic = d.direction == Direction::Ros2Mqtt ? source : destination;
    d.mqttTopic = d.direction == Direction::Ros2Mqtt ? destination : source;
    return d;
}

QString FleetSnapshotBuilder::stoppedText(double lastSeen)
{
    if (!(lastSeen > 0))
        return tr("host stopped reporting");
    return tr("host stopped reporting since %1")
        .arg(QDateTime::fromMSecsSinceEpoch(qint64(lastSeen * 1000)).toString(u"HH:mm"_s));
}

FleetSnapshot FleetSnapshotBuilder::build(const QHash<QString, PrometheusAnswer>& answers,
                                          const WatchRules& rules, double now,
                                          QHash<QString, double>* hostsSeen)
{
    FleetSnapshot snap;
    snap.time = now;
    for (const PrometheusAnswer& a : answers) {
        snap.droppedSeries += a.droppedSeries;
        snap.badSamples += a.badSamples;
        for (const QString& w : a.warnings)
            if (!snap.warnings.contains(w))
                snap.warnings << w;
    }

    QHash<QString, FleetHost> hosts = hostsOf(answers, now, hostsSeen);
    LinkTable table;
    linksOf(answers, hosts, now, &table);
    figuresOf(answers, &table);
    QList<FleetLink>& links = table.links;
    QHash<QString, bool> bridgeDown;
    for (const PrometheusAnswer::Series& s : answers.value(u"bridges"_s).series)
        if (valueOf(s) == 0)
            bridgeDown.insert(s.label(u"host"_s) + u'|' + s.label(u"bridge"_s), true);

    for (qsizetype row = 0; row < links.size(); ++row) {
        FleetLink& l = links[row];
        const Figures& f = table.figures[size_t(row)];
        LinkFigures& lf = l.figures;
        // The mean over the chart's window (the watch's own 5-s rate is 0 for a slow link); a
        // discovered link has no source side to give a rate of.
        lf.source.rateHz = l.def.discovered ? qQNaN() : f.sourceRecent / kRateWindowSeconds;
        lf.destination.rateHz = f.destinationRecent / kRateWindowSeconds;
        lf.source.messages = whole(f.sourceMessages);
        lf.destination.messages = whole(f.destinationMessages);
        lf.source.bytes = whole(f.sourceBytes);
        lf.destination.bytes = whole(f.destinationBytes);
        lf.lost = whole(f.lost);
        lf.stalls = whole(f.stalls);
        lf.lossPercent = f.sourceRecent > 0 ? std::min(100.0, 100.0 * f.recentLost / f.sourceRecent) : 0;
        lf.latencyP50Ms = f.p50;
        lf.latencyP99Ms = f.p99;
        if (std::isfinite(f.p99))
            lf.latencySource = LatencySource::Stamps;
        l.reportedState = f.state;
        if (!l.hostReporting) {
            l.verdict.unknown = true;
            l.verdict.detail = stoppedText(hosts.value(l.host).lastSeen);
            continue;
        }
        if (!f.seen) {
            l.verdict.unknown = true;
            l.verdict.detail = tr("unknown (the watch on %1 cannot see both sides)").arg(l.host);
            continue;
        }
        l.verdict = judge(rules.forLink(l.def.key()), l, f);
        if (!bridgeDown.isEmpty() && bridgeDown.contains(l.host + u'|' + l.bridge)) {
            l.bridgeDown = true;
            l.verdict.level = LinkLevel::Alert;
            l.verdict.reasons.prepend(LinkReason::BridgeDown);
            l.verdict.detail = tr("the bridge %1 on %2 is down").arg(l.bridge, l.host);
        }
    }

    snap.links = std::move(links);
    std::sort(snap.links.begin(), snap.links.end(), [](const FleetLink& a, const FleetLink& b) {
        // The links of a host share its strings (one pool): the same data is the same text.
        for (const auto& [x, y] : {std::tie(a.host, b.host), std::tie(a.bridge, b.bridge),
                                   std::tie(a.link, b.link), std::tie(a.direction, b.direction)}) {
            if (x.constData() == y.constData() && x.size() == y.size())
                continue;
            if (const int c = x.compare(y); c != 0)
                return c < 0;
        }
        return false;
    });
    snap.hosts = hosts.values();
    std::sort(snap.hosts.begin(), snap.hosts.end(),
              [](const FleetHost& a, const FleetHost& b) { return a.name < b.name; });
    return snap;
}
