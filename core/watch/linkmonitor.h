// SPDX-License-Identifier: MIT
#pragma once

#include "watch/bridgeliveness.h"
#include "watch/eventjournal.h"
#include "watch/linkbridges.h"
#include "watch/linkdef.h"
#include "watch/linkjudge.h"
#include "watch/linkreader.h"
#include "watch/linkrulebook.h"
#include "watch/linktrack.h"
#include "watch/watchersight.h"
#include "watch/watchrules.h"
#include "wire/sourcemessage.h"

#include <deque>
#include <memory>
#include <optional>
#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QStringList>
#include <queue>
#include <tuple>
#include <vector>

struct MqttMessage;

/// Watches links: counts what arrives at both ends, checks the rules, and turns every change
/// of a link's or a bridge's state into an event.
///
/// It holds the links (LinkTrack) and the parts that do the work: the reader that routes messages to
/// them (LinkReader), each link's traffic (LinkTraffic: rates, loss, Header.seq, latency percentiles), the
/// judge (LinkJudge: rules to a level and reasons), each bridge's liveness (BridgeLiveness) and the events
/// (EventJournal).
///
/// Pure logic on the owner's thread: messages are handed in batches (from the MQTT connection's
/// drain and the ROS monitor's arrivals), time is passed in, so tests drive it with any clock.
/// Work per message is a hash lookup and a few counters; the statistics (percentiles, loss) are
/// computed in tick(), once a second.
class LinkMonitor : public QObject
{
    Q_OBJECT
public:
    explicit LinkMonitor(QObject* parent = nullptr);
    ~LinkMonitor() override;

    /// Replaces the links (figures of links that stay are kept); `nowNs` starts the new ones.
    void setLinks(const QList<LinkDef>& links, qint64 nowNs);
    void setRules(const WatchRules& rules);
    /// The rules, and how many times a link's rules were looked up: once per link that came or
    /// changed in setLinks(), and once per link in setRules(). The bounded work.
    const LinkRuleBook& ruleBook() const { return m_ruleBook; }

    int linkCount() const;
    /// Moves whenever the links are set (their indexes may have changed).
    quint64 linksVersion() const { return m_linksVersion; }
    /// Moves whenever a figure, level or sight of a link may have changed: messages read, links set,
    /// statistics refreshed for a link that has heard something, events, blindness. A reader of every
    /// link's figures (the metrics) skips a fleet of idle links while it stands still.
    quint64 activity() const { return m_linksVersion + m_reader.read() + m_changes; }
    /// The links whose figures, level or sight may have moved since the last call (each once): heard
    /// something, refreshed or judged. For the one reader of every link's figures (the metrics),
    /// which takes every link again when linksVersion() moves.
    std::vector<int> takeMoved() { return m_reader.takeMoved(); }
    /// How many times a link was judged: the bounded idle work (a silent fleet is not judged).
    quint64 judgements() const { return m_judgements; }
    const LinkDef& link(int index) const;
    int indexOf(const QString& id) const;
    LinkFigures figures(int index) const;
    LinkLevel level(int index) const;
    QStringList reasons(int index) const;
    /// "unknown (broker unreachable)" while the watcher cannot see a side of the link (empty: it can).
    QString unknown(int index) const;

    /// Whether the watcher sees a graph: its own broker connection, the ROS master, the ROS 2
    /// domain. A link with a side on an unseen graph is unknown: not stalled, nothing lost.
    WatcherSight& sight() { return m_sight; }
    /// The links' ROS topics watched on the ROS 2 domain (the others are watched through the master).
    void setRos2Topics(const QSet<QString>& topics);
    /// Destination rate and latency p99, one point a second, oldest first (at most 10 minutes).
    using HistoryPoint = LinkHistoryPoint;
    /// How many points a link's history keeps (default kHistoryPoints; 0: none). A history costs
    /// 32 bytes a point: 19 KiB a link that heard something, 190 MiB at 10,000 links, which a
    /// `watch` that draws no chart does not keep.
    void setHistoryPoints(std::size_t points);
    static constexpr std::size_t kHistoryPoints = 600;
    std::vector<HistoryPoint> history(int index) const;
    /// Latency samples (ms) since the last call, for histograms (at most 10,000 are kept), kept
    /// only once setKeepLatencies() asked for them (the metrics do; a window does not).
    std::vector<double> takeNewLatencies(int index);
    void setKeepLatencies(bool keep);
    /// Whether the links keep their matched messages for takeNewObserved() (off: none is kept).
    void setKeepObserved(bool keep);
    /// The observed hop latencies (time, latency, both ns) matched since the last call, appended to
    /// `out`; returns how many were dropped past the bound (10,000 a link) meanwhile.
    quint64 takeNewObserved(int index, std::vector<std::pair<qint64, qint64>>& out);
    /// Bridges by name: up, down, or unknown (no traffic to judge by).
    using BridgeState = ::BridgeState;
    const LinkBridges& bridges() const { return m_bridges; }
    /// The events: those open now, and the last 1,000 that ended (oldest first).
    const EventJournal& events() const { return m_journal; }

