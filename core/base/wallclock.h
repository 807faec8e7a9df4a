// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <QtGlobal>

/// The wall clock in ns since the epoch: what stamps, receive times and injected times use
/// (CLOCK_REALTIME, the same clock as ros::WallTime and mqtt_client's stamps).
inline qint64 wallClockNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}
