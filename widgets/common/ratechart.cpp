// SPDX-License-Identifier: MIT
#include "ratechart.h"

#include "widgets/common/chartstyle.h"

#include <algorithm>
#include <QChart>
#include <QEvent>
#include <QLineSeries>
#include <QValueAxis>

RateChart::RateChart(QWidget* parent)
    : QChartView(parent)
    , m_series(new QLineSeries)
    , m_x(new QValueAxis)
    , m_y(new QValueAxis)
{
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->addSeries(m_series);
    chart->addAxis(m_x, Qt::AlignBottom);
    chart->addAxis(m_y, Qt::AlignLeft);
    m_series->attachAxis(m_x);
    m_series->attachAxis(m_y);
    m_x->setTitleText(tr("seconds ago"));
    chart->setMargins(QMargins(2, 2, 2, 2));
    setChart(chart);
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(160);
}

void RateChart::setSamples(const QList<double>& samples, const QString& unit)
{
    QList<QPointF> points;
    points.reserve(samples.size());
    double top = 0;
    double bottom = 0; // rates never go below 0; a latency between hosts whose clocks differ may
    const int n = int(samples.size());
    for (int i = 0; i < n; ++i) {
        points.append(QPointF(i - n + 1, samples[i]));
        top = std::max(top, samples[i]);
        bottom = std::min(bottom, samples[i]);
    }
    m_series->replace(points);
    // Round ticks (0, 2.5, 5 … not 5.92, 8.88, 11.8), the axis ends on one above the data.
    ChartStyle::setRoundTicks(m_x, std::min(-10, 1 - n), 0); // the window as it is, ticks on whole 5s, 20s…
    ChartStyle::setNiceRange(m_y, bottom < 0 ? bottom * 1.05 : 0, top > 0 ? top * 1.05 : (bottom < 0 ? 0 : 1), 5);
    m_y->setTitleText(unit);
}

void RateChart::changeEvent(QEvent* event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        ChartStyle::apply(chart(), palette());
}
