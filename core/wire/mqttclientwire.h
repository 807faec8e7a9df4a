// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "wire/rosmessage.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// What mqtt_client announces about an MQTT topic: its ROS type and whether payloads are stamped.
struct RosMsgTypeInfo
{
    QString md5; ///< ROS 1; mqtt_client for ROS 2 leaves it empty
    QString name; ///< e.g. "geometry_msgs/PoseStamped" (ROS 1), "std_msgs/msg/String" (ROS 2)
    QString definition; ///< ROS 1: full definition with dependencies; ROS 2: empty
    bool stamped = false;
    /// Which mqtt_client sent it, and so how its payloads are serialized: ROS 1 (ROS
    /// serialization, an 8-byte stamp) or ROS 2 (CDR, a 12-byte CDR stamp).
    RosTypeRegistry::Dialect dialect = RosTypeRegistry::Dialect::Ros1;
    bool operator==(const RosMsgTypeInfo& o) const
    {
        return md5 == o.md5 && name == o.name && definition == o.definition && stamped == o.stamped
            && dialect == o.dialect;
    }
};

/// mqtt_client's wire protocol, byte for byte: v2.2.1 for ROS 1, v2.0 to v2.5 for ROS 2.
///
/// For a non-primitive mapping it publishes, retained, on `mqtt_client/ros_msg_type/<topic>` a
/// serialized RosMsgType (`string md5, string name, string definition, bool stamped`), and on
/// `<topic>` the serialized message, preceded by the send time when stamped.
///
/// ROS 1: ROS serialization (little-endian, uint32 lengths, no padding); the stamp is 8 bytes of
/// ROS time (uint32 sec, uint32 nsec).
///
/// ROS 2: what rclcpp::Serialization gives (rmw_serialize): CDR (XCDR1) after a 4-byte
/// encapsulation header (00 01 little-endian, 00 00 big-endian, two bytes of options), values
/// aligned to their size from the end of the header, strings as a uint32 length that counts a
/// terminating NUL, then the bytes and the NUL. mqtt_client fills only name and stamped (md5
/// and definition are empty strings). The stamp is a builtin_interfaces/msg/Time serialized on
/// its own (its own header, int32 sec, uint32 nanosec: 12 bytes), and the message follows it
/// with its own header; nothing else separates them.
///
/// Which one an announcement is: its first byte. A ROS 1 one starts with the length of its md5
/// (32, or 1 for "*"; anything else is refused), so never with a zero byte; a CDR encapsulation
/// header always does. See dialectOf().
class MqttClientWire
{
    Q_DECLARE_TR_FUNCTIONS(MqttClientWire)
public:
    using Dialect = RosTypeRegistry::Dialect;

    static QString typeTopicPrefix() { return QStringLiteral("mqtt_client/ros_msg_type/"); }
    /// For `mqtt_client/ros_msg_type/<topic>`, the data topic; otherwise empty.
    static QString dataTopicOf(const QString& typeTopic);

    /// Announcements are a few kB; one larger than this is an error, not parsed (its definition
    /// would be parsed and sized by every receiver).
    static constexpr qsizetype kMaxTypeBytes = 1024 * 1024;
    /// ROS 2 when the announcement starts with a zero byte (a CDR encapsulation header), else ROS 1.
    static Dialect dialectOf(const QByteArray& announcement);
    /// Decodes either dialect (dialectOf() tells which); the result says which it was.
    static Result<RosMsgTypeInfo> decodeType(const QByteArray& bytes);
    /// The announcement as the mqtt_client of `info.dialect` sends it (ROS 2: little-endian CDR,
    /// as rmw_fastrtps and rmw_cyclonedds write it on a little-endian host).
    static QByteArray encodeType(const RosMsgTypeInfo& info);

    /// Bytes of the injected stamp.
    static constexpr qsizetype kRos1StampBytes = 8;
    static constexpr qsizetype kRos2StampBytes = 12;
    static qsizetype stampBytes(Dialect dialect)
    {
        return dialect == Dialect::Ros2 ? kRos2StampBytes : kRos1StampBytes;
    }

    /// The injected send time of a stamped payload (ns since the epoch) and the message after it.
    struct Stamped
    {
        qint64 stampNs = 0;
        QByteArray message;
    };
    static Result<Stamped> splitStamped(const QByteArray& payload, Dialect dialect = Dialect::Ros1);
    /// ROS 2 stamps are written little-endian.
    static QByteArray stamped(qint64 stampNs, const QByteArray& message, Dialect dialect = Dialect::Ros1);

    /// A payload of an announced type as a value: the message after the stamp when stamped,
    /// decoded as the dialect serializes (RosMessageDecoder::decode() or decodeCdr()).
    static Result<RosValue> decodePayload(const RosTypeRegistry& registry, const RosMsgTypeInfo& type,
                                          const QByteArray& payload, const RosDecodeLimits& limits = {});

private:
    static Result<RosMsgTypeInfo> decodeRos2Type(const QByteArray& bytes);
};
