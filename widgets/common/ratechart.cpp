// SPDX-License-Identifier: MIT
#include "ratechart.h"

#include "widgets/common/chartstyle.h"

#include <algorithm>
#include <cmath>
#include <utility>
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
    m_x->setLabelFormat(QStringLiteral("%d"));
    m_x->setTickType(QValueAxis::TicksDynamic);
    m_x->setTickAnchor(0);
    m_y->setLabelFormat(QStringLiteral("%g"));
    m_y->setTickType(QValueAxis::TicksDynamic); // ticks on the round steps of scaleFor()
    m_y->setTickAnchor(0);
    chart->setMargins(QMargins(2, 2, 2, 2));
    setChart(chart);
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(160);
}

namespace {
/// The smallest of 1, 2, 2.5 and 5 times a power of ten that is at least `v` (> 0).
double roundStepAtLeast(double v)
{
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 2.5, 5.0})
        if (m * p >= v * (1 - 1e-9))
            return m * p;
    return 10 * p;
}

/// The shortest of a few familiar spans (seconds) that holds `seconds`, and its tick step.
std::pair<double, double> timeSpanFor(int seconds)
{
    static constexpr std::pair<double, double> spans[]
        = {{10, 5}, {20, 10}, {30, 10}, {60, 20}, {120, 30}, {300, 100}, {600, 200}, {1200, 300}, {3600, 1200}};
    for (const auto& s : spans)
        if (seconds <= s.first)
            return s;
    return {std::ceil(seconds / 600.0) * 600, 600};
}
} // namespace

RateChart::Scale RateChart::scaleFor(double bottom, double top)
{
    if (!(top > 0) && !(bottom < 0))
        return {0, 1, 0.25};
    // Three to six ticks on round steps, with a margin over the largest value.
    const double step = roundStepAtLeast(std::max(top, -bottom) * 1.1 / 5);
    return {bottom < 0 ? std::floor(bottom * 1.1 / step) * step : 0,
            top > 0 ? std::ceil(top * 1.1 / step) * step : 0, step};
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
    // Axes change only when their round range does: laying out an axis's labels costs more than
    // drawing the line, and a rate wobbling between 9.9 and 10.1 Hz keeps the same range.
    const auto [span, every] = timeSpanFor(n - 1);
    if (m_x->min() != -span) {
        m_x->setTickInterval(every);
        m_x->setRange(-span, 0);
    }
    const Scale y = scaleFor(bottom, top);
    if (y.step != m_y->tickInterval())
        m_y->setTickInterval(y.step);
    if (y.min != m_y->min() || y.max != m_y->max())
        m_y->setRange(y.min, y.max);
    m_y->setTitleText(unit);
}

void RateChart::changeEvent(QEvent* event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        ChartStyle::apply(chart(), palette());
}
