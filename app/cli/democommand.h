// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope demo [--seconds N] [-o RUN] [--format md|json]`: the demo lab without a window.
int runDemoCommand(const QStringList& arguments);
/// `bridgescope demo-node vehicle|cloud ...`: one of the demo lab's ROS nodes (started by the lab).
int runDemoNodeCommand(const QStringList& arguments);
