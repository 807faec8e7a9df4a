// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

class LatencySeries;

/// Latency series that an ECDF chart draws, found by their SeriesId text. LatencyEngine is one
/// (the Measure page); LatencySeriesSet is the small one a probe keeps.
class EcdfSource
{
public:
    virtual ~EcdfSource() = default;
    /// The index of the series with `id`, -1 when there is none (yet). Stable while the layout
    /// revision stays; it also picks the series' colour.
    virtual int ecdfIndex(const QString& id) const = 0;
    virtual const LatencySeries& ecdfSeries(int index) const = 0;
    virtual QString ecdfLabel(int index) const = 0;
    /// Changes whenever series come or go, so that a chart knows to lay itself out again.
    virtual quint64 ecdfLayoutRevision() const = 0;
};
