// SPDX-License-Identifier: MIT
#include "latencytimeline.h"

#include <algorithm>

void LatencyTimeline::add(qint64 timeNs, qint64 valueNs)
{
    // Floor division: a stamp before 1970 (a clock not set) still has its second.
    const qint64 second = timeNs >= 0 ? timeNs / 1'000'000'000 : -((-timeNs + 999'999'999) / 1'000'000'000);
    auto it = m_buckets.end();
    if (m_buckets.empty() || m_buckets.back().second < second) {
        m_buckets.push_back({second, valueNs, valueNs, 0, 0});
        it = m_buckets.end() - 1;
    } else {
        it = std::lower_bound(m_buckets.begin(), m_buckets.end(), second,
                              [](const Bucket& b, qint64 s) { return b.second < s; });
        if (it == m_buckets.begin() && it->second != second && m_buckets.size() >= kSeconds)
            return; // older than what is kept
        if (it->second != second)
            it = m_buckets.insert(it, Bucket {second, valueNs, valueNs, 0, 0});
    }
    it->min = std::min(it->min, valueNs);
    it->max = std::max(it->max, valueNs);
    it->sum += double(valueNs);
    ++it->count;
    while (m_buckets.size() > kSeconds)
        m_buckets.pop_front();
    ++m_revision;
}

void LatencyTimeline::clear()
{
    m_buckets.clear();
    ++m_revision;
}
