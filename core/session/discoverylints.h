// SPDX-License-Identifier: MIT
#pragma once

#include "config/mqttclientrelease.h"
#include "config/problem.h"
#include "session/mappinghealthevaluator.h"

#include <optional>
#include <QCoreApplication>

/// The traps of mqtt_client's issue tracker that only the running lab shows: what discovery sees
/// on the ROS graph and on the broker, checked against a config. Each problem names the
/// mqtt_client issue it comes from and says how to fix it. They are warnings: a file is not invalid
/// because of what is running today, and the list changes with the lab.
///
/// - `non-ros-publisher` (mqtt_client #12, #78): an mqtt2ros mapping without `primitive` (or, from
///   2.5, `json`) whose MQTT topic carries messages mqtt_client did not announce: the bridge never
///   publishes them on ROS.
/// - `ros-type-changes` (#15, #45): the ROS topic of a mapping without `ros_type` is published with
///   more than one type, so the type the bridge takes depends on who came first; or `ros_type`
///   names a type nobody publishes.
/// - `qos-incompatible` (#48): ROS 2, the QoS the bridge would use cannot match the topic's
///   publishers (ros2mqtt) or subscribers (mqtt2ros).
/// - `fastdds-discovery-server` (#67): ROS_DISCOVERY_SERVER is set, and a bridge that is a plain
///   discovery client sees only the topics of its own host.
class DiscoveryLints
{
    Q_DECLARE_TR_FUNCTIONS(DiscoveryLints)
public:
    struct Options
    {
        std::optional<MqttClientRelease> target; ///< none: the newest the layout loads
        /// The ROS_DISCOVERY_SERVER the lab uses (this process's environment), or empty.
        QString discoveryServer;
    };
    /// Problems of `config` against what `in` sees (the same inputs as the mappings' health).
    static QList<Problem> check(const BridgeConfig& config, const MappingHealthEvaluator::Inputs& in,
                                const Options& options);
};
