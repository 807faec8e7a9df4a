// SPDX-License-Identifier: MIT
#pragma once

class QChart;
class QPalette;
class QValueAxis;
namespace NiceTicks {
struct Axis;
}

/// Charts in the colours of the widgets around them: background, text, axes and grid from the
/// palette (a dark theme gets a dark chart), the series keeping their own colours. Qt Charts'
/// themes would recolour the series too, so the brushes are set one by one.
namespace ChartStyle {
/// Applies `palette` to the chart and to the axes it has now.
void apply(QChart* chart, const QPalette& palette);
/// Shows [lo, hi] on `axis` with ticks on round numbers (NiceTicks), ends on a tick, and labels
/// with the decimals the step needs, the same for every label (10 and 7.5 as "10.0" and "7.5").
void setNiceRange(QValueAxis* axis, double lo, double hi, int wantedTicks = 6);
/// Shows the round axis `ticks` made (NiceTicks::axis) on `axis`.
void setNiceRange(QValueAxis* axis, const NiceTicks::Axis& ticks);
/// Shows exactly [lo, hi] on `axis` (a time window that must not grow) with ticks on the round
/// numbers inside it, at most about `wantedTicks`.
void setRoundTicks(QValueAxis* axis, double lo, double hi, int wantedTicks = 4);
/// Whether the palette is a dark one (its window darker than its text).
bool isDark(const QPalette& palette);
} // namespace ChartStyle
