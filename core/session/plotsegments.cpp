// SPDX-License-Identifier: MIT
#include "plotsegments.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace PlotSegments {

double gapSeconds(const QList<QPointF>& points)
{
    constexpr qsizetype kRecent = 256; // bounded work per field and redraw
    std::vector<double> intervals;
    for (qsizetype i = std::max<qsizetype>(1, points.size() - kRecent); i < points.size(); ++i)
        intervals.push_back(points[i].x() - points[i - 1].x());
    if (intervals.empty())
        return kMinGapSeconds;
    const auto middle = intervals.begin() + std::ptrdiff_t(intervals.size() / 2);
    std::nth_element(intervals.begin(), middle, intervals.end());
    return std::max(kMinGapSeconds, 3 * *middle);
}

namespace {
/// The points of one column of a run: its first, lowest, highest and last, by index.
struct Column
{
    qsizetype first = -1, low = -1, high = -1, last = -1;
    bool empty() const { return first < 0; }
    void add(const QList<QPointF>& points, qsizetype i)
    {
        if (empty())
            first = low = high = i;
        if (points[i].y() < points[low].y())
            low = i;
        if (points[i].y() > points[high].y())
            high = i;
        last = i;
    }
    /// Appends them in time order, each once, and starts the column anew.
    void flush(const QList<QPointF>& points, QList<QPointF>& out)
    {
        if (empty())
            return;
        qsizetype keep[] {first, low, high, last};
        std::sort(std::begin(keep), std::end(keep));
        for (std::size_t k = 0; k < std::size(keep); ++k)
            if (k == 0 || keep[k] != keep[k - 1])
                out.append(points[keep[k]]);
        *this = Column();
    }
};
} // namespace

QList<QList<QPointF>> visible(const QList<QPointF>& points, double left, double right, double gap,
                              int columns)
{
    QList<QList<QPointF>> runs;
    if (points.isEmpty() || !(right > left))
        return runs;
    const auto byX = [](const QPointF& p, double x) { return p.x() < x; };
    qsizetype first = std::lower_bound(points.cbegin(), points.cend(), left, byX) - points.cbegin();
    qsizetype last = std::lower_bound(points.cbegin(), points.cend(), right, byX) - points.cbegin();
    first = std::max<qsizetype>(0, first - 1);
    last = std::min(points.size() - 1, last);
    // Thinned only when there are more points than a few per column; fewer are drawn as they are.
    const bool thin = last - first + 1 > 4 * qsizetype(std::max(1, columns));
    const double width = (right - left) / std::max(1, columns);
    QList<QPointF> run;
    Column column;
    double columnIndex = 0;
    for (qsizetype i = first; i <= last; ++i) {
        const double c = std::floor((points[i].x() - left) / width);
        if (i > first && points[i].x() - points[i - 1].x() > gap) {
            column.flush(points, run);
            runs.append(run);
            run.clear();
        } else if (!column.empty() && (c != columnIndex || !thin)) {
            column.flush(points, run);
        }
        columnIndex = c;
        column.add(points, i);
    }
    column.flush(points, run);
    if (!run.isEmpty())
        runs.append(run);
    return runs;
}

} // namespace PlotSegments
