// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "latency/rundata.h"
#include "watch/watchrules.h"

#include <deque>
#include <memory>
#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QStringList>
#include <vector>

struct MqttMessage;
struct SourceHead;

/// One bridged link: a mapping of a bridge config, from its source to its destination.
struct LinkDef
{
    QString config; ///< the config's name (its file's base name)
    QString client; ///< the bridge's MQTT client id (empty when the config sets none)
    Direction direction = Direction::Ros2Mqtt;
    QString rosTopic;
    QString mqttTopic;
    bool stamped = false; ///< ROS → MQTT with inject_timestamp: payloads carry the send time
    QString willTopic; ///< the bridge's last will, when its config sets one
    QByteArray willMessage;
    /// Found on the broker (an mqtt_client type announcement), not in a config: only its MQTT end is
    /// known (`rosTopic` is empty), and it belongs to no bridge.
    bool discovered = false;
    /// The mapping's `timestamp_topic_prefix` (the benchmarking suite's mqtt_client stamps every
    /// message at PREFIX/in and PREFIX/out): with a pipeline holding both, the link's latency.
    QString stampPrefix;

    /// "config|ros2mqtt|/ros/topic|mqtt/topic": stable across runs, unique within a watch.
    QString id() const;
    QString bridge() const; ///< what names the bridge: the client id, else the config
    LinkKey key() const { return {rosTopic, mqttTopic, client, config}; }
    QString sourceTopic() const { return direction == Direction::Ros2Mqtt ? rosTopic : mqttTopic; }
    QString destinationTopic() const { return direction == Direction::Ros2Mqtt ? mqttTopic : rosTopic; }
    /// One link per mapping of `config` (mappings without both topics are skipped).
    static QList<LinkDef> fromConfig(const BridgeConfig& config, const QString& name);
    /// The link an mqtt_client announces by publishing `mqtt_client/ros_msg_type/<mqttTopic>`: some
    /// bridge sends a ROS topic there. Named "discovered|ros2mqtt||<mqttTopic>".
    static LinkDef discoveredAt(const QString& mqttTopic, bool stamped);
    static QString discoveredConfig() { return QStringLiteral("discovered"); }
};

/// What an mqtt_client type announcement said, as far as watching needs it.
struct AnnouncedType
{
    QString type; ///< e.g. "geometry_msgs/PointStamped"
    bool stamped = false; ///< the payloads carry the send time
    bool header = false; ///< the message starts with a std_msgs/Header (ROS 1: its seq comes first)
    bool ros2 = false; ///< sent by mqtt_client for ROS 2 (CDR, a 12-byte stamp)
};

enum class LinkLevel { Ok, Warning, Alert };

/// What one end of a link saw.
struct SideFigures
{
    quint64 messages = 0;
    quint64 bytes = 0;
    double rateHz = 0; ///< over the last few seconds
    double bytesPerSecond = 0;
    qint64 lastNs = 0; ///< 0: nothing yet
};

/// A link's figures at one moment.
/// Where a link's latency comes from; the first that delivers wins over the ones before it.
enum class LatencySource { None, Stamps, LatencyTopic, Pipeline };

struct LinkFigures
{
    SideFigures source;
    SideFigures destination;
    quint64 lost = 0; ///< messages the source sent that the destination never got (never decreases)
    double lossPercent = 0; ///< over the last 10 s
    quint64 seqGaps = 0; ///< Header.seq values skipped at the destination
    quint64 duplicates = 0;
    quint64 reordered = 0;
    quint64 latencySamples = 0;
    double latencyP50Ms = qQNaN(); ///< over the last 60 s (NaN: no stamps)
    double latencyP99Ms = qQNaN();
    LatencySource latencySource = LatencySource::None;
    quint64 stalls = 0; ///< stall events so far
    QJsonObject toJson() const;
    static QString latencySourceName(LatencySource source); ///< as in the JSON: "stamps", ...
};

/// A state change of a link or a bridge: open while `endNs` is 0.
struct WatchEvent
{
    QString subject; ///< a link id, or "bridge:NAME"
    QString config;
    QString client;
    QString direction; ///< "ros2mqtt", "mqtt2ros", or empty for a bridge
    QString rosTopic;
    QString mqttTopic;
    LinkLevel level = LinkLevel::Ok;
    QStringList reasons; ///< "stall", "source_stopped", "loss", "rate", "latency", "bridge_down", ...
    QString detail; ///< a sentence for people
    qint64 startNs = 0;
    qint64 endNs = 0;
    LinkFigures atStart;
    LinkFigures atEnd;

    /// Seconds from start to end (0 while open, or when the end is not after the start), computed
    /// without overflow whatever the two times are (a run file's or a peer's).
    double durationSeconds() const
    {
        return endNs > 0 && endNs > startNs ? double((static_cast<long double>(endNs) - startNs) / 1e9L) : 0;
    }
    /// One JSON line's object: {"event": "start"|"end", ...}.
    QJsonObject toJson() const;
    /// As a run file keeps it: the JSON line with the figures at start and (when ended) at end.
    RecordedEvent toRecorded() const;
    static QString levelName(LinkLevel level);
};

