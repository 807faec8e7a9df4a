// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>

/// The rules for ROS graph names and MQTT topics, shared by the config checks, the MQTT profile and
/// every view that takes a name from the user. Rejections say why, in a few words.
class TopicNames
{
    Q_DECLARE_TR_FUNCTIONS(TopicNames)
public:
    /// ROS graph resource name rules (ROS 1; `strict` adds the ROS 2 ones).
    static bool isValidRosName(const QString& name, bool strict, QString* why = nullptr);
    /// MQTT topic rules; `publish` forbids wildcards.
    static bool isValidMqttTopic(const QString& topic, bool publish, QString* why = nullptr);
    static bool hasWildcard(const QString& topic);
    /// Whether an MQTT subscription filter matches a topic name.
    static bool topicMatches(const QString& filter, const QString& topic);
};
