// SPDX-License-Identifier: MIT
#include "shiftestimate.h"

#include "latency/latencyseries.h"

#include <algorithm>
#include <cmath>

namespace {
/// How many differences y_j − x_i are at most t (both sorted): O(n + m).
LatencyInt128 countAtMost(const std::vector<qint64>& x, const std::vector<qint64>& y, LatencyInt128 t)
{
    LatencyInt128 count = 0;
    std::size_t i = 0; // the first x with y_j − x <= t; moves forward as y_j grows
    for (const qint64 yj : y) {
        while (i < x.size() && LatencyInt128(yj) - x[i] > t)
            ++i;
        count += LatencyInt128(x.size() - i);
    }
    return count;
}

/// The k-th smallest difference (1-based), exact: the values are integers.
LatencyInt128 kthDifference(const std::vector<qint64>& x, const std::vector<qint64>& y, LatencyInt128 k)
{
    LatencyInt128 lo = LatencyInt128(y.front()) - x.back();
    LatencyInt128 hi = LatencyInt128(y.back()) - x.front();
    while (lo < hi) {
        const LatencyInt128 mid = lo + (hi - lo) / 2; // hi − lo >= 0: rounds down
        if (countAtMost(x, y, mid) >= k)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}
} // namespace

std::optional<ShiftEstimate> ShiftEstimate::of(std::vector<qint64> x, std::vector<qint64> y, double msPerUnit)
{
    if (x.empty() || y.empty())
        return std::nullopt;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    const double n = double(x.size());
    const double m = double(y.size());
    const LatencyInt128 pairs = LatencyInt128(x.size()) * LatencyInt128(y.size());
    // Rank of the interval's ends: N/2 − z·sqrt(N(n+m+1)/12), the normal approximation of the
    // Mann–Whitney count (as R's wilcox.test(conf.int = TRUE, exact = FALSE, correct = FALSE)).
    constexpr double z = 1.959963984540054; // the 97.5 % quantile of the normal distribution
    const double c = double(pairs) / 2 - z * std::sqrt(double(pairs) * (n + m + 1) / 12);
    const LatencyInt128 k = LatencyInt128(std::floor(c));
    if (k < 1)
        return std::nullopt;
    const auto ms = [msPerUnit](LatencyInt128 v) { return double(v) * msPerUnit; };
    ShiftEstimate e;
    const LatencyInt128 half = pairs / 2;
    e.shiftMs = pairs % 2 != 0 ? ms(kthDifference(x, y, half + 1))
                               : (ms(kthDifference(x, y, half)) + ms(kthDifference(x, y, half + 1))) / 2;
    e.lowMs = ms(kthDifference(x, y, k));
    e.highMs = ms(kthDifference(x, y, pairs - k + 1));
    return e;
}
