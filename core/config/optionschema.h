// SPDX-License-Identifier: MIT
#pragma once

#include "config/mqttclientrelease.h"

#include <QList>
#include <QString>
#include <QStringList>

/// Where an option lives in an mqtt_client config.
enum class OptionScope { Broker, Client, Ros2Mqtt, Mqtt2Ros };

/// How an option's text is to be read.
enum class OptionKind { String, Path, Int, Double, Bool, StringList, Enum };

/// One option that mqtt_client (or the benchmarking suite's fork) understands.
///
/// The table of these drives reading, writing, validation, the inspector forms and the peer
/// config, so an option added here is handled everywhere.
struct OptionSpec
{
    QString path; ///< dotted path inside its scope, e.g. "advanced.mqtt.qos"
    OptionKind kind = OptionKind::String;
    QString defaultText; ///< mqtt_client's default, as text; empty when there is none
    QStringList enumValues; ///< for OptionKind::Enum
    int minimum = 0; ///< for OptionKind::Int
    int maximum = 0; ///< for OptionKind::Int; minimum == maximum means unbounded
    const char* summary = nullptr; ///< untranslated; translate with OptionSchema context
    bool ros2Only = false; ///< only understood by the ROS 2 mqtt_client (>= 2.3)
    /// The first mqtt_client release that reads it (extensions: the oldest, they are not its own).
    MqttClientRelease since = MqttClientRelease::V2_2;
    bool extension = false; ///< not mqtt_client's own (benchmarking suite fork)
    bool secret = false; ///< a password: never shown in previews or logs in clear

    bool isTopic() const { return path == QLatin1String("ros_topic") || path == QLatin1String("mqtt_topic"); }
};

/// The table of known options per scope.
namespace OptionSchema {
const QList<OptionSpec>& options(OptionScope scope);
const OptionSpec* find(OptionScope scope, const QString& path);
/// The option's one-line summary, translated.
QString summary(const OptionSpec& spec);
/// A short human name for a scope ("broker", "ros2mqtt", ...), as written in the YAML.
QString scopeKey(OptionScope scope);
/// Known keys whose value is a map (e.g. "advanced", "advanced.ros", "tls").
bool isSection(OptionScope scope, const QString& path);
} // namespace OptionSchema
