// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqtttopicstore.h"
#include "wire/mqttclientwire.h"

#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QHash>

class RosTypeRegistry;

/// What mqtt_client announces of the broker's topics, and whether their payloads agree with it.
///
/// A type announcement (ROS 1 with its definition, ROS 2 naming its type only) gives its data topic
/// a type; a ROS 2 type decodes with the ROS 2 definitions the checks are given (setRos2Registry()).
/// A stamped topic's payloads give the one-way latency; payloads that do not split or do not decode
/// (the newest of each topic in a batch, within a small budget) are counted as malformed on their
/// topic. The findings go on the topics' MqttTopicNode.
class MqttPayloadChecks
{
    Q_DECLARE_TR_FUNCTIONS(MqttTopicTree)
public:
    struct Type
    {
        RosMsgTypeInfo info;
        std::shared_ptr<const RosTypeRegistry> registry; ///< ROS 1: from the announced definition
        QString error;
    };

    /// A type announcement for `dataTopic` that came on `typeNode`: true when the data topic's type
    /// changed; a malformed one is counted on `typeNode`.
    bool absorbAnnouncement(const QString& dataTopic, const QByteArray& payload, MqttTopicNode* typeNode);
    /// The type announced for a data topic, or null.
    std::shared_ptr<const Type> typeOf(const QString& topic) const { return m_types.value(topic); }
    /// The one-way latencies a topic's mean is taken over.
    static constexpr std::size_t kLatencyWindow = 100;
    /// A message on a data topic of that type: its latency when the type is stamped (or the payload
    /// counted as malformed when it does not split).
    void stamp(const Type& type, const MqttMessage& msg, MqttTopicNode* n);
    /// Whether the topic's newest payload decodes with its announced type; counted when not.
    void checkNewest(MqttTopicNode* n);

    std::shared_ptr<const RosTypeRegistry> registryOf(const Type& type) const;
    /// Why payloads of the type show raw (a ROS 2 type without a definition), or empty.
    QString typeNoteOf(const Type& type) const;
    void setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry) { m_ros2Registry = std::move(registry); }
    /// Data topics of announced ROS 2 types, whose rows change with the ROS 2 registry.
    QStringList ros2Topics() const;
    int unknownTypeTopics() const;
    quint64 malformedTypeAnnouncements() const { return m_malformedTypes; }
    quint64 malformedPayloads() const { return m_malformedPayloads; }
    void clear();

private:
    QHash<QString, std::shared_ptr<Type>> m_types; ///< by data topic
    mutable std::shared_ptr<const RosTypeRegistry> m_ros2Registry; ///< set on first use when not given
    quint64 m_malformedTypes = 0;
    quint64 m_malformedPayloads = 0;
};
