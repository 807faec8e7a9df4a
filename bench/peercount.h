// SPDX-License-Identifier: MIT
#pragma once
// The bare peers of bench_watch (bench_rossub, bench_pahosub): count what arrives, print the count
// once a second on stdout, stop at SIGTERM. Plain C++: the peers link no Qt.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace PeerCount {
inline std::atomic<unsigned long long> received {0};
inline std::atomic<bool> stop {false};
inline void onTerm(int) { stop = true; }
inline void stopOnTerm() { std::signal(SIGTERM, onTerm); }
/// Prints the count once a second until SIGTERM.
inline void printUntilTerm()
{
    for (int tenths = 0; !stop; ++tenths) {
        usleep(100000);
        if (tenths % 10 == 0) {
            std::printf("%llu\n", static_cast<unsigned long long>(received));
            std::fflush(stdout);
        }
    }
}
} // namespace PeerCount
