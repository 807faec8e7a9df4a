// SPDX-License-Identifier: MIT
#include "ratechart.h"

#include "text/niceticks.h"
#include "widgets/common/chartstyle.h"

#include <algorithm>
#include <cmath>
#include <QChart>
#include <QEvent>
#include <QFontMetrics>
#include <QLineSeries>
#include <QValueAxis>

namespace {
/// The shortest of a few familiar spans (seconds) that holds `seconds`: the time axis keeps its
/// range for a while as the history grows, instead of changing every second.
double timeSpanFor(int seconds)
{
    for (const double span : {10.0, 20.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1200.0, 3600.0})
        if (seconds <= span)
            return span;
    return std::ceil(seconds / 600.0) * 600;
}
} // namespace

RateChart::RateChart(QWidget* parent)
    // Our chart from the start: QChartView(parent) makes a chart of its own, and setChart()
    // releases it without deleting it (LeakSanitizer found it behind every window).
    : QChartView(new QChart, parent)
    , m_series(new QLineSeries)
    , m_x(new QValueAxis)
    , m_y(new QValueAxis)
{
    QChart* chart = this->chart();
    chart->legend()->hide();
    chart->addSeries(m_series);
    chart->addAxis(m_x, Qt::AlignBottom);
    chart->addAxis(m_y, Qt::AlignLeft);
    m_series->attachAxis(m_x);
    m_series->attachAxis(m_y);
    m_x->setTitleText(tr("seconds ago"));
    chart->setMargins(QMargins(2, 2, 2, 2));
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    // The lowest the chart stays legible: below about eight lines Qt Charts draws the time axis's
    // labels and title as "..." (measured offscreen: whole at 125 px with 16 px labels, cut at 120).
    setMinimumHeight(8 * lineHeight());
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
    // Round ticks (0, 2.5, 5 … not 5.92, 8.88, 11.8), the axis ends on one above the data. The
    // axes are set only when their round range changes: laying out an axis's labels cost more than
    // drawing the line (perf, the Links page), and a rate wobbling between 9.9 and 10.1 Hz keeps
    // its range, as the time axis keeps a familiar span while the history grows.
    const double span = timeSpanFor(n - 1);
    if (m_x->min() != -span || m_x->max() != 0)
        ChartStyle::setRoundTicks(m_x, -span, 0);
    m_lo = bottom < 0 ? bottom * 1.05 : 0;
    m_hi = top > 0 ? top * 1.05 : (bottom < 0 ? 0 : 1);
    fitYAxis();
    m_y->setTitleText(unit);
}

void RateChart::fitYAxis()
{
    // Qt Charts gives each y label the plot's height over the tick count, less its padding
    // (VerticalAxis::updateGeometry), and draws one that does not fit as "...". The plot is the
    // view's height less about four and a half lines (margins, the time axis's labels and title:
    // 71 px of 125 with 16 px labels, measured offscreen); from the view's height, not from
    // QChart::plotAreaChanged, since a new range relays the chart out within setRange().
    const int line = lineHeight();
    const double room = height() - 4.5 * line;
    NiceTicks::Axis y = NiceTicks::axis(m_lo, m_hi, 2);
    for (int wanted = 5; wanted > 2; --wanted) {
        const NiceTicks::Axis a = NiceTicks::axis(m_lo, m_hi, wanted);
        if (a.tickCount() * (line + 6) <= room) {
            y = a;
            break;
        }
    }
    if (y.lo != m_y->min() || y.hi != m_y->max() || y.tickCount() != m_y->tickCount())
        ChartStyle::setNiceRange(m_y, y);
}

int RateChart::lineHeight() const
{
    return QFontMetrics(m_y->labelsFont()).height() + 2; // a label item's height: 16 px for 14
}

void RateChart::resizeEvent(QResizeEvent* event)
{
    QChartView::resizeEvent(event);
    fitYAxis();
}

void RateChart::changeEvent(QEvent* event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        ChartStyle::apply(chart(), palette());
}