/// Watches links: counts what arrives at both ends, checks the rules, and turns every change
/// of a link's or a bridge's state into an event.
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
    const WatchRules& rules() const { return m_rules; }

    int linkCount() const;
    const LinkDef& link(int index) const;
    int indexOf(const QString& id) const;
    LinkFigures figures(int index) const;
    LinkLevel level(int index) const;
    QStringList reasons(int index) const;
    /// Destination rate and latency p99, one point a second, oldest first (at most 10 minutes).
    struct HistoryPoint
    {
        qint64 ns = 0;
        double rateHz = 0;
        double p99Ms = qQNaN();
        LinkLevel level = LinkLevel::Ok;
    };
    std::vector<HistoryPoint> history(int index) const;
    /// Latency samples (ms) since the last call, for histograms (at most 10,000 are kept).
    std::vector<double> takeNewLatencies(int index);
    /// Bridges by name: up, down, or unknown (no traffic to judge by).
    enum class BridgeState { Unknown, Up, Down };
    BridgeState bridgeState(const QString& bridge) const;
    QStringList bridges() const;
    /// Events that are open now, and the last 1,000 that ended (oldest first).
    QList<WatchEvent> openEvents() const;
    QList<WatchEvent> endedEvents() const;

    /// Every MQTT topic an mqtt_client announced a type for (retained or not), at most
    /// kMaxAnnounced; `droppedAnnouncements()` counts the topics beyond.
    static constexpr int kMaxAnnounced = 10'000;
    const QHash<QString, AnnouncedType>& announced() const { return m_announced; }
    quint64 droppedAnnouncements() const { return m_droppedAnnouncements; }

    /// ROS topics to subscribe: the links' own and the bridges' latency topics found in `rosTopics`
    /// (mqtt_client publishes `~/latencies/<ros topic>` for stamped MQTT → ROS links).
    QStringList rosTopicsToMonitor(const QStringList& rosTopics) const;
    /// The definition of a ROS topic's type (for Header.seq), from the ROS monitor; a ROS 2 topic's
    /// type without one (ROS 2 has no seq; a `std_msgs/msg/Float64` latency topic is found by it).
    void setRosDefinition(const QString& topic, const QString& type, const QString& definition);

    /// The measurement's pipeline (its stamp topics in order): links whose PREFIX/in and PREFIX/out
    /// are in it take their latency from its samples, and from nothing else once one arrived.
    void setPipeline(const QStringList& stampTopics);
    /// One complete sample of that pipeline (stamp times in its order), received at `nowNs`.
    void addPipelineSample(const std::vector<qint64>& times, qint64 nowNs);

    /// The links' MQTT topics: what the watch monitors on the MQTT source.
    QStringList mqttTopics() const;
    /// Messages of the links' topics, from their MessageSources (MQTT, ROS 1, ROS 2): the first
    /// bytes of each are enough for a stamp, a Header.seq and a Float64 latency.
    void add(const std::vector<SourceHead>& batch);
    /// mqtt_client's control messages, which only MQTT has: type announcements and last wills
    /// (the rest of the batch is ignored).
    void addMqttControl(const std::vector<MqttMessage>& batch);
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
    struct Track;
    struct Bridge;
    void index();
    void evaluate(int i, qint64 nowNs);
    void evaluateBridge(const QString& name, Bridge& bridge, qint64 nowNs);
    void change(const QString& subject, const LinkDef* link, LinkLevel level, const QStringList& reasons,
                const QString& detail, const LinkFigures& figures, qint64 nowNs);
    void refreshStatistics(qint64 nowNs);
    void announce(const QString& dataTopic, const QByteArray& payload);
    void addMqttHead(const SourceHead& head);
    void addRosHead(const SourceHead& head);
    void indexPipeline();
    static void applyAnnouncement(Track& track, const AnnouncedType& type);

    WatchRules m_rules;
    std::vector<std::unique_ptr<Track>> m_tracks;
    QHash<QString, QList<int>> m_byMqtt;
    QHash<QString, QList<int>> m_byRos;
    QHash<QString, int> m_byLatencyTopic; ///< ROS latency topic -> link
    QHash<QString, int> m_byId;
    QHash<QString, std::shared_ptr<Bridge>> m_bridges;
    QHash<QString, QList<QString>> m_willTopics; ///< will topic -> bridges
    QStringList m_pipeline; ///< stamp topics
    std::vector<int> m_pipelineLinks; ///< tracks that have both stamps in it
    QHash<QString, AnnouncedType> m_announced; ///< by data topic
    QHash<QString, std::size_t> m_announcementHash; ///< by data topic: the last payload's, decoded once
    quint64 m_droppedAnnouncements = 0;
    QHash<QString, WatchEvent> m_open; ///< by subject
    std::deque<WatchEvent> m_ended;
    qint64 m_lastRefreshNs = 0;
};
