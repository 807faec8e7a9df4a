// SPDX-License-Identifier: MIT
#pragma once

#include "latency/headhub.h"
#include "latency/messagesource.h"
#include "latency/taphub.h"
#include "mqtt/mqttconnection.h"

#include <memory>
#include <optional>
#include <QHash>
#include <vector>

class MqttTopics;
class RosTypeRegistry;

/// The broker's topics as a MessageSource, for the views that take any graph (field plots, Watch,
/// Map health): what RosMonitor is to ROS 1 and Ros2Participant to ROS 2.
///
/// The connection's discovery subscription already takes every topic, so monitoring subscribes to
/// nothing: it marks the topics whose figures (figures()) and message heads (openHeadTap()) a user
/// wants. The live session hands it each drain's batch (add()) on the GUI thread, where every call
/// runs; work per message is a hash lookup, and what it keeps is bounded by the callers' limits.
/// Figures are the topic tree's (rates, the last stamped payload's latency); the type of an arrival
/// is the ROS type mqtt_client announced for its topic, empty without an announcement.
class MqttSource : public MessageSource
{
public:
    explicit MqttSource(const MqttTopics* topics);
    ~MqttSource() override;

    /// One drain's messages, oldest first.
    void add(const std::vector<MqttMessage>& batch);

    SourceGraph sourceGraph() const override { return SourceGraph::Mqtt; }
    void monitor(const QString& topic) override;
    void unmonitor(const QString& topic) override;
    bool isMonitored(const QString& topic) const override;
    QHash<QString, TopicFigures> figures(qint64 nowNs) const override;
    std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads) override;
    /// Subscribes to nothing (the connection takes every topic); arrivals carry the type
    /// mqtt_client announced for the topic.
    std::unique_ptr<Tap> openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override;

    /// The ROS 2 definitions a JSON payload is converted with (the live session's).
    void setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry)
    {
        m_ros2Types = std::move(registry);
    }
    /// The monitored topics that `json` links read, with their ROS 2 types (replacing those set
    /// before): their heads carry the key of the CDR each payload converts to (SourceHead::jsonKey),
    /// at most Ros2BridgeWire::kMaxJsonBytes of it parsed.
    void setJsonTypes(const QHash<QString, QString>& types) { m_jsonTypes = types; }
    /// Payloads of those topics that did not convert (not JSON, not the type, too large).
    quint64 jsonUnconverted() const { return m_jsonUnconverted; }
    /// The most JSON converted in one drain's batch; past it payloads are not converted (counted
    /// in jsonOverBudget(); their links count them as not converted).
    static constexpr qint64 kMaxJsonBytesPerBatch = 4 * 1024 * 1024;
    quint64 jsonOverBudget() const { return m_jsonOverBudget; }

private:
    /// The key of the CDR a JSON payload of `type` converts to, none when it does not.
    std::optional<ContentKey> jsonKey(const QString& type, const QByteArray& payload);

    std::shared_ptr<const RosTypeRegistry> m_ros2Types;
    QHash<QString, QString> m_jsonTypes;
    quint64 m_jsonUnconverted = 0;
    quint64 m_jsonOverBudget = 0;
    const MqttTopics* m_topics;
    QHash<QString, int> m_monitored; ///< topic → monitor() calls not yet balanced
    HeadHub m_heads;
    TapHub m_taps;
};
