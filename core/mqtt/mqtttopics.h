// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"
#include "mqtt/mqttpayloadchecks.h"
#include "mqtt/mqtttopicstore.h"

#include <deque>
#include <memory>
#include <optional>
#include <QList>
#include <QStringList>
#include <vector>

class RosTypeRegistry;

/// The broker's topics as they are kept, without a Qt model: the topic store (MqttTopicStore:
/// levels, figures, history, budgets) and the payload checks (MqttPayloadChecks: announced types,
/// latencies, payloads that do not decode) fed batch by batch, and what is known of one topic.
/// MqttTopicTree (core/models) shows it as rows; the broker's MessageSource (MqttSource), the watch's
/// metrics and the discover command read it.
class MqttTopics
{
public:
    using Node = MqttTopicNode;
    using HistoryEntry = MqttTopicNode::HistoryEntry;

    /// What is known about one topic (for the detail pane and the discover command).
    struct TopicInfo
    {
        QString topic;
        quint64 messages = 0; ///< on this topic itself
        quint64 bytes = 0;
        quint64 retainedMessages = 0;
        int lastSize = 0;
        bool retained = false; ///< the last message was retained
        int qos = 0;
        qint64 lastNs = 0;
        double rate = 0;
        std::optional<RosMsgTypeInfo> rosType;
        QString typeError; ///< a type announcement that could not be decoded
        QString typeNote; ///< why payloads of the announced type show raw (a ROS 2 type not known)
        quint64 malformedPayloads = 0; ///< did not decode (also over a decode budget), per topic
        QString payloadError; ///< why the last malformed payload did not decode
        double lastLatencyMs = 0;
        double meanLatencyMs = 0;
        quint64 latencySamples = 0;
        QList<double> rateHistory; ///< one value per second, oldest first
    };

    /// What one batch made: the levels with new levels below them (in their `pending`, not yet
    /// rows), and whether a $SYS statistic changed.
    struct Applied
    {
        std::vector<Node*> withPending;
        bool statisticsChanged = false;
    };

    /// Counts, keeps and checks one drain's messages, oldest first; the levels whose figures changed
    /// go to `dirty` (once each, see MqttTopicNode::markDirty()).
    Applied apply(std::vector<MqttMessage>&& batch, std::vector<Node*>& dirty);
    /// Updates every level's rate and rate history once a second (`nowNs` is wall-clock time):
    /// true when it did.
    bool updateRates(qint64 nowNs);
    void clear();
    /// The ROS 2 definitions announced ROS 2 types decode with; until set, the bundled ones
    /// (Ros2Definitions::registry(), built once and shared).
    void setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry);

    std::optional<TopicInfo> info(const QString& topic) const;
    QList<TopicInfo> topics() const; ///< every topic, by name
    /// The type mqtt_client announced for a data topic, whether or not a message came on it yet.
    std::optional<RosMsgTypeInfo> announcedType(const QString& topic) const;
    const std::deque<HistoryEntry>* history(const QString& topic) const;
    /// A registry able to decode the topic's payloads, when mqtt_client announced its type (for
    /// ROS 2, the ROS 2 registry when it knows the type; else none, and TopicInfo::typeNote says so).
    std::shared_ptr<const RosTypeRegistry> registryFor(const QString& topic) const;
    /// The topics at or below a level that may hold a retained message
    /// (MqttTopicStore::mayHoldRetained()).
    QStringList retainedBelow(const QString& path, int limit = 100000) const;

    MqttTopicStore& store() { return m_store; }
    const MqttTopicStore& store() const { return m_store; }
    const MqttPayloadChecks& checks() const { return m_checks; }

private:
    MqttTopicStore m_store;
    MqttPayloadChecks m_checks;
    qint64 m_lastTickNs = 0;
};
