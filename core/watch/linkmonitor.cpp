// SPDX-License-Identifier: MIT
#include "linkmonitor.h"

#include "mqtt/mqttconnection.h"
#include "wire/mqttclientwire.h"

#include <algorithm>
#include <limits>
#include <map>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = LinkWindows::kSecond;
constexpr std::size_t kHistoryPoints = 600;
} // namespace

LinkMonitor::LinkMonitor(QObject* parent)
    : QObject(parent)
{ }

LinkMonitor::~LinkMonitor() = default;

void LinkMonitor::setLinks(const QList<LinkDef>& links, qint64 nowNs)
{
    std::map<QString, std::unique_ptr<Track>> old;
    for (auto& t : m_tracks)
        old[t->def.id()] = std::move(t);
    m_tracks.clear();
    QSet<QString> seen;
    for (const LinkDef& def : links) {
        const QString id = def.id();
        if (seen.contains(id))
            continue; // the same mapping twice in one config: one link
        seen.insert(id);
        auto it = old.find(id);
        std::unique_ptr<Track> t;
        bool sameKey = false;
        if (it != old.end() && it->second) {
            t = std::move(it->second);
            const LinkKey was = t->def.key(), is = def.key();
            sameKey = was.rosTopic == is.rosTopic && was.mqttTopic == is.mqttTopic && was.client == is.client
                && was.config == is.config;
        } else {
            t = std::make_unique<Track>();
            t->startNs = nowNs;
        }
        t->def = def;
        if (!sameKey) // the rules of a link that stays are kept: setRules() sets them anew
            t->rules = m_ruleBook.forLink(def);
        m_tracks.push_back(std::move(t));
    }
    index();
}

void LinkMonitor::setRules(const WatchRules& rules)
{
    m_ruleBook.set(rules);
    for (auto& t : m_tracks)
        t->rules = m_ruleBook.forLink(t->def);
}

void LinkMonitor::index()
{
    ++m_linksVersion;
    m_byId.clear();
    for (int i = 0; i < int(m_tracks.size()); ++i)
        m_byId.insert(m_tracks[std::size_t(i)]->def.id(), i);
    m_bridges.index(m_tracks);
    m_reader.index();
}

int LinkMonitor::linkCount() const
{
    return int(m_tracks.size());
}

const LinkDef& LinkMonitor::link(int index) const
{
    return m_tracks.at(std::size_t(index))->def;
}

int LinkMonitor::indexOf(const QString& id) const
{
    return m_byId.value(id, -1);
}

LinkFigures LinkMonitor::figures(int index) const
{
    const Track& t = *m_tracks.at(std::size_t(index));
    LinkFigures f = t.liveFigures();
    f.stalls = t.stalls;
    return f;
}

LinkLevel LinkMonitor::level(int index) const
{
    return m_tracks.at(std::size_t(index))->level;
}

QStringList LinkMonitor::reasons(int index) const
{
    return LinkJudge::reasonNames(m_tracks.at(std::size_t(index))->reasons);
}

QString LinkMonitor::unknown(int index) const
{
    return m_tracks.at(std::size_t(index))->unknown;
}

void LinkMonitor::setRos2Topics(const QSet<QString>& topics)
{
    for (auto& t : m_tracks)
        t->onRos2 = topics.contains(t->def.rosTopic);
}

std::vector<LinkMonitor::HistoryPoint> LinkMonitor::history(int index) const
{
    const auto& h = m_tracks.at(std::size_t(index))->history;
    return {h.begin(), h.end()};
}

std::vector<double> LinkMonitor::takeNewLatencies(int index)
{
    std::vector<double> out;
    out.swap(m_tracks.at(std::size_t(index))->newLatencies);
    return out;
}

void LinkMonitor::addMqttControl(const std::vector<MqttMessage>& batch)
{
    const QString typePrefix = MqttClientWire::typeTopicPrefix();
    for (const MqttMessage& m : batch) {
        if (m.topic.startsWith(typePrefix)) {
            m_reader.announce(MqttClientWire::dataTopicOf(m.topic), m.payload);
            continue;
        }
        m_bridges.noteWill(m, m_tracks);
    }
}

void LinkMonitor::refreshStatistics(qint64 nowNs)
{
    for (auto& tp : m_tracks) {
        Track& t = *tp;
        if (t.dormant())
            continue; // nothing to refresh, and no history yet: a fleet's idle links cost nothing
        ++m_changes;
        t.refresh(nowNs);
        t.history.push_back({nowNs, t.dst.f.rateHz, t.figures.latencyP99Ms, t.level});
        if (t.history.size() > kHistoryPoints)
            t.history.pop_front();
    }
}

void LinkMonitor::tick(qint64 nowNs)
{
    m_changes += quint64(m_sight.update(m_tracks, nowNs));
    const bool refresh = nowNs - m_lastRefreshNs >= kSecond;
    if (refresh) {
        m_lastRefreshNs = nowNs;
        refreshStatistics(nowNs);
    }
    // Only links whose verdict can change: a dormant link judged dormant with the same sight is
    // judged the same (idle work does not grow with a fleet's silent links).
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const Track& t = *m_tracks[std::size_t(i)];
        if (!(t.judgedDormant && t.dormant() && t.judgedBlindness == t.blindness))
            evaluate(i, nowNs);
    }
    for (auto it = m_bridges.all().begin(); it != m_bridges.all().end(); ++it)
        evaluateBridge(it.key(), **it, nowNs);
    if (refresh)
        emit refreshed();
}

