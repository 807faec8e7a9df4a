// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/problem.h"

#include <functional>
#include <optional>
#include <QCoreApplication>

/// Checks a config against what mqtt_client accepts and what works on a real link.
///
/// Every problem names the mapping, says how to fix it, and points at the line it came from.
/// Errors make a file invalid; warnings (missing TLS files, a buffer without client id, ...) do not.
class ConfigValidator
{
    Q_DECLARE_TR_FUNCTIONS(ConfigValidator)
public:
    struct Options
    {
        /// Where mqtt_client resolves relative paths; empty: $ROS_HOME, else ~/.ros.
        QString rosHome;
        /// Whether a file exists (replaceable in tests); default: QFileInfo::exists.
        std::function<bool(const QString&)> fileExists;
        /// The mqtt_client release checked against; none: the newest that loads the layout
        /// (MqttClientReleases::defaultTarget).
        std::optional<MqttClientRelease> target;
    };

    static QList<Problem> validate(const BridgeConfig& config, const Options& options = {});

    /// "ros2mqtt '/a' → 'a'": how problems name a mapping.
    static QString describe(const Mapping& m);
    /// How mqtt_client resolves a relative file path.
    static QString resolvePath(const QString& path, const QString& rosHome);
};
