// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QString>

#include <vector>

class QChart;
class QGraphicsItem;
class QGraphicsTextItem;

/// A chart's legend in rows at its bottom: each entry a swatch and its whole text, left to right,
/// an entry wider than a row wrapped, never cut. QLegend elides what its one row cannot hold
/// (`object_detection…`, `highest …`), so the charts that show names hide it and use this. The
/// chart's bottom margin grows by the rows' height, so the plot gets what they leave. A child of
/// the chart: it lays itself out again when the chart's size changes.
class RowLegend : public QObject
{
    Q_OBJECT
public:
    explicit RowLegend(QChart* chart);
    /// An entry: `swatch` (drawn by the caller, a child of the chart) and `text`; an empty text
    /// hides the entry. Returns its index for setText().
    int addEntry(QGraphicsItem* swatch, const QString& text);
    void setText(int entry, const QString& text);
    QString text(int entry) const;
    /// Places the entries again in the chart's font and label colour (after a palette change).
    void layOut();
    /// The height the rows take (0 when no entry is shown).
    int height() const { return m_height; }

private:
    struct Entry
    {
        QGraphicsItem* swatch;
        QGraphicsTextItem* text;
    };
    QChart* m_chart;
    std::vector<Entry> m_entries;
    int m_height = 0;
    int m_bottomMargin; ///< the chart's own bottom margin, below the rows' height
};