void LinkMonitor::evaluate(int i, qint64 nowNs)
{
    Track& t = *m_tracks[std::size_t(i)];
    ++m_judgements;
    t.judgedDormant = t.dormant();
    t.judgedBlindness = t.blindness;
    LinkJudge::Input in;
    in.figures = figures(i);
    in.periodNs = t.src.expectedPeriodNs();
    // Silences count from when the watcher saw again, at the latest: what it did not see is not silence.
    in.sourceSilenceNs = t.src.f.lastNs > 0 ? nowNs - std::max(t.src.f.lastNs, t.sightNs) : -1;
    // Silence at the destination counts from its last message, or from when the source (re)started.
    // After an outage of its own sight the watch subscribes again, and the bridge (on the same broker)
    // reconnects as well: the destination's silence counts from a margin later.
    const qint64 seenFrom = t.sightNs > 0 ? t.sightNs + LinkWindows::kSightMarginNs : 0;
    in.destinationSilenceNs = nowNs - std::max({t.dst.f.lastNs, t.startNs, t.src.resumedNs, seenFrom});
    // Right after a stall, a start or a restart of either end (or of the watcher's sight) the windows still
    // hold the outage, which has its own event: loss and rates are judged again once the windows are past
    // it. Both ends must have been heard over the whole window (they subscribe at different moments).
    in.settled = nowNs - std::max({t.stallEndedNs, t.src.resumedNs, t.dst.resumedNs, seenFrom})
        > LinkWindows::kLossWindowNs + LinkWindows::kLossLagNs + kSecond;
    in.blindness = t.blindness;
    in.stallLevel = t.stalled ? t.stallLevel : LinkLevel::Ok;
    in.destinationSteadyNs = nowNs - t.silentNs;
    const LinkJudge::Verdict v = LinkJudge::judge(t.rules, t.def, in);
    t.unknown = v.unknown ? v.detail : QString();
    if (v.silent)
        t.silentNs = nowNs;
    const bool stalled = v.reasons.contains(LinkReason::Stall);
    if (stalled && !t.stalled)
        ++t.stalls;
    // A stall ended with the destination's first message after its last silence (its recovery since
    // only confirms it).
    qint64 stallEnd = 0;
    if (!stalled && t.stalled && !v.unknown) {
        stallEnd = t.silentNs;
        for (auto it = t.dst.arrivals.crbegin(); it != t.dst.arrivals.crend() && it->first > t.silentNs; ++it)
            stallEnd = it->first;
    }
    if (!stalled && t.stalled)
        t.stallEndedNs = nowNs;
    t.stalled = stalled;
    if (stalled)
        t.stallLevel = std::max(t.stallLevel, v.level);
    else
        t.stallLevel = LinkLevel::Ok;
    t.reasons = v.reasons;
    if (v.level == t.level) {
        // Same level, same event: it gathers every reason it had.
        m_journal.gather(t.def.id(), LinkJudge::reasonNames(v.reasons));
        return;
    }
    t.level = v.level;
    change(t.def.id(), &t.def, v.level, LinkJudge::reasonNames(v.reasons), v.detail, figures(i), nowNs,
           stallEnd);
}

void LinkMonitor::evaluateBridge(const QString& name, BridgeLiveness& b, qint64 nowNs)
{
    BridgeLiveness::Input in;
    in.nowNs = nowNs;
    in.blind = !m_sight.sees(SourceGraph::Mqtt);
    for (int i : std::as_const(b.links)) {
        const Track& t = *m_tracks[std::size_t(i)];
        in.lastDataNs = std::max(in.lastDataNs, t.dst.f.lastNs);
        const qint64 limit = std::max<qint64>(5 * t.src.expectedPeriodNs(), kSecond);
        in.carries = in.carries || (t.dst.f.lastNs > 0 && nowNs - t.dst.f.lastNs <= limit);
        in.stalled = in.stalled || t.reasons.contains(LinkReason::Stall);
    }
    if (!b.update(in))
        return;
    const bool down = b.state == BridgeState::Down;
    LinkDef bridge;
    if (!b.links.isEmpty())
        bridge = m_tracks[std::size_t(b.links.first())]->def;
    change(u"bridge:"_s + name, &bridge, down ? LinkLevel::Alert : LinkLevel::Ok,
           down ? QStringList {LinkJudge::reasonName(LinkReason::BridgeDown)} : QStringList(), b.detail(name),
           LinkFigures(), nowNs);
}

void LinkMonitor::change(const QString& subject, const LinkDef* link, LinkLevel level,
                         const QStringList& reasons, const QString& detail, const LinkFigures& figures,
                         qint64 nowNs, qint64 endNs)
{
    ++m_changes;
    if (const auto ended = m_journal.end(subject, endNs > 0 ? endNs : nowNs, figures))
        emit eventEnded(*ended);
    if (level == LinkLevel::Ok)
        return;
    WatchEvent e;
    e.subject = subject;
    e.config = link->config;
    e.configFile = link->configFile;
    e.client = link->client;
    if (!subject.startsWith(u"bridge:"_s)) {
        e.direction = directionName(link->direction);
        e.rosTopic = link->rosTopic;
        e.mqttTopic = link->mqttTopic;
    }
    e.level = level;
    e.reasons = reasons;
    e.detail = detail;
    e.startNs = nowNs;
    e.atStart = figures;
    m_journal.open(e);
    emit eventStarted(e);
}

void LinkMonitor::closeAll(qint64 nowNs)
{
    const QStringList subjects = m_journal.openSubjects();
    for (const QString& s : subjects) {
        const int i = m_byId.value(s, -1);
        change(s, nullptr, LinkLevel::Ok, {}, QString(), i >= 0 ? figures(i) : LinkFigures(), nowNs);
    }
}
