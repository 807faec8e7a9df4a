// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "session/livesources.h"
#include "watch/linkmonitor.h"

#include <functional>
#include <memory>
#include <optional>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <vector>

class MqttConnection;
class RosGraphPoller;
class RosMonitor;
class Ros2Participant;

class MeasureSession;

/// Watching links live: feeds a LinkMonitor from a LiveSession's MessageSources (the arrivals of
/// the MQTT source, the ROS monitor and the ROS 2 participant while it is in a domain; mqtt_client's
/// control messages from the MQTT batches), keeps what they monitor in step with the links and the
/// graphs (a link's ROS topic is watched on whichever graph has it), and ticks the monitor four
/// times a second. Broker and master restarts are the
/// live session's business (it reconnects and registers again); the links simply resume. While the
/// watch's own connection cannot see a graph (the broker connection down, the master or the ROS 2
/// domain unreachable) the links with a side there are unknown, not stalled, and lose nothing.
///
/// It watches the configs it is given and nothing else: a window gives only those the user turned
/// watching on for, within a link limit (setLinkLimit()); planOf() says beforehand what one would
/// subscribe to.
class WatchSession : public QObject
{
    Q_OBJECT
public:
    /// What the watch reads: the sources (with their drain and MQTT batches) and the two graphs.
    struct Parts
    {
        LiveSources sources;
        const RosGraphPoller* rosGraph = nullptr; ///< the ROS 1 master's graph
        const Ros2Participant* ros2 = nullptr; ///< the ROS 2 domain's graph, while it is joined
        const RosMonitor* rosMonitor = nullptr; ///< the ROS 1 types and definitions
        const MqttConnection* mqtt = nullptr; ///< the watch's own broker connection (null: always seen)
    };
    /// A config to watch: its name (its file's base name), its file (empty: not saved) and content.
    struct Config
    {
        QString name;
        QString file;
        BridgeConfig config;
    };
    /// What watching a config subscribes to: its links and their topics on each graph.
    struct Plan
    {
        int links = 0;
        QStringList rosTopics; ///< through the ROS 1 master
        QStringList ros2Topics; ///< on the ROS 2 domain (those published there now)
        QStringList mqttTopics;
    };
    /// The links a window watches at most (see docs/ROBUSTNESS.md): each is a subscription on the
    /// broker and one at the master or the ROS 2 domain, which the lab's master and broker carry.
    static constexpr int kWindowLinkLimit = 2'000;
    explicit WatchSession(const Parts& parts, QObject* parent = nullptr);
    ~WatchSession() override;

    LinkMonitor* monitor() const { return m_monitor; }
    /// Watches the links of these configs (name, config), replacing what was watched.
    void setConfigs(const QList<std::pair<QString, BridgeConfig>>& configs);
    /// Watches the links of these configs, replacing what was watched; beyond the link limit nothing
    /// changes and the error says so (the count and the limit).
    Status setConfigs(const QList<Config>& configs);
    /// The links watched at most (0: no limit, the default; a window sets kWindowLinkLimit).
    void setLinkLimit(int links) { m_linkLimit = links; }
    int linkLimit() const { return m_linkLimit; }
    /// What watching `config` would subscribe to, on the graphs as they are now.
    Plan planOf(const Config& config) const;
    /// Whether the links mqtt_client announces on the broker (its type topics) that no config has
    /// are watched too, from their MQTT end (on by default).
    void setDiscovering(bool discovering);
    bool isDiscovering() const { return m_discovering; }
    /// The discovered links watched at most: a broker's clients may announce any number. Those
    /// watched stay watched while announced; newer ones past it are not watched, counted by
    /// unwatchedLinks().
    static constexpr int kMaxDiscoveredLinks = 5'000;
    /// Announced links not watched to keep within kMaxDiscoveredLinks (as of the last discovery).
    int unwatchedLinks() const { return m_unwatched; }
    /// Messages of watched topics that came and went untimed (more between two reads than the
    /// watch keeps, here or in the DDS child).
    quint64 droppedHeads() const;
    void setRules(const WatchRules& rules) { m_monitor->setRules(rules); }
    /// Works with the measurement of `measure`: every event goes into its run file while it
    /// records (the events open when the recording starts, then each start and end; an event still
    /// open at its stop stays open there), and links whose stamps are in its pipeline take their
    /// latency from its samples. Takes its sample listener.
    void useMeasurement(MeasureSession* measure);
    /// Hands each link's observed hop latencies (issue 45: its two ends matched by content) to
    /// `sink` after every drain that matched any, as single-stage series named
    /// SeriesId::observedName(): at most kMaxObservedSeries links get a series (the first to match);
    /// `leftOut.links` counts the links that matched beyond them, whose figures are on the Links
    /// page only; `leftOut.dropped` the values dropped so far past a link's bound between two drains
    /// (10,000). An empty sink stops it. useMeasurement() sets the measurement's.
    struct ObservedLeftOut
    {
        int links = 0;
        quint64 dropped = 0;
    };
    using ObservedSink
        = std::function<void(std::vector<LatencyValue>&& values, ObservedLeftOut leftOut, qint64 nowNs)>;
    static constexpr int kMaxObservedSeries = 32;
    void setObservedSink(ObservedSink sink);
    /// Runs the ROS and tick work now (tests; the live session's drain does it otherwise).
    void update(qint64 nowNs);

private:
    void syncRosTopics();
    void syncMqttTopics();
    void applyLinks();
    /// Adds the links announced since the last call that no config has; true when there were any.
    bool discoverLinks();

    bool ros2Running() const;
    /// The ROS 2 domain's topics that have publishers (empty when it is not joined).
    QSet<QString> ros2Published() const;
    void updateSight();
    void handOverObserved(qint64 nowNs);
    /// The observed series of link `d` (empty: past kMaxObservedSeries, counted).
    QString observedSeries(const LinkDef& d);

    Parts m_parts; ///< the sources may go first (siblings in a window die in the order they were made)
    LinkMonitor* m_monitor;
    std::vector<std::unique_ptr<HeadTap>> m_heads; ///< one per graph
    qint64 m_lastTickNs = 0;
    qint64 m_lastSyncNs = 0;
    /// RosMonitor::typesLearned() when the reader last took the ROS 1 types (-1: take them again).
    qint64 m_rosTypesSeen = -1;
    /// Hands the reader the ROS 1 types learned since the last call.
    void takeRosTypes(qint64 nowNs);
    Subscriptions m_monitored; ///< ROS 1 topics subscribed
    Subscriptions m_monitored2; ///< ROS 2 topics subscribed
    Subscriptions m_monitoredMqtt;
    QList<LinkDef> m_configLinks;
    QSet<QString> m_configMqttTopics;
    QStringList m_discovered; ///< MQTT topics of the discovered links, sorted
    int m_unwatched = 0;
    int m_linkLimit = 0;
    bool m_discovering = true;
    ObservedSink m_observedSink;
    QHash<QString, QString> m_observedSeries; ///< link id → its series' name
    /// Link index → its series' name (empty: left out; none: not looked up yet) for the links as
    /// of linksVersion m_observedAtVersion: the id is not built at every drain.
    std::vector<std::optional<QString>> m_observedAt;
    quint64 m_observedAtVersion = 0;
    QSet<QString> m_observedNames;
    QSet<QString> m_observedLeftOut; ///< ids of the links that matched past kMaxObservedSeries
    quint64 m_observedDropped = 0;
    quint64 m_observedDroppedSaid = 0; ///< as handed to the sink last
};
