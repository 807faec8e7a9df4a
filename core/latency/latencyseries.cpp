// SPDX-License-Identifier: MIT
#include "latencyseries.h"

#include "latency/quantile.h"

#include <algorithm>
#include <cmath>

LatencySeries::LatencySeries(double msPerUnit)
    : m_msPerUnit(msPerUnit)
{ }

void LatencySeries::addToSums(qint64 value)
{
    if (value > kExactLimit || value < -kExactLimit) {
        ++m_big;
        return;
    }
    if (!m_hasRef) {
        m_ref = value;
        m_hasRef = true;
    }
    const LatencyInt128 d = LatencyInt128(value) - m_ref; // |d| <= 2^51: d * d and sums fit
    m_sum += d;
    m_sumSq += d * d;
}

void LatencySeries::removeFromSums(qint64 value)
{
    if (value > kExactLimit || value < -kExactLimit) {
        --m_big;
        return;
    }
    const LatencyInt128 d = LatencyInt128(value) - m_ref;
    m_sum -= d;
    m_sumSq -= d * d;
}

void LatencySeries::add(qint64 value)
{
    addToSums(value);
    m_sorted.insert(value);
}

void LatencySeries::remove(qint64 value)
{
    removeFromSums(value);
    m_sorted.erase(value);
}

void LatencySeries::append(qint64 value)
{
    ++m_appended;
    m_values.push_back(value);
    if (m_window > 0 && m_sorted.size() == m_window) {
        // A full window slides: the oldest value leaves as the new one comes, in one move.
        const qint64 out = m_values[m_windowStart++];
        removeFromSums(out);
        addToSums(value);
        m_sorted.replace(out, value);
    } else {
        add(value);
    }
    if (m_values.size() > kMaxKept) {
        // Forget the oldest tenth in one move; in whole-run mode they leave the statistics too.
        const std::size_t drop = kMaxKept / 10;
        for (std::size_t i = m_windowStart; i < drop; ++i)
            remove(m_values[i]);
        m_values.erase(m_values.begin(), m_values.begin() + std::ptrdiff_t(drop));
        m_windowStart = m_windowStart > drop ? m_windowStart - drop : 0;
    }
}

void LatencySeries::clear()
{
    m_values.clear();
    m_values.shrink_to_fit();
    m_windowStart = 0;
    m_sorted.clear();
    m_appended = 0;
    m_hasRef = false;
    m_sum = 0;
    m_sumSq = 0;
    m_big = 0;
}

void LatencySeries::setWindow(qint64 samples)
{
    samples = std::max<qint64>(samples, 0);
    if (samples == m_window)
        return;
    m_window = samples;
    m_sorted.clear();
    m_sum = 0;
    m_sumSq = 0;
    m_big = 0;
    m_hasRef = false;
    m_windowStart = m_window > 0 && m_values.size() > std::size_t(m_window)
        ? m_values.size() - std::size_t(m_window)
        : 0;
    for (std::size_t i = m_windowStart; i < m_values.size(); ++i)
        add(m_values[i]);
}

std::pair<long double, long double> LatencySeries::directMoments() const
{
    const qint64 n = count();
    const std::size_t first = m_values.size() - std::size_t(n);
    long double sum = 0;
    for (std::size_t i = first; i < m_values.size(); ++i)
        sum += static_cast<long double>(m_values[i]);
    const long double mean = sum / n;
    long double squares = 0;
    for (std::size_t i = first; i < m_values.size(); ++i) {
        const long double d = static_cast<long double>(m_values[i]) - mean;
        squares += d * d;
    }
    return {mean, n > 1 ? squares / (n - 1) : 0};
}

double LatencySeries::meanMs() const
{
    const qint64 n = count();
    if (n == 0)
        return LatencyStats::nan();
    if (m_big > 0)
        return double(directMoments().first * m_msPerUnit);
    const long double mean = static_cast<long double>(m_ref) + static_cast<long double>(m_sum) / n;
    return double(mean * m_msPerUnit);
}

double LatencySeries::stdMs() const
{
    const qint64 n = count();
    if (n < 2)
        return LatencyStats::nan();
    if (m_big > 0)
        return double(std::sqrt(std::max<long double>(directMoments().second, 0)) * std::abs(m_msPerUnit));
    const long double s = static_cast<long double>(m_sum);
    const long double var = (static_cast<long double>(m_sumSq) - s * s / n) / (n - 1);
    return double(std::sqrt(std::max<long double>(var, 0)) * std::abs(m_msPerUnit));
}

double LatencySeries::quantileMs(double q) const
{
    const qint64 n = count();
    if (n == 0)
        return LatencyStats::nan();
    const auto [lo, t] = Quantile::rank(n, q);
    const auto [first, second] = m_sorted.atPair(lo);
    return Quantile::lerp(toMs(first), toMs(second), t);
}

LatencyStats LatencySeries::stats() const
{
    LatencyStats s;
    s.count = count();
    if (s.count == 0)
        return s;
    s.mean = meanMs();
    s.std = stdMs();
    s.min = toMs(m_sorted.min());
    s.max = toMs(m_sorted.max());
    s.median = quantileMs(0.5);
    s.p90 = quantileMs(0.90);
    s.p95 = quantileMs(0.95);
    s.p99 = quantileMs(0.99);
    s.p999 = quantileMs(0.999);
    return s;
}
