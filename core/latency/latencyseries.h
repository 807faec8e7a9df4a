// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencystats.h"
#include "latency/sortedblocks.h"

#include <utility>
#include <vector>

__extension__ typedef __int128 LatencyInt128; ///< exact sums of squared ns

/// The values of one latency series and their statistics over a window of the last N samples
/// (or the whole run).
///
/// Values are integers (ns, or half-ns for halved series: `msPerUnit` says how to read them), so
/// sums are exact. Each append updates exact sums and a sorted multiset in O(log n + block):
/// mean and std cost O(1), median and percentiles a binary search; nothing is re-sorted.
class LatencySeries
{
public:
    /// Whole-run series keep at most this many values; older ones leave (and are counted).
    static constexpr std::size_t kMaxKept = 20'000'000;

    explicit LatencySeries(double msPerUnit = 1e-6);

    void append(qint64 value);
    void clear();
    /// 0 for the whole run. Rebuilds the window from the kept values.
    void setWindow(qint64 samples);
    qint64 window() const { return m_window; }

    double msPerUnit() const { return m_msPerUnit; }
    double toMs(qint64 value) const { return double(value) * m_msPerUnit; }
    /// Values in the window.
    qint64 count() const { return m_sorted.size(); }
    /// Values appended since the last clear (also those that left the window).
    qint64 totalCount() const { return m_appended; }
    /// The kept values in arrival order; the window is the last count() of them.
    const std::vector<qint64>& values() const { return m_values; }
    const SortedBlocks& sorted() const { return m_sorted; }
    qint64 latest() const { return m_values.empty() ? 0 : m_values.back(); }

    LatencyStats stats() const;
    /// The q-quantile (0..1) in ms, interpolated linearly between closest ranks (numpy's default).
    double quantileMs(double q) const;
    double meanMs() const;
    double stdMs() const;

    /// Values beyond this (about 13 days in ns) stay out of the exact sums, whose squares could
    /// overflow 128 bits; while the window holds one, mean and std are computed from the values.
    static constexpr qint64 kExactLimit = qint64(1) << 50;

private:
    void add(qint64 value);
    void remove(qint64 value);
    void addToSums(qint64 value);
    void removeFromSums(qint64 value);
    /// Mean and corrected variance of the window in long double, from the values themselves.
    std::pair<long double, long double> directMoments() const;

    double m_msPerUnit;
    qint64 m_window = 600;
    std::vector<qint64> m_values;
    std::size_t m_windowStart = 0; ///< index in m_values of the window's first value
    SortedBlocks m_sorted;
    qint64 m_appended = 0;
    // Exact sums of (value - m_ref) over the window; the shift keeps them small.
    qint64 m_ref = 0;
    bool m_hasRef = false;
    LatencyInt128 m_sum = 0;
    LatencyInt128 m_sumSq = 0;
    qint64 m_big = 0; ///< values in the window beyond kExactLimit (not in the sums)
};
