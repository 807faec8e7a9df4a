// SPDX-License-Identifier: MIT
#pragma once

#include <QChartView>

class LatencyTimeline;
class QDateTimeAxis;
class QLineSeries;
class QValueAxis;
class RowLegend;

/// Latency over wall-clock time, beside the ECDF: per second of the samples, the mean and the
/// highest total latency (a spike at 12:03 shows as one). Time ticks on round seconds or minutes,
/// ms ticks on round numbers. refresh() redraws only when the timeline moved.
class TimelineChart : public QChartView
{
    Q_OBJECT
public:
    explicit TimelineChart(QWidget* parent = nullptr);
    void setTimeline(const LatencyTimeline* timeline);
    void refresh();
    /// Points drawn (tests).
    qsizetype pointCount() const;

protected:
    void changeEvent(QEvent* event) override; ///< a new palette recolours it
    void resizeEvent(QResizeEvent* event) override; ///< as many time ticks as have room

private:
    void fitTimeAxis();

    const LatencyTimeline* m_timeline = nullptr;
    quint64 m_revision = ~quint64(0);
    QLineSeries* m_mean;
    QLineSeries* m_max;
    QDateTimeAxis* m_x;
    QValueAxis* m_y;
    RowLegend* m_legend;
    qint64 m_first = 0; ///< the seconds the time axis spans
    qint64 m_last = 60;
};
