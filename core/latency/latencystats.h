// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <limits>
#include <QtGlobal>

/// Statistics of one latency series, in milliseconds (the paper's unit).
///
/// std is the corrected standard deviation (ddof = 1, the paper's jitter); percentiles and the
/// median interpolate linearly between the closest ranks, as numpy does by default. With fewer
/// than two values std is NaN; with none, everything is.
struct LatencyStats
{
    static constexpr double nan() { return std::numeric_limits<double>::quiet_NaN(); }
    qint64 count = 0;
    double mean = nan();
    double median = nan();
    double std = nan();
    double min = nan();
    double max = nan();
    double p90 = nan();
    double p95 = nan();
    double p99 = nan();
    double p999 = nan();
};
