// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QByteArray>
#include <QHash>
#include <QString>
#include <QtGlobal>
#include <QtNumeric>

/// What a monitor knows of one subscribed topic, ROS 1 (TopicStats) and ROS 2
/// (Ros2MonitorStats) alike, so that the views show both from one model.
struct TopicFigures
{
    quint64 messages = 0;
    quint64 bytes = 0;
    int lastSize = 0;
    qint64 lastNs = 0; ///< wall clock of the last message
    double rateHz = 0; ///< over the last few seconds, like rostopic hz
    double bytesPerSecond = 0;
    QString type;
    QByteArray lastMessage; ///< as it came: ROS 1 serialization, or CDR with its encapsulation header
    quint64 lost = 0; ///< ROS 2: samples DDS reports lost (roscpp tells none)
    /// MQTT: the latency of the last payload mqtt_client stamped, when one came (ROS: none).
    std::optional<double> lastLatencyMs;
    /// ROS 2: how old the samples were when they came, by their DDS source timestamp (the writer's
    /// clock: true as far as it agrees with this one), whatever their type, Header or not; the
    /// median of the last kAgeSamples. NaN: none came with a source timestamp (ROS 1: none).
    double ageMs = qQNaN();
    static constexpr int kAgeSamples = 64;
};

/// The figures of every topic of a monitor's snapshot, without what only its graph knows (md5,
/// matched publishers).
template <class Stats>
QHash<QString, TopicFigures> topicFiguresOf(const QHash<QString, Stats>& stats)
{
    QHash<QString, TopicFigures> figures;
    figures.reserve(stats.size());
    for (auto it = stats.cbegin(); it != stats.cend(); ++it)
        figures.insert(it.key(), *it);
    return figures;
}
