// SPDX-License-Identifier: MIT
#include "timelinechart.h"

#include "latency/latencytimeline.h"
#include "latency/palette.h"
#include "widgets/common/chartstyle.h"
#include "widgets/common/rowlegend.h"

#include <algorithm>
#include <QChart>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QEvent>
#include <QGraphicsRectItem>
#include <QLineSeries>
#include <QValueAxis>

using namespace Qt::StringLiterals;

namespace {
/// Seconds between time ticks: a round step that gives at most `wanted` ticks.
/// Ticks every `step` seconds from `from` to `to`, the ends on a step.
struct TimeTicks
{
    qint64 step = 1;
    qint64 from = 0;
    qint64 to = 0;
    int count() const { return int((to - from) / step) + 1; }
};

/// The finest round step whose ticks, the ends rounded out to it, are at most `wanted`: rounding
/// out adds up to a tick at each end, which would leave a label less room than its text.
TimeTicks timeTicks(qint64 first, qint64 last, int wanted)
{
    const auto at = [&](qint64 step) {
        const qint64 from = first - ((first % step) + step) % step;
        return TimeTicks {step, from, from + (last - from + step - 1) / step * step};
    };
    for (qint64 step : {1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200, 21600, 86400})
        if (const TimeTicks t = at(step); t.count() <= wanted)
            return t;
    // Stamps days apart (a clock that is not set): whole days, never thousands of ticks.
    return at(((last - first) / std::max(1, wanted - 2) / 86400 + 1) * 86400);
}
} // namespace

TimelineChart::TimelineChart(QWidget* parent)
    // Our chart from the start: QChartView(parent) makes a chart of its own, and setChart()
    // releases it without deleting it (LeakSanitizer found it behind every window).
    : QChartView(new QChart, parent)
    , m_mean(new QLineSeries)
    , m_max(new QLineSeries)
    , m_x(new QDateTimeAxis)
    , m_y(new QValueAxis)
{
    setObjectName(u"latencyTimeline"_s);
    QChart* chart = this->chart();
    chart->setMargins(QMargins(4, 4, 4, 4));
    const QColor color(seriesColor(0));
    m_mean->setName(tr("total, mean per second"));
    m_mean->setPen(QPen(color, 2));
    QColor light = color;
    light.setAlpha(140);
    m_max->setName(tr("highest per second"));
    m_max->setPen(QPen(light, 1.2));
    // The legend in rows, whole: QLegend cut both names to `highest …` and `total, m…` beside
    // the ECDF at 1280x800.
    m_legend = new RowLegend(chart);
    for (QLineSeries* s : {m_mean, m_max}) {
        auto* line = new QGraphicsRectItem(0, 0, 14, 3, chart);
        line->setBrush(s->pen().color());
        line->setPen(Qt::NoPen);
        m_legend->addEntry(line, s->name());
    }
    m_x->setObjectName(u"timeAxis"_s);
    m_y->setObjectName(u"latencyAxis"_s);
    chart->addAxis(m_x, Qt::AlignBottom);
    chart->addAxis(m_y, Qt::AlignLeft);
    for (QLineSeries* s : {m_max, m_mean}) {
        chart->addSeries(s);
        s->attachAxis(m_x);
        s->attachAxis(m_y);
    }
    m_x->setTitleText(tr("sample time"));
    m_y->setTitleText(tr("latency [ms]"));
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    refresh();
}

void TimelineChart::setTimeline(const LatencyTimeline* timeline)
{
    m_timeline = timeline;
    m_revision = ~quint64(0);
    refresh();
}

qsizetype TimelineChart::pointCount() const
{
    return m_mean->count();
}

void TimelineChart::refresh()
{
    const quint64 revision = m_timeline ? m_timeline->revision() : 0;
    if (revision == m_revision)
        return;
    m_revision = revision;
    QList<QPointF> mean;
    QList<QPointF> max;
    double top = 0;
    double bottom = 0; // a total between hosts whose clocks differ may be negative
    qint64 first = QDateTime::currentSecsSinceEpoch() - 60;
    qint64 last = first + 60;
    if (m_timeline && !m_timeline->buckets().empty()) {
        const auto& buckets = m_timeline->buckets();
        mean.reserve(qsizetype(buckets.size()));
        max.reserve(qsizetype(buckets.size()));
        for (const LatencyTimeline::Bucket& b : buckets) {
            const double at = double(b.second) * 1000 + 500; // the middle of its second
            mean.append(QPointF(at, b.meanNs() * 1e-6));
            max.append(QPointF(at, double(b.max) * 1e-6));
            top = std::max(top, double(b.max) * 1e-6);
            bottom = std::min(bottom, double(b.min) * 1e-6);
        }
        first = buckets.front().second;
        last = std::max(buckets.back().second + 1, first + 10);
    }
    m_mean->replace(mean);
    m_max->replace(max);
    m_first = first;
    m_last = last;
    fitTimeAxis();
    ChartStyle::setNiceRange(m_y, bottom, top > bottom ? top : bottom + 1, 5);
}

/// Time ticks on round seconds or minutes, the ends on a step, as many as the plot has room for
/// with their labels whole ("12:03:05" elided to "12:0…" tells nothing): again at every resize.
void TimelineChart::fitTimeAxis()
{
    const qint64 first = m_first;
    const qint64 last = m_last;
    const QFontMetrics labels(m_x->labelsFont());
    const qreal plot = chart()->plotArea().width() > 0 ? chart()->plotArea().width() : width() * 0.7;
    // Each label gets the plot's width over the ticks; room for its text and a gap.
    const int labelWidth = labels.horizontalAdvance(u"00:00:00"_s) + labels.horizontalAdvance(u"00"_s);
    const int wanted = std::clamp(int(plot) / std::max(1, labelWidth), 2, 7);
    const TimeTicks ticks = timeTicks(first, last, wanted);
    m_x->setRange(QDateTime::fromSecsSinceEpoch(ticks.from), QDateTime::fromSecsSinceEpoch(ticks.to));
    m_x->setTickCount(ticks.count());
    m_x->setFormat(ticks.step < 60 ? u"HH:mm:ss"_s : ticks.step < 86400 ? u"HH:mm"_s : u"yyyy-MM-dd"_s);
}

void TimelineChart::resizeEvent(QResizeEvent* event)
{
    QChartView::resizeEvent(event);
    fitTimeAxis();
}

void TimelineChart::changeEvent(QEvent* event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) {
        ChartStyle::apply(chart(), palette());
        m_legend->layOut(); // in the new text colour
    }
}
