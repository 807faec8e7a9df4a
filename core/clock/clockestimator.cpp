// SPDX-License-Identifier: MIT
#include "clock/clockestimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {
constexpr qint64 kMaxTimeNs = qint64(1) << 62; // year 2116: room to add and subtract without overflow
/// A probe is "low-delay" for the drift fit within this factor of the best one's round trip.
constexpr double kLowDelayFactor = 2.0;
constexpr int kMinFitProbes = 3;
} // namespace

ClockEstimator::ClockEstimator(QString host)
    : m_host(std::move(host))
{ }

bool ClockEstimator::add(qint64 t1, qint64 t2, qint64 t3, qint64 t4)
{
    const auto plausible = [](qint64 t) { return t > 0 && t < kMaxTimeNs; };
    const bool ok = plausible(t1) && plausible(t2) && plausible(t3) && plausible(t4) && t4 >= t1 && t3 >= t2
        && (t4 - t1) - (t3 - t2) >= 0 && t4 - t1 <= kMaxRoundTripNs
        && std::llabs((t2 - t1) + (t3 - t4)) / 2 <= kMaxOffsetNs
        && (m_probes.empty() || t4 >= m_probes.back().midNs - kWindowNs);
    if (!ok) {
        ++m_refused;
        return false;
    }
    // Halves summed, not the sum halved: (t2 - t1) + (t3 - t4) cannot overflow within the bounds.
    const qint64 sum = (t2 - t1) + (t3 - t4);
    m_probes.push_back({t1 + (t4 - t1) / 2, sum / 2, (t4 - t1) - (t3 - t2)});
    ++m_accepted;
    while (int(m_probes.size()) > kMaxProbes
           || (!m_probes.empty() && m_probes.front().midNs < m_probes.back().midNs - kWindowNs))
        m_probes.pop_front();
    return true;
}

double ClockEstimator::drift() const
{
    if (m_probes.empty())
        return 0;
    qint64 best = std::numeric_limits<qint64>::max();
    for (const Probe& p : m_probes)
        best = std::min(best, p.delayNs);
    const double limit = std::max(1.0, double(best)) * kLowDelayFactor;
    // Least squares of offset over time, relative to the first probe (seconds and ns as doubles).
    const qint64 origin = m_probes.front().midNs;
    const qint64 offsetOrigin = m_probes.front().offsetNs;
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    qint64 first = std::numeric_limits<qint64>::max();
    qint64 last = std::numeric_limits<qint64>::min();
    for (const Probe& p : m_probes) {
        if (double(p.delayNs) > limit)
            continue;
        const double x = double(p.midNs - origin);
        const double y = double(p.offsetNs - offsetOrigin);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        first = std::min(first, p.midNs);
        last = std::max(last, p.midNs);
    }
    if (n < kMinFitProbes || last - first < kMinDriftSpanNs)
        return 0;
    const double denominator = n * sxx - sx * sx;
    if (!(denominator > 0))
        return 0;
    const double slope = (n * sxy - sx * sy) / denominator;
    return std::isfinite(slope) ? slope : 0;
}

ClockEstimate ClockEstimator::estimate(qint64 nowNs) const
{
    ClockEstimate e;
    e.host = m_host;
    if (m_probes.empty())
        return e;
    const double rho = drift();
    const double spread = std::fabs(rho) + kDriftAllowancePpm * 1e-6;
    const Probe* chosen = nullptr;
    double chosenBound = std::numeric_limits<double>::infinity();
    for (const Probe& p : m_probes) {
        const double bound = double(p.delayNs) / 2 + spread * double(std::llabs(nowNs - p.midNs));
        if (bound < chosenBound) {
            chosenBound = bound;
            chosen = &p;
        }
    }
    // Rounded outwards: a bound 1 ns too tight is a broken promise.
    e.offsetNs = chosen->offsetNs + qint64(std::llround(rho * double(nowNs - chosen->midNs)));
    e.uncertaintyNs = qint64(std::ceil(chosenBound)) + 2;
    e.driftPpm = rho * 1e6;
    e.bestRoundTripNs = chosen->delayNs;
    e.atNs = nowNs;
    e.probes = int(m_probes.size());
    return e;
}

void ClockEstimator::clear()
{
    m_probes.clear();
}
