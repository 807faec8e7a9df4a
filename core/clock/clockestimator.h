// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockestimate.h"

#include <deque>
#include <QString>
#include <QtGlobal>

/// A far host's clock offset from four-timestamp probes, NTP's way: each probe's offset
/// θ = ((t2 − t1) + (t3 − t4)) / 2 lies within half its round trip δ = (t4 − t1) − (t3 − t2) of
/// the truth at the probe's midpoint, whatever the two legs took; the drift ρ comes from a
/// least-squares line through the low-delay probes' offsets once they span kMinDriftSpanNs.
///
/// estimate(now) takes the probe whose bound is tightest at `now`:
///   offset = θ + ρ·(now − t), uncertainty = δ/2 + (|ρ| + kDriftAllowancePpm)·(now − t),
/// t the probe's midpoint on our clock. The true offset lies within it whenever every probe's two
/// legs took no negative time and the true drift stays within kDriftAllowancePpm (a quartz
/// oscillator's tolerance is ±20..50 ppm; a clock disciplined by chrony or PTP stays far below).
/// Bounded: the last kMaxProbes probes of the last kWindowNs.
class ClockEstimator
{
public:
    static constexpr int kMaxProbes = 256;
    static constexpr qint64 kWindowNs = 300'000'000'000LL; ///< five minutes
    static constexpr double kDriftAllowancePpm = 20;
    static constexpr qint64 kMinDriftSpanNs = 10'000'000'000LL;
    static constexpr qint64 kMaxRoundTripNs = 60'000'000'000LL; ///< longer probes are refused
    static constexpr qint64 kMaxOffsetNs = 366LL * 24 * 3600 * 1'000'000'000LL; ///< a year

    explicit ClockEstimator(QString host = {});

    /// Adds a probe: t1 and t4 on our clock, t2 and t3 on the far host's (ns since the epoch).
    /// False, and counted as refused, when a leg or the far host's processing took negative time,
    /// or a time is not plausible (before 1970, round trip or offset beyond the limits above).
    bool add(qint64 t1, qint64 t2, qint64 t3, qint64 t4);
    /// What is known at `nowNs` (our clock); invalid before the first probe.
    ClockEstimate estimate(qint64 nowNs) const;

    const QString& host() const { return m_host; }
    qint64 accepted() const { return m_accepted; }
    qint64 refused() const { return m_refused; }
    int size() const { return int(m_probes.size()); }
    void clear();

private:
    struct Probe
    {
        qint64 midNs; ///< (t1 + t4) / 2, our clock
        qint64 offsetNs; ///< θ
        qint64 delayNs; ///< δ
    };
    /// The drift (ns per ns) through the low-delay probes; 0 until they span kMinDriftSpanNs.
    double drift() const;

    QString m_host;
    std::deque<Probe> m_probes; ///< oldest first
    qint64 m_accepted = 0;
    qint64 m_refused = 0;
};
