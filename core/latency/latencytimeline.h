// SPDX-License-Identifier: MIT
#pragma once

#include <deque>
#include <QtGlobal>

/// A latency over time, as a plot of it needs it (a spike at 12:03 is what people look for):
/// per second of the samples' first stamp, the lowest, mean and highest value, for the last
/// kSeconds seconds. Bounded whatever the rate: a second's samples are one bucket.
class LatencyTimeline
{
public:
    struct Bucket
    {
        qint64 second = 0; ///< seconds since the epoch of the samples' first stamps
        qint64 min = 0; ///< ns
        qint64 max = 0;
        double sum = 0;
        qint64 count = 0;
        double meanNs() const { return count > 0 ? sum / double(count) : 0; }
    };
    /// Seconds kept: a quarter of an hour.
    static constexpr std::size_t kSeconds = 900;

    /// A sample whose first stamp is at `timeNs` (since the epoch) took `valueNs`. Samples may
    /// come a little out of order; one older than the oldest second kept is left out.
    void add(qint64 timeNs, qint64 valueNs);
    void clear();
    const std::deque<Bucket>& buckets() const { return m_buckets; }
    /// Changes with every add and clear (redraw only when it moved).
    quint64 revision() const { return m_revision; }

private:
    std::deque<Bucket> m_buckets; ///< ordered by second, at most kSeconds
    quint64 m_revision = 0;
};
