// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QPointF>

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
};
