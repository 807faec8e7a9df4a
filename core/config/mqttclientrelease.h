// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QString>
#include <QStringList>

/// The releases of mqtt_client (ika-rwth-aachen/mqtt_client) whose configs differ, oldest first.
/// Read from the tags' own sources, the keys each node declares and loads:
/// - 2.3.0 adds `ros_type` and `advanced.ros.qos.{reliability,durability}` (ROS 2), and is the
///   last release with a ROS 1 node: the ROS 1 list layout loads up to 2.3.0 only;
/// - 2.4.0 drops ROS 1 and changes no key;
/// - 2.4.1 adds `client.tls.server_cert_auth` (default true);
/// - 2.4.2 bridges `std_msgs/msg/UInt8MultiArray` as a primitive, both ways (its bytes as they are);
/// - 2.5.0 adds `json`, which needs `ros_type` in both directions.
enum class MqttClientRelease {
    V2_2, ///< 2.2.0 and 2.2.1
    V2_3, ///< 2.3.0
    V2_4_0,
    V2_4_1,
    V2_4_2,
    V2_5, ///< 2.5.0
};

struct BridgeConfig;

namespace MqttClientReleases {

constexpr MqttClientRelease kOldest = MqttClientRelease::V2_2;
constexpr MqttClientRelease kNewest = MqttClientRelease::V2_5;
/// The last release with a ROS 1 node.
constexpr MqttClientRelease kLastRos1 = MqttClientRelease::V2_3;

/// "2.2", "2.3", "2.4.0", "2.4.1", "2.4.2", "2.5".
QString name(MqttClientRelease release);
/// Every release's name, oldest first.
QStringList names();
/// The release a name says: its name, with or without a leading "v", "2.2.1" and any "X.Y.0" of
/// a release named "X.Y"; nullopt for anything else ("2.4" names three releases).
std::optional<MqttClientRelease> fromName(const QString& text);

/// The releases a config loads in, from its layout and the keys and values it uses.
struct Range
{
    MqttClientRelease lowest = kOldest; ///< the oldest that knows everything it uses
    MqttClientRelease highest = kNewest; ///< the newest that loads its layout
    /// Why: "json (2.5)", "the ROS 1 layout (up to 2.3)"; empty when every release loads it.
    QStringList reasons;
    bool loadsSomewhere() const { return lowest <= highest; }
};
Range detect(const BridgeConfig& config);
/// The release a config targets when none is chosen: the newest its layout loads in.
MqttClientRelease defaultTarget(const BridgeConfig& config);
/// Which release a config is checked against (`chosen`, else the default) and which releases
/// load it, in a sentence: "checked against mqtt_client 2.5 (auto); it loads in 2.3 to 2.5
/// (ros_type (2.3))".
QString summary(const BridgeConfig& config, std::optional<MqttClientRelease> chosen);
/// Whether `release` bridges a primitive of `rosType` ("std_msgs/msg/UInt8MultiArray" from 2.4.2).
bool primitiveTypeKnown(const QString& rosType, MqttClientRelease release);
} // namespace MqttClientReleases
