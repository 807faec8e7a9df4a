// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"

#include <optional>
#include <QHash>

/// What mqtt_client announced per MQTT topic (`mqtt_client/ros_msg_type/<topic>`, retained or not):
/// the type, whether its payloads are stamped, whether it starts with a Header, which ROS it came from.
///
/// mqtt_client may announce with every message: a payload is decoded only when it changed. At most
/// kMax topics are kept; `dropped()` counts the announcements of topics beyond (a hostile broker's
/// made-up topics cost a hash lookup each).
class AnnouncedTypes
{
public:
    static constexpr int kMax = 10'000;

    /// An announcement on `dataTopic`: the type it says when it is new and decodes, nothing otherwise
    /// (the same payload again, a topic past the bound, bytes that are not an announcement).
    std::optional<AnnouncedType> add(const QString& dataTopic, const QByteArray& payload);
    /// Every topic's last decoded announcement, by data topic.
    const QHash<QString, AnnouncedType>& all() const { return m_types; }
    quint64 dropped() const { return m_dropped; }

    /// Whether a ROS type's definition starts with a std_msgs/Header (ROS 1: its seq comes first).
    static bool headerFirst(const QString& type, const QString& definition);

private:
    QHash<QString, AnnouncedType> m_types; ///< by data topic
    QHash<QString, std::size_t> m_hashes; ///< by data topic: the last payload's, decoded once
    quint64 m_dropped = 0;
};
