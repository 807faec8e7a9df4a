// SPDX-License-Identifier: MIT
#include "linkmonitor.h"

#include "mqtt/mqttconnection.h"
#include "wire/mqttclientwire.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = LinkWindows::kSecond;
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
        t->keepObserved = m_keepObserved;
        t->keepLatencies = m_keepLatencies;
        if (!sameKey) // the rules of a link that stays are kept: setRules() sets them anew
            t->rules = m_ruleBook.forLink(def);
        m_tracks.push_back(std::move(t));
    }
    index();
}

void LinkMonitor::setHistoryPoints(std::size_t points)
{
    m_historyPoints = points;
    for (auto& t : m_tracks)
        while (t->history.size() > points)
            t->history.pop_front();
}

void LinkMonitor::setRules(const WatchRules& rules)
{
    m_ruleBook.set(rules);
    for (auto& t : m_tracks)
        t->rules = m_ruleBook.forLink(t->def);
    m_judgeAll = true;
}

void LinkMonitor::index()
{
    ++m_linksVersion;
    m_judgeAll = true;
    m_deadlines = {}; // their indexes are gone
    for (auto& t : m_tracks)
        t->queuedNs = 0;
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
    ++m_ros2Version;
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

void LinkMonitor::setKeepLatencies(bool keep)
{
    if (keep == m_keepLatencies)
        return;
    m_keepLatencies = keep;
    for (auto& t : m_tracks) {
        t->keepLatencies = keep;
        if (!keep)
            t->newLatencies = {};
    }
}

void LinkMonitor::setKeepObserved(bool keep)
{
    m_keepObserved = keep;
    for (auto& t : m_tracks) {
        t->keepObserved = keep;
        if (!keep)
            t->newObserved = {};
    }
}

quint64 LinkMonitor::takeNewObserved(int index, std::vector<std::pair<qint64, qint64>>& out)
{
    Track& t = *m_tracks.at(std::size_t(index));
    out.insert(out.end(), t.newObserved.cbegin(), t.newObserved.cend());
    t.newObserved.clear();
    return std::exchange(t.newObservedDropped, 0);
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

std::vector<int> LinkMonitor::refreshStatistics(qint64 nowNs)
{
    std::vector<int> refreshed;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        Track& t = *m_tracks[std::size_t(i)];
        if (t.dormant())
            continue; // nothing to refresh, and no history yet: a fleet's idle links cost nothing
        if (!t.still(nowNs)) { // past every window a refresh gives the same figures: only the point
            ++m_changes;
            t.refresh(nowNs);
            refreshed.push_back(i);
            m_reader.moved(i);
        }
        if (m_historyPoints == 0)
            continue;
        t.history.push_back({nowNs, t.dst.f.rateHz, t.figures.latencyP99Ms, t.level});
        if (t.history.size() > m_historyPoints)
            t.history.pop_front();
    }
    return refreshed;
}

bool LinkMonitor::sightMoved()
{
    const auto key = std::make_tuple(m_sight.blindMask(), m_linksVersion, m_ros2Version);
    if (m_sightKey == key)
        return false;
    m_sightKey = key;
    return true;
}

void LinkMonitor::tick(qint64 nowNs)
{
    if (sightMoved()) {
        const int changed = m_sight.update(m_tracks, nowNs);
        m_changes += quint64(changed);
        m_judgeAll = m_judgeAll || changed > 0;
    }
    const bool refresh = nowNs - m_lastRefreshNs >= kSecond;
    std::vector<int> moved; // the links whose figures were refreshed
    if (refresh) {
        m_lastRefreshNs = nowNs;
        moved = refreshStatistics(nowNs);
    }
    judgeChanged(moved, nowNs);
    if (refresh) // the sources' periods moved: what the bridges' links show, counted anew
        m_bridges.recount(m_tracks);
    for (auto it = m_bridges.all().begin(); it != m_bridges.all().end(); ++it)
        evaluateBridge(it.key(), **it, nowNs);
    if (refresh)
        emit refreshed();
}

void LinkMonitor::judgeChanged(const std::vector<int>& refreshed, qint64 nowNs)
{
    const std::vector<int> heard = m_reader.takeHeard();
    if (m_judgeAll) {
        m_judgeAll = false;
        // A dormant link judged dormant with the same sight is judged the same (idle work does not
        // grow with a fleet's silent links).
        for (int i = 0; i < int(m_tracks.size()); ++i) {
            const Track& t = *m_tracks[std::size_t(i)];
            if (!(t.judgedDormant && t.dormant() && t.judgedBlindness == t.blindness))
                evaluate(i, nowNs);
        }
        return;
    }
    const auto judge = [&](int i) {
        if (m_tracks[std::size_t(i)]->judgedNs != nowNs)
            evaluate(i, nowNs);
    };
    for (int i : heard)
        judge(i);
    for (int i : refreshed)
        judge(i);
    while (!m_deadlines.empty() && m_deadlines.top().first <= nowNs) {
        const auto [at, i] = m_deadlines.top();
        m_deadlines.pop();
        Track& t = *m_tracks[std::size_t(i)];
        if (t.queuedNs != at)
            continue; // an entry its link left for an earlier one
        t.queuedNs = 0;
        if (t.judgeAtNs > nowNs)
            schedule(i, t.judgeAtNs); // its deadline moved on since
        else if (t.judgeAtNs > 0)
            judge(i);
    }
}

void LinkMonitor::schedule(int i, qint64 atNs)
{
    Track& t = *m_tracks[std::size_t(i)];
    t.judgeAtNs = atNs;
    if (atNs <= 0 || (t.queuedNs > 0 && t.queuedNs <= atNs))
        return; // none, or its entry comes first and looks at judgeAtNs then
    t.queuedNs = atNs;
    m_deadlines.emplace(atNs, i);
}

void LinkMonitor::evaluate(int i, qint64 nowNs)
{
    Track& t = *m_tracks[std::size_t(i)];
    ++m_judgements;
    m_reader.moved(i); // its level, reasons, stalls or sight may change
    t.judgedNs = nowNs;
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
    const qint64 settledAt = std::max({t.stallEndedNs, t.src.resumedNs, t.dst.resumedNs, seenFrom})
        + LinkWindows::kLossWindowNs + LinkWindows::kLossLagNs + kSecond;
    in.settled = nowNs > settledAt;
    in.settlesInNs = in.settled ? 0 : settledAt - nowNs + 1;
    in.blindness = t.blindness;
    in.stallLevel = t.stalled ? t.stallLevel : LinkLevel::Ok;
    in.destinationSteadyNs = nowNs - t.silentNs;
    const LinkJudge::Verdict v = LinkJudge::judge(t.rules, t.def, in);
    if (!t.dormant()) // a dormant link is judged again at its first message or a change of sight
        if (const qint64 quiet = LinkJudge::quietNs(t.rules, in))
            schedule(i, nowNs + quiet);
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
    if (t.bridge) {
        t.bridge->stalledLinks += int(stalled) - int(t.stalled);
        t.bridge->lastDataNs = std::max(t.bridge->lastDataNs, t.dst.f.lastNs);
        t.bridge->carriesUntilNs = std::max(t.bridge->carriesUntilNs, LinkBridges::carriesUntilNs(t));
    }
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
    // What its links showed when they were last judged: a link judged at this tick if it heard.
    in.lastDataNs = b.lastDataNs;
    in.carries = b.carriesUntilNs > 0 && nowNs <= b.carriesUntilNs;
    in.stalled = b.stalledLinks > 0;
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
