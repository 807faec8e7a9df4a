// SPDX-License-Identifier: MIT
#include "ecdf.h"

#include "latency/latencyseries.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {
qint64 clampedUnits(double u)
{
    if (u >= 9.2e18)
        return std::numeric_limits<qint64>::max();
    if (u <= -9.2e18)
        return std::numeric_limits<qint64>::min();
    return qint64(u);
}

/// The smallest integer value not below `ms`: values below it are exactly the values below `ms`.
qint64 unitsCeil(double ms, double msPerUnit)
{
    return clampedUnits(std::ceil(ms / msPerUnit));
}

/// The largest integer value not above `ms`.
qint64 unitsFloor(double ms, double msPerUnit)
{
    return clampedUnits(std::floor(ms / msPerUnit));
}
} // namespace

std::pair<double, double> Ecdf::shownRange(const LatencySeries& series)
{
    const SortedBlocks& sorted = series.sorted();
    const qint64 n = sorted.size();
    if (n == 0)
        return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    const double lo = series.toMs(sorted.min());
    const double hi = series.toMs(sorted.max());
    if (n < kMinValuesToCut)
        return {lo, hi};
    const double q = series.toMs(sorted.at(qint64(std::floor(kShownQuantile * double(n - 1)))));
    const double edge = q + std::max({0.4 * (q - lo), 0.05 * std::abs(q), 1e-3});
    return {lo, std::min(hi, edge)};
}

qint64 Ecdf::countAbove(const LatencySeries& series, double ms)
{
    return series.sorted().size() - series.sorted().countAtMost(unitsFloor(ms, series.msPerUnit()));
}

QList<QPointF> Ecdf::steps(const LatencySeries& series)
{
    QList<QPointF> out;
    const SortedBlocks& sorted = series.sorted();
    const qint64 n = sorted.size();
    if (n == 0)
        return out;
    const std::vector<qint64> values = sorted.toVector();
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i + 1 < values.size() && values[i + 1] == values[i])
            continue;
        out.append(QPointF(series.toMs(values[i]), double(i + 1) / double(n)));
    }
    return out;
}

QList<QPointF> Ecdf::reduced(const LatencySeries& series, double minMs, double maxMs, int columns,
                             bool logScale)
{
    QList<QPointF> out;
    const SortedBlocks& sorted = series.sorted();
    const qint64 n = sorted.size();
    if (n == 0 || columns < 1 || !(maxMs > minMs) || (logScale && minMs <= 0))
        return out;
    const double perUnit = series.msPerUnit();
    const double dn = double(n);
    const double logMin = logScale ? std::log(minMs) : 0;
    const double logSpan = logScale ? std::log(maxMs) - logMin : 0;
    const auto boundary = [&](int c) {
        if (c >= columns)
            return maxMs;
        const double f = double(c) / double(columns);
        return logScale ? std::exp(logMin + f * logSpan) : minMs + f * (maxMs - minMs);
    };
    out.reserve(2 * columns + 2);
    qint64 before = sorted.countBelow(unitsCeil(minMs, perUnit));
    out.append(QPointF(minMs, double(before) / dn));
    for (int c = 0; c < columns; ++c) {
        // The last column includes its right edge; the others end just before it.
        const qint64 upTo = c + 1 == columns ? sorted.countAtMost(unitsFloor(maxMs, perUnit))
                                             : sorted.countBelow(unitsCeil(boundary(c + 1), perUnit));
        if (upTo <= before)
            continue;
        const double x = series.toMs(sorted.at(before));
        out.append(QPointF(x, double(before) / dn));
        out.append(QPointF(x, double(upTo) / dn));
        before = upTo;
    }
    out.append(QPointF(maxMs, double(before) / dn));
    return out;
}
