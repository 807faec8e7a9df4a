// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QByteArray>
#include <QString>

/// Proposes new mappings for topics a user drags or selects: names on the other side and the
/// options that what discovery knows calls for.
class MappingFactory
{
public:
    /// What discovery knows about an MQTT topic.
    struct MqttFacts
    {
        bool seen = false; ///< messages arrived on it
        QString announcedType; ///< mqtt_client's type announcement, if any
        QByteArray lastPayload;
    };

    /// "/lidar/points" under "vehicle" -> "vehicle/lidar/points" (leading '/' dropped).
    static QString mqttTopicFor(const QString& rosTopic, const QString& prefix);
    /// "vehicle/lidar points" under "/cloud" -> "/cloud/vehicle/lidar_points" (a valid ROS name).
    static QString rosTopicFor(const QString& mqttTopic, const QString& ns);

    /// A ros2mqtt mapping for a ROS topic of `rosType`, sent to `mqttTopic`.
    static Mapping ros2mqtt(const QString& rosTopic, const QString& rosType, const QString& mqttTopic,
                            const MqttFacts& destination, ConfigLayout layout);
    /// An mqtt2ros mapping for an MQTT topic, published on `rosTopic`.
    static Mapping mqtt2ros(const QString& mqttTopic, const MqttFacts& source, const QString& rosTopic,
                            ConfigLayout layout);

    /// std_msgs/String, Bool, Int32, ...: what mqtt_client can send as plain text.
    static bool isPrimitiveType(const QString& rosType);
    /// "std_msgs/Bool" <-> "std_msgs/msg/Bool" as the layout wants it.
    static QString typeForLayout(const QString& rosType, ConfigLayout layout);
    /// The std_msgs type a plain-text payload looks like ("42" -> Int64), or empty if not plain.
    static QString primitiveTypeOf(const QByteArray& payload);
};
