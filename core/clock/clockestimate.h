// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QtGlobal>

/// What is known of a far host's clock, from four-timestamp probes (ClockEstimator): how far it is
/// ahead of ours, and how far that figure can be trusted.
///
/// `offsetNs` is the far clock minus ours at `atNs` (our clock). The true offset lies within
/// `uncertaintyNs` of it: half the best probe's round trip (a probe's two legs take no negative
/// time, so the offset lies within half its round trip of its midpoint), plus what the clock can
/// have drifted since that probe. A stamp of the far host minus one of ours is corrected by
/// subtracting `offsetNs`, and the corrected figure carries ± `uncertaintyNs`.
struct ClockEstimate
{
    QString host; ///< the far host's name (as the pipeline's `hosts:` names it)
    qint64 offsetNs = 0; ///< far clock minus ours
    qint64 uncertaintyNs = -1; ///< < 0: no estimate yet
    double driftPpm = 0; ///< far clock's rate minus ours, in parts per million (0 until measured)
    /// The round trip (the far host's processing excluded) of the probe the estimate rests on: the
    /// lowest-delay one, unless a later one gives the tighter bound by now (ClockEstimator).
    qint64 bestRoundTripNs = -1;
    qint64 atNs = 0; ///< our wall clock when the estimate holds (ns since the epoch)
    int probes = 0; ///< answered probes it rests on

    bool isValid() const { return uncertaintyNs >= 0; }

    /// The offset of `to` relative to `from`, both measured from the same prober: their
    /// difference, with the sum of their uncertainties. Invalid when either is.
    static ClockEstimate between(const ClockEstimate& from, const ClockEstimate& to);
};
