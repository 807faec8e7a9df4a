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

protected:
    void changeEvent(QEvent* event) override; ///< a new palette recolours it
    void resizeEvent(QResizeEvent* event) override; ///< fewer y labels when lower

private:
    /// The y axis's round range for [m_lo, m_hi], with as many ticks as the plot's height gives
    /// their labels room for: Qt Charts draws a label taller than its share of the axis as "...".
    void fitYAxis();
    int lineHeight() const; ///< of an axis label as Qt Charts draws it

    QLineSeries* m_series;
    QValueAxis* m_x;
    QValueAxis* m_y;
    double m_lo = 0;
    double m_hi = 1;
};
