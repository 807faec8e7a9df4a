// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ros2protocol.h"

#include <QByteArray>

/// What Ros2Link and Ros2EndpointLink need of the child process `bridgescope-dds`:
/// DdsChildSupervisor in the program, a recorder in tests.
class DdsChildPipe
{
public:
    virtual ~DdsChildPipe() = default;
    /// A child was launched and its end was not handled yet (it may be ending).
    virtual bool hasChild() const = 0;
    /// A child runs: what is sent now reaches it.
    virtual bool childRunning() const = 0;
    /// Bytes sent to the running child that it has not read yet.
    virtual qint64 bytesToWrite() const = 0;
    /// One frame to the running child (dropped when none runs).
    virtual void send(Ros2Protocol::Kind kind, const QByteArray& body) = 0;
};
