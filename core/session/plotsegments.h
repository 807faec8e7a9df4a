// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QPointF>

/// What a chart draws of one field's points in a time range: runs of points joined by lines, split
/// where nothing arrived for longer than the field's gap, and thinned to a few points per pixel
/// column so that drawing costs the same for 100 or 500,000 points.
namespace PlotSegments {
/// Never a gap below this: a fast topic's jitter is no outage.
inline constexpr double kMinGapSeconds = 1.0;
/// The longest interval that still joins two points: three times the median interval of the last
/// few hundred points (how often the topic usually comes), at least kMinGapSeconds.
double gapSeconds(const QList<QPointF>& points);
/// The points of [left, right] (with one neighbour on each side, so lines reach the edges) as runs
/// without a gap (an interval above `gap`). More than four points per column are thinned to at
/// most the first, lowest, highest and last of each of `columns` columns of the range. `points` are
/// oldest first.
QList<QList<QPointF>> visible(const QList<QPointF>& points, double left, double right, double gap,
                              int columns);
} // namespace PlotSegments
