// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "config/bridgeconfig.h"
#include "mqtt/mqttlink.h"
#include "mqtt/mqttprofile.h"

#include <optional>
#include <QByteArray>
#include <QHash>
#include <QString>
#include <vector>

/// One mapping as a reference bridge runs it: its values with `$(arg NAME)` substituted and
/// mqtt_client's defaults where the config says nothing.
struct BridgeRoute
{
    Direction direction = Direction::Ros2Mqtt;
    QString rosTopic;
    QString mqttTopic;
    bool primitive = false;
    bool stamped = false; ///< ros2mqtt: inject_timestamp
    bool json = false; ///< ROS 2
    QString rosType; ///< ROS 2: the fixed type (ros_type), or empty
    int qos = 0;
    bool retained = false;
    bool latched = false;
    int queueSize = 1;
    /// ROS 2: advanced.ros.qos as written ("reliable", "transient_local", ...; empty or "auto":
    /// from the publisher, for ros2mqtt).
    QString reliability;
    QString durability;
    QString stampPrefix; ///< timestamp_topic_prefix
};

/// What an mqtt_client config (any layout) asks of a reference bridge, whatever ROS it runs on:
/// the broker (overridden by a --broker URL), the client's last will and the mappings. Shared by
/// ReferenceBridge (ROS 1) and Ros2Bridge (ROS 2).
struct BridgeSpec
{
    BridgeConfig config;
    MqttProfile profile;
    MqttWill will;
    std::vector<BridgeRoute> routes;

    /// The config read; an error when it is not a bridge config, has no mapping, uses an
    /// `$(arg NAME)` not in `args`, or a value is out of range.
    static Result<BridgeSpec> load(const QByteArray& yaml, const QString& brokerUrl,
                                   const QHash<QString, QString>& args);
};
