// SPDX-License-Identifier: MIT
#pragma once

#include "wire/rosmessage.h"
#include "wire/stampcodec.h"

#include <optional>
#include <QByteArray>
#include <QString>

/// What the ROS 2 reference bridge writes and reads besides whole messages, as mqtt_client v2.5
/// (MqttClient.cpp) and the benchmarking suite's ROS 2 nodes do: CDR (XCDR1, little-endian) after
/// the encapsulation header 00 01 00 00, as rclcpp serializes.
namespace Ros2BridgeWire {

constexpr const char* kTimeStampedType = "benchmarking_suite/msg/TimeStamped";

/// benchmarking_suite/msg/TimeStamped {std_msgs/msg/Header header, builtin_interfaces/msg/Time
/// time}: header.stamp is the sample, `time` the stamp (a ROS 2 Header has no seq).
QByteArray encodeTimeStamped(const StampCodec::Decoded& stamp);
/// std_msgs/msg/Float64, as mqtt_client publishes `~/latencies/<topic>`.
QByteArray encodeFloat64(double value);
/// The header.stamp a message that starts with a std_msgs/msg/Header carries (either byte order),
/// in ns; nullopt when the bytes are too short or the time out of a stamp's range.
std::optional<qint64> headerStampNs(const QByteArray& cdr);
/// Whether messages of `type` start with a std_msgs/msg/Header (false for types `registry` does
/// not know).
bool startsWithHeader(const RosTypeRegistry& registry, const QString& type);

/// A std_msgs primitive as mqtt_client v2.5's primitiveRosMessageToString() writes it: String's
/// data, Bool "true"/"false", integers in decimal, floats as std::to_string (six decimals),
/// UInt8MultiArray's bytes; nullopt for other types or bytes that do not decode.
std::optional<QByteArray> primitiveText(const RosTypeRegistry& registry, const QString& type, const QByteArray& cdr);

/// A message and its type.
struct Typed
{
    QString type;
    QByteArray cdr;
};
/// Text from MQTT as mqtt_client v2.5's mqtt2primitive() takes it: "true"/"false" (any case) a
/// std_msgs/msg/Bool, a whole int32 an Int32, a whole float a Float32, anything else a String.
Typed primitiveFromText(const QByteArray& text);
/// Text for a fixed primitive type (fixedMqtt2PrimitiveRos()): nullopt when it does not read as
/// one ("1"/"0" are Bool too; integers out of range are refused).
std::optional<QByteArray> fixedPrimitive(const RosTypeRegistry& registry, const QString& type, const QByteArray& text);
/// The most a json: true mapping converts, either way: JSON text towards ROS, CDR towards JSON.
/// QJsonDocument builds its whole tree before the encoder's limits apply (about 40 times the text:
/// a 40 MB array of zeros took the bridge to 1.7 GB), and a decoded message is as big again; a
/// bigger payload is refused unread (issue 41). A JSON message is a small one; big data goes as CDR.
inline constexpr qsizetype kMaxJsonBytes = 1024 * 1024;

/// Why a payload of `bytes` is not converted ("a payload of N bytes, more than ...").
QString tooLargeForJson(qsizetype bytes);
/// A message as a JSON object, field by field (json: true mappings towards MQTT; mqtt_client v2.5
/// writes it with rosx_introspection, whose exact text, spacing and number format included, is
/// not checked here), or why not.
Result<QByteArray> toJson(const RosTypeRegistry& registry, const QString& type, const QByteArray& cdr);
/// JSON text as a message of `type` (json: true mappings), or why not. Both refuse more than
/// kMaxJsonBytes before anything is parsed.
Result<QByteArray> fromJson(const RosTypeRegistry& registry, const QString& type, const QByteArray& json);

} // namespace Ros2BridgeWire
