// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"

#include <QCoreApplication>
#include <QStringList>

/// The config for the other end of a link: what one host sends, the other receives.
class PeerConfig
{
    Q_DECLARE_TR_FUNCTIONS(PeerConfig)
public:
    struct Result
    {
        BridgeConfig config;
        QStringList notes; ///< what could not be carried over, and why
    };
    /// Every ros2mqtt R -> M becomes mqtt2ros M -> R and the reverse; options are carried over
    /// where they mean something on the other side (qos, primitive, json, ros_type, queue sizes;
    /// retained <-> latched). The broker stays; the client id becomes `clientId`, or the old id
    /// with "_peer" appended.
    static Result make(const BridgeConfig& config, const QString& clientId = QString());
};
