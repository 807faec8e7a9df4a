// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope bridge CONFIG.yaml [--broker URL] [--ros-master URI] [--name NODE] [--arg NAME=VALUE]...`
int runBridgeCommand(const QStringList& arguments);
