// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/problem.h"

#include <QByteArray>
#include <QCoreApplication>

/// What reading a config file gave: the config, and what was wrong with the text itself.
struct ConfigReadResult
{
    BridgeConfig config;
    QList<Problem> problems; ///< YAML syntax and structure problems (rules come from ConfigValidator)
    bool parsed = false; ///< false: not YAML, or not a bridge config at all
    bool lossy = false; ///< parts of the file have no place in the model; a rewrite would lose them
    QList<Problem> dropped; ///< those parts, as warnings naming each one and where it is
};

/// Reads mqtt_client (ROS 1 and ROS 2 layouts) and mqtt_bridge configs; detects the layout.
class ConfigReader
{
    Q_DECLARE_TR_FUNCTIONS(ConfigReader)
public:
    static ConfigReadResult read(const QByteArray& text);
    /// A file of `size` bytes, past YamlLimits::maxBytes: refused by its size, unread ("The file is
    /// 17 MB, the limit is 8 MB."), whoever opened it.
    static Problem tooLarge(qint64 size);
    /// mqtt_bridge "std_msgs.msg:Bool" <-> ROS "std_msgs/Bool".
    static QString rosTypeFromMqttBridge(const QString& msgType);
    static QString mqttBridgeTypeFromRos(const QString& rosType);
};
