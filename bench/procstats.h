// SPDX-License-Identifier: MIT
#pragma once

// What a benchmark process measures of itself, without Qt: the Fast DDS peer (bench_ros2_fastdds)
// is built as DDS's own examples are, and uses these as the Qt-based benchmarks do (benchutil.h).

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/resource.h>

namespace Bench {

/// User + system CPU seconds of this process so far.
inline double cpuSeconds()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec)
        + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

/// A field of /proc/self/status in kB ("VmRSS:", "VmHWM:"), or -1.
inline long long statusKb(const char* field)
{
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f)
        return -1;
    char line[256];
    long long kb = -1;
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, field, std::strlen(field)) == 0)
            kb = std::atoll(line + std::strlen(field));
    std::fclose(f);
    return kb;
}

} // namespace Bench
