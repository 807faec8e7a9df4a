// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope watch CONFIG.yaml... [--broker URL] [--ros-master URI] [--rules R.yaml]
/// [--metrics HOST:PORT] [--events-jsonl FILE] [--seconds N]`
int runWatchCommand(const QStringList& arguments);
