// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// What mqtt_client announces about an MQTT topic: its ROS type and whether payloads are stamped.
struct RosMsgTypeInfo
{
    QString md5;
    QString name; ///< e.g. "geometry_msgs/PoseStamped"
    QString definition; ///< full definition with dependencies
    bool stamped = false;
    bool operator==(const RosMsgTypeInfo& o) const
    {
        return md5 == o.md5 && name == o.name && definition == o.definition && stamped == o.stamped;
    }
};

/// mqtt_client's wire protocol (v2.2.1, ROS 1), byte for byte.
///
/// For a non-primitive mapping it publishes, retained, on `mqtt_client/ros_msg_type/<topic>` a
/// ROS-serialized RosMsgType (three strings and a bool), and on `<topic>` the ROS-serialized
/// message, preceded by 8 bytes of ROS time (uint32 sec, uint32 nsec, little-endian) when stamped.
class MqttClientWire
{
    Q_DECLARE_TR_FUNCTIONS(MqttClientWire)
public:
    static QString typeTopicPrefix() { return QStringLiteral("mqtt_client/ros_msg_type/"); }
    /// For `mqtt_client/ros_msg_type/<topic>`, the data topic; otherwise empty.
    static QString dataTopicOf(const QString& typeTopic);

    /// Announcements are a few kB; one larger than this is an error, not parsed (its definition
    /// would be parsed and sized by every receiver).
    static constexpr qsizetype kMaxTypeBytes = 1024 * 1024;
    static std::optional<RosMsgTypeInfo> decodeType(const QByteArray& bytes, QString* error = nullptr);
    static QByteArray encodeType(const RosMsgTypeInfo& info);

    /// The injected send time of a stamped payload (ns since the epoch) and the message after it.
    struct Stamped
    {
        qint64 stampNs = 0;
        QByteArray message;
    };
    static std::optional<Stamped> splitStamped(const QByteArray& payload);
    static QByteArray stamped(qint64 stampNs, const QByteArray& message);
};
