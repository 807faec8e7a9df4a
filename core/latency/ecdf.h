// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QPointF>
#include <utility>

class LatencySeries;

/// Empirical distribution functions of a series' window, in ms.
class Ecdf
{
public:
    /// Every step: (value, fraction of values at most that value), one point per distinct value.
    static QList<QPointF> steps(const LatencySeries& series);

    /// The ECDF over [minMs, maxMs] for a plot `columns` pixels wide (columns equally spaced, in
    /// log space when `logScale`): per column with values, two points at its first value (the
    /// level before and after the column), so no step moves by more than one column. Exact where
    /// a column holds one distinct value. Costs O(columns · log n), whatever the window size.
    static QList<QPointF> reduced(const LatencySeries& series, double minMs, double maxMs, int columns,
                                  bool logScale = false);

    /// The values a linear axis shows, in ms: from the smallest to a high quantile (kShownQuantile,
    /// the nearest rank below) plus two fifths of that span as margin (a normal tail fits), or to
    /// the largest value when it lies within. One outlier does not stretch the axis; the figure
    /// marks what lies beyond.
    /// A series of fewer than kMinValuesToCut values is shown whole. {+inf, -inf} when empty.
    static std::pair<double, double> shownRange(const LatencySeries& series);
    /// Values of the series' window above `ms`.
    static qint64 countAbove(const LatencySeries& series, double ms);
    static constexpr double kShownQuantile = 0.99;
    static constexpr qint64 kMinValuesToCut = 20;
};
