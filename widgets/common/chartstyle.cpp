// SPDX-License-Identifier: MIT
#include "chartstyle.h"

#include "text/niceticks.h"

#include <QAbstractAxis>
#include <QChart>
#include <QLegend>
#include <QPalette>
#include <QValueAxis>

bool ChartStyle::isDark(const QPalette& palette)
{
    return palette.color(QPalette::Window).lightness() < palette.color(QPalette::WindowText).lightness();
}

void ChartStyle::apply(QChart* chart, const QPalette& palette)
{
    const QColor text = palette.color(QPalette::Text);
    const QColor base = palette.color(QPalette::Base);
    QColor grid = palette.color(QPalette::Mid);
    grid.setAlpha(isDark(palette) ? 110 : 140);
    chart->setBackgroundBrush(base);
    chart->setBackgroundPen(Qt::NoPen);
    chart->setPlotAreaBackgroundVisible(false);
    chart->setTitleBrush(text);
    chart->legend()->setLabelColor(text);
    for (QAbstractAxis* axis : chart->axes()) {
        axis->setLabelsColor(text);
        axis->setTitleBrush(text);
        axis->setLinePenColor(palette.color(QPalette::Mid));
        axis->setGridLineColor(grid);
        axis->setMinorGridLineColor(grid.lighter(isDark(palette) ? 80 : 115));
    }
}

void ChartStyle::setNiceRange(QValueAxis* axis, double lo, double hi, int wantedTicks)
{
    setNiceRange(axis, NiceTicks::axis(lo, hi, wantedTicks));
}

void ChartStyle::setNiceRange(QValueAxis* axis, const NiceTicks::Axis& a)
{
    axis->setRange(a.lo, a.hi);
    axis->setTickType(QValueAxis::TicksFixed);
    axis->setTickCount(a.tickCount());
    axis->setLabelFormat(QStringLiteral("%.") + QString::number(a.decimals) + QStringLiteral("f"));
}

void ChartStyle::setRoundTicks(QValueAxis* axis, double lo, double hi, int wantedTicks)
{
    const double step = NiceTicks::step(lo, hi, wantedTicks);
    axis->setRange(lo, hi);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0);
    axis->setTickInterval(step);
    axis->setLabelFormat(QStringLiteral("%.") + QString::number(NiceTicks::decimals(step)) + QStringLiteral("f"));
}
