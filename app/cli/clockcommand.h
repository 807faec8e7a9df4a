// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope clock serve --name NAME [--broker URL] [--udp [ADDR:]PORT] [--clock-offset-ms X]`
/// and `bridgescope clock probe (--udp ADDR:PORT | --broker URL --host NAME) [--count N]
/// [--interval-ms M] [--json]`: the clock service of a host, and a measurement of a far host's clock.
int runClockCommand(const QStringList& arguments);
