// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

/// bench_watch's fleet form (BENCH_FORM=fleet): one watch over many links, no window; `program`
/// is the bridgescope binary. Returns the process's exit code.
int runWatchFleet(const QString& program);

/// The MQTT topic of link `i`, as bench_loadgen publishes it.
QString fleetTopic(int i);
