// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope probe [--broker URL] [--size BYTES] [--rate HZ] [--qos 0|1|2] [--count N] [--sweep]
/// [--json] [--echo | --via-echo]`.
int runProbeCommand(const QStringList& arguments);
