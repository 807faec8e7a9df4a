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

private:
    QLineSeries* m_series;
    QValueAxis* m_x;
    QValueAxis* m_y;
};
