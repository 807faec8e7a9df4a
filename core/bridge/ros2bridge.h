// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "bridge/bridgehop.h"
#include "mqtt/mqttprofile.h"
#include "ros2/ros2types.h"

#include <memory>
#include <QCoreApplication>
#include <QString>

/// The ROS 2 reference bridge: runs an mqtt_client config (ROS 2 layout; the ROS 1 and
/// mqtt_bridge layouts are converted) between a DDS domain and one broker, speaking mqtt_client
/// v2.5's ROS 2 wire (docs/formats.md): the message's CDR bytes as rclcpp serializes them, the
/// RosMsgType announcement in CDR (name and stamped only) retained on
/// `mqtt_client/ros_msg_type/<topic>`, the optional 12-byte CDR send time before the message,
/// `~/latencies/<topic>` (std_msgs/msg/Float64) for stamped messages, fixed types (`ros_type`:
/// published at once, announcements ignored), `primitive` text, `json` towards ROS, and the
/// ROS 2 QoS of each mapping (advanced.ros.qos; for ros2mqtt what the config leaves to `auto` is
/// taken from the publisher, as v2.5 does). Plus the benchmarking suite's
/// `timestamp_topic_prefix` stamps as benchmarking_suite/msg/TimeStamped on `<prefix>/in` and
/// `<prefix>/out`.
///
/// Its DDS side is a Ros2Participant (the child process `bridgescope-dds`): the node is announced
/// in ros_discovery_info under mqtt_client's name. Messages from DDS are forwarded on this
/// thread's event loop as they come; messages from the broker are handed to it from Paho's thread.
/// Towards ROS they take half of BridgeOptions::maxQueuedBytes, a quarter waiting for the event loop and
/// a quarter in the pipe to the DDS process (a message beyond either is dropped and counted, one
/// larger than a quarter passes alone); the other half bounds what waits for the broker
/// (MqttLink), as in the ROS 1 bridge. Each mapping is forwarded by a BridgeHop, as in the ROS 1
/// bridge; this class gives it its DDS side and subscribes as v2.5 does.
class Ros2Bridge
{
    Q_DECLARE_TR_FUNCTIONS(Ros2Bridge)
public:
    explicit Ros2Bridge(BridgeHop::Log log);
    ~Ros2Bridge();

    /// Reads the config (any layout). Errors: not a bridge config, no mapping, bad values.
    Status load(const QByteArray& yaml, const BridgeOptions& options);
    /// Joins the domain and connects to the broker (waiting up to 10 s); then bridges from this
    /// thread's event loop.
    Status start(const Ros2Options& ros);
    void stop();

    const BridgeCounters& counters() const;
    const MqttProfile& profile() const;
    int mappingCount() const;
    /// The node's full name ("/mqtt_client"): BridgeOptions::nodeName, else the ROS 2 config's node
    /// key, else mqtt_client's default.
    QString nodeName() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};
