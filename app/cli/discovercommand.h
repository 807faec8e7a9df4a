// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope discover [--broker URL] [--ros-master URI] [--seconds N] [--json]`.
int runDiscoverCommand(const QStringList& arguments);
