// SPDX-License-Identifier: MIT
#pragma once

#include "session/fieldplotter.h"

#include <QChartView>

class QLineSeries;
class QValueAxis;

/// Plotted fields over time: one line per field in its own colour, the legend naming topic and
/// field, the time axis in seconds showing the plotter's window.
class FieldPlotChart : public QChartView
{
    Q_OBJECT
public:
    explicit FieldPlotChart(QWidget* parent = nullptr);
    /// Replaces every line's points in one call each.
    void setSeries(const QList<PlotSeries>& series);
    const QList<QLineSeries*>& lines() const { return m_lines; }

protected:
    void changeEvent(QEvent* event) override; ///< a new palette recolours it
    void resizeEvent(QResizeEvent* event) override;

private:
    /// Each field's legend entry: its topic shortened to fit the entry's share, its field whole.
    QStringList legendNames(const QList<PlotField>& fields) const;
    void relabel();

    QList<PlotField> m_fields;
    QList<QLineSeries*> m_lines;
    QValueAxis* m_x;
    QValueAxis* m_y;
};
