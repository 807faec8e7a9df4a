// SPDX-License-Identifier: MIT
#pragma once

#include <QList>

/// Axis ticks on round numbers, the same in every chart and report: steps of 1, 2, 2.5 or 5
/// times a power of ten, and axis ends on a step (so a tick is never at 11.8, 8.88 or 5.92).
namespace NiceTicks {
/// An axis: its ends, the step between ticks, and the decimals a label needs to show the step.
struct Axis
{
    double lo = 0;
    double hi = 1;
    double step = 0.2;
    int decimals = 1;
    /// The ticks, lo to hi.
    int tickCount() const;
};
/// The round step that divides [lo, hi] into about `wanted - 1` intervals (at most `wanted - 1`).
double step(double lo, double hi, int wanted = 6);
/// The decimals a label needs to show multiples of `step` exactly (2.5 → 1, 0.25 → 2, 50 → 0).
int decimals(double step);
/// An axis that covers [lo, hi] with ends on round steps; an empty range gets a unit around it.
Axis axis(double lo, double hi, int wanted = 6);
/// Round tick positions inside [lo, hi].
QList<double> ticks(double lo, double hi, int wanted = 6);
} // namespace NiceTicks
