// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "latency/rundata.h"
#include "watch/watchrules.h"

#include <QJsonObject>
#include <QStringList>

/// One bridged link: a mapping of a bridge config, from its source to its destination.
struct LinkDef
{
    QString config; ///< the config's name (its file's base name)
    QString configFile; ///< the config's file (empty: not known, or not saved yet)
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
    /// mqtt_client sends the ROS message's value as text (`primitive`): matched by that text.
    bool primitive = false;
    /// mqtt_client (v2.5) sends the message's fields as JSON (`json`, not `primitive`): matched by
    /// the CDR that JSON makes as `rosType` (the mapping's `ros_type`), as the bridge converts it.
    bool json = false;
    QString rosType;
    /// mqtt_client carries the ROS serialization as it is (no `primitive`, no `json`): the two ends'
    /// contents can be matched without stamps (issue 45).
    bool rawPayload() const { return !primitive && !json; }

    /// "config|ros2mqtt|/ros/topic|mqtt/topic": stable across runs, unique within a watch.
    QString id() const;
    QString bridge() const; ///< what names the bridge: the client id, else the config
    /// "SOURCE → DESTINATION" (topics in the direction of the data), or the one topic known of a
    /// discovered link: its name in a bridge, as the metrics' `link` label has it.
    QString name() const;
    LinkKey key() const { return {rosTopic, mqttTopic, client, config}; }
    QString sourceTopic() const { return direction == Direction::Ros2Mqtt ? rosTopic : mqttTopic; }
    QString destinationTopic() const { return direction == Direction::Ros2Mqtt ? mqttTopic : rosTopic; }
    /// One link per mapping of `config` (mappings without both topics are skipped).
    static QList<LinkDef> fromConfig(const BridgeConfig& config, const QString& name,
                                     const QString& file = QString());
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
    /// Observed hop latency (issue 45): each message Bridgescope saw go in matched by its content
    /// with the copy it saw come out, on its one clock; over the last 60 s (NaN: none matched).
    quint64 observedSamples = 0;
    double observedP50Ms = qQNaN();
    double observedP99Ms = qQNaN();
    quint64 observedLost = 0; ///< went in and never came out (within the matcher's wait)
    quint64 observedAmbiguous = 0; ///< identical contents in flight at once: no latency
    quint64 observedUnexplained = 0; ///< came out with nothing seen going in
    quint64 observedOverflow = 0; ///< dropped unjudged past the matcher's bound
    /// A `json` link's MQTT payloads that did not convert to its ros_type: not matched.
    quint64 observedUnconverted = 0;
    quint64 stalls = 0; ///< stall events so far
    QJsonObject toJson() const;
    static QString latencySourceName(LatencySource source); ///< as in the JSON: "stamps", ...
};

/// A state change of a link or a bridge: open while `endNs` is 0.
struct WatchEvent
{
    QString subject; ///< a link id, or "bridge:NAME"
    QString config;
    QString configFile; ///< where the event came from: the watched config's file (may be empty)
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
    /// A time as events write it: ISO 8601, UTC, milliseconds.
    static QString isoTime(qint64 ns);
};

/// "ros2mqtt" or "mqtt2ros", as events and the JSON name a direction.
QString directionName(Direction direction);
