// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <deque>
#include <QtGlobal>
#include <utility>

/// Message rate and bandwidth over the last few seconds, as rostopic hz and bw compute them:
/// the intervals between the arrivals still in the window. Bounded: at most kMaxArrivals kept.
class RateWindow
{
public:
    static constexpr qint64 kWindowNs = 5'000'000'000LL;
    static constexpr std::size_t kMaxArrivals = 20000;

    void add(qint64 nowNs, qint64 size)
    {
        m_arrivals.emplace_back(nowNs, size);
        m_lastNs = nowNs;
        while (m_arrivals.size() > kMaxArrivals
               || (!m_arrivals.empty() && nowNs - m_arrivals.front().first > kWindowNs))
            m_arrivals.pop_front();
    }

    /// Messages per second and bytes per second at `nowNs` (zero when too few arrivals are left).
    std::pair<double, double> rates(qint64 nowNs) const
    {
        qsizetype n = 0;
        qint64 first = 0;
        qint64 bytes = 0;
        for (const auto& [t, size] : m_arrivals) {
            if (nowNs - t > kWindowNs)
                continue;
            if (n == 0)
                first = t;
            ++n;
            bytes += size;
        }
        const qint64 span = nowNs - first;
        const double hz = n >= 2 && m_lastNs > first ? double(n - 1) / (double(m_lastNs - first) / 1e9) : 0;
        const double bps
            = n >= 1 && span > 0 ? double(bytes) / (double(std::max<qint64>(span, 1000000000LL)) / 1e9) : 0;
        return {hz, bps};
    }

private:
    std::deque<std::pair<qint64, qint64>> m_arrivals; ///< (time, size)
    qint64 m_lastNs = 0;
};
