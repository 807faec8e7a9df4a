// SPDX-License-Identifier: MIT
#pragma once

#include <QtGlobal>
#include <utility>
#include <vector>

/// The one definition of a quantile in Bridgescope: numpy's default ("linear"), interpolated
/// between the closest ranks. The Measure page's statistics (LatencySeries) and the Links page's
/// p50/p99 (LinkTraffic) both take theirs from here, so the same samples give the same figures.
namespace Quantile {
/// The virtual index q*(n-1) of the q-quantile (0..1) of n values: its lower rank in [0, n) and
/// the fraction towards the next rank.
std::pair<qint64, double> rank(qint64 n, double q);
/// numpy's lerp between the values of ranks k and k+1 at fraction t: exact at both ends.
double lerp(double atRank, double atNextRank, double t);
/// The q-quantile of unsorted `values` (reordered in place) in O(n); NaN when there are none.
double of(std::vector<double>& values, double q);
} // namespace Quantile
