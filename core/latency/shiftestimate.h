// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QtGlobal>
#include <vector>

/// How much one sample of latencies is shifted against another, with its uncertainty: the
/// Hodges–Lehmann estimate (the median of every difference y − x) and the distribution-free
/// confidence interval that goes with the Mann–Whitney test (order statistics of those
/// differences, normal approximation of the rank count, ties not corrected).
///
/// Robust where a mean is not: one 277 ms outlier among 40 samples moves the mean by 7 ms and the
/// shift hardly at all. Deterministic (no resampling); O((n + m) log) work and memory, the n·m
/// differences are never formed. Samples in a run are not independent, so the interval is a
/// lower bound of the true uncertainty.
struct ShiftEstimate
{
    static constexpr double kLevel = 0.95;
    double shiftMs = 0; ///< y − x
    double lowMs = 0;
    double highMs = 0;

    /// Whether the interval leaves out no shift at all.
    bool significant() const { return lowMs > 0 || highMs < 0; }

    /// `y` against `x` (values in units of `msPerUnit` ms); nullopt when they are too few for a
    /// 95 % interval (fewer than about 4 each).
    static std::optional<ShiftEstimate> of(std::vector<qint64> x, std::vector<qint64> y,
                                           double msPerUnit = 1e-6);
};