    /// mqtt_client's control messages, which only MQTT has: type announcements and last wills
    /// (the rest of the batch is ignored).
    void addMqttControl(const std::vector<MqttMessage>& batch);
    /// What reads the links' messages (and latency topics, pipeline samples) into their traffic.
    LinkReader& reader() { return m_reader; }
    const LinkReader& reader() const { return m_reader; }
    /// Every MQTT topic an mqtt_client announced a type for, at most kMaxAnnounced.
    static constexpr int kMaxAnnounced = AnnouncedTypes::kMax;
    /// Checks the rules at `nowNs` (call a few times a second); statistics are refreshed once a
    /// second. Emits eventStarted/eventEnded for every change.
    void tick(qint64 nowNs);
    /// Ends every open event at `nowNs` (the watch stops).
    void closeAll(qint64 nowNs);

signals:
    void eventStarted(const WatchEvent& event);
    void eventEnded(const WatchEvent& event);
    /// After tick() refreshed the statistics.
    void refreshed();

private:
    using Track = LinkTrack;
    void index();
    void evaluate(int i, qint64 nowNs);
    void evaluateBridge(const QString& name, BridgeLiveness& bridge, qint64 nowNs);
    void change(const QString& subject, const LinkDef* link, LinkLevel level, const QStringList& reasons,
                const QString& detail, const LinkFigures& figures, qint64 nowNs, qint64 endNs = 0);
    /// Refreshes the statistics of links that heard something within their windows; the others
    /// get their history point only. Returns the links refreshed (their figures may have moved).
    std::vector<int> refreshStatistics(qint64 nowNs);
    /// Judges the links whose verdict may have changed: all after a change of links, rules or
    /// sight; else those that heard something, were refreshed or whose deadline passed.
    void judgeChanged(const std::vector<int>& refreshed, qint64 nowNs);
    /// When link `i` is to be judged next without a message (0: not).
    void schedule(int i, qint64 atNs);
    /// Whether the links' sight needs a pass over them (the blind graphs, links or ROS 2 topics moved).
    bool sightMoved();

    LinkRuleBook m_ruleBook;
    std::vector<std::unique_ptr<Track>> m_tracks;
    LinkReader m_reader {m_tracks};
    QHash<QString, int> m_byId;
    LinkBridges m_bridges;
    EventJournal m_journal;
    qint64 m_lastRefreshNs = 0;
    WatcherSight m_sight;
    quint64 m_linksVersion = 0;
    quint64 m_changes = 0; ///< refreshes of hearing links, level and sight changes
    quint64 m_judgements = 0;
    std::size_t m_historyPoints = kHistoryPoints;
    bool m_keepObserved = false;
    bool m_keepLatencies = false;
    /// (time, link): when a silence may change a link's verdict, earliest first; one live entry a
    /// link (LinkTrack::queuedNs), older ones are dropped when they come up.
    std::priority_queue<std::pair<qint64, int>, std::vector<std::pair<qint64, int>>, std::greater<>>
        m_deadlines;
    bool m_judgeAll = true; ///< links, rules or sight changed: every link is judged at the next tick
    quint64 m_ros2Version = 0; ///< moves with setRos2Topics()
    std::optional<std::tuple<unsigned, quint64, quint64>> m_sightKey; ///< what update() last saw
};
