// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "mqtt/mqttprofile.h"
#include "ros2/ros2types.h"

#include <QString>

/// What the Discover page drives of the live session: which ROS master, broker and ROS 2 domain
/// it uses. The page is handed this and the parts it shows, not the session.
class SessionControls
{
public:
    virtual ~SessionControls() = default;
    virtual void setRosMasterUri(const QString& uri) = 0;
    virtual QString rosMasterUri() const = 0;
    virtual void connectBroker(const MqttProfile& profile) = 0;
    virtual void disconnectBroker() = 0;
    virtual Status startRos2(const Ros2Options& options) = 0;
    virtual void stopRos2() = 0;
    virtual bool isRos2Running() const = 0;
};
