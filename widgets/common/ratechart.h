// SPDX-License-Identifier: MIT
#pragma once

#include <QChartView>

class QLineSeries;
class QValueAxis;

/// A small line chart of a rate over the last minutes, one point per second.
class RateChart : public QChartView
{
    Q_OBJECT
public:
    explicit RateChart(QWidget* parent = nullptr);
    /// One value per second, oldest first; replaces the series in one call.
    void setSamples(const QList<double>& samples, const QString& unit);

    /// A value axis from `min` to `max` with ticks every `step`, a round number (1, 2, 2.5 or 5
    /// times a power of ten), holding `bottom` (<= 0) to `top` (>= 0) with a margin.
    struct Scale
    {
        double min = 0;
        double max = 1;
        double step = 0.25;
    };
    static Scale scaleFor(double bottom, double top);

protected:
    void changeEvent(QEvent* event) override; ///< a new palette recolours it

private:
    QLineSeries* m_series;
    QValueAxis* m_x;
    QValueAxis* m_y;
};
