// SPDX-License-Identifier: MIT
#include "fieldplotchart.h"

#include "session/plotsegments.h"
#include "widgets/common/chartstyle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <QChart>
#include <QEvent>
#include <QKeyEvent>
#include <QLegend>
#include <QLineSeries>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QValueAxis>
#include <QWheelEvent>

using namespace Qt::StringLiterals;

namespace {
// Apart on light and dark backgrounds alike (the categorical palette of matplotlib).
const QColor kColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                           QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};
constexpr double kMinSpan = 0.01; // seconds: closer than this, points are apart by more than the view
constexpr double kZoomStep = 0.8; // a wheel notch or a + shows this share of the time
} // namespace

FieldPlotChart::FieldPlotChart(QWidget* parent)
    // Our chart from the start: QChartView(parent) makes a chart of its own, and setChart()
    // releases it without deleting it (LeakSanitizer found it behind every window).
    : QChartView(new QChart, parent)
    , m_x(new QValueAxis)
    , m_y(new QValueAxis)
{
    QChart* chart = this->chart();
    m_x->setObjectName(u"timeAxis"_s);
    chart->addAxis(m_x, Qt::AlignBottom);
    chart->addAxis(m_y, Qt::AlignLeft);
    chart->legend()->hide(); // the list of plotted fields is the legend: it has room for whole names
    m_x->setTitleText(tr("seconds"));
    m_x->setLabelFormat(QStringLiteral("%.4g"));
    m_y->setLabelFormat(QStringLiteral("%.4g"));
    m_x->setRange(0, 10);
    m_y->setRange(0, 1);
    chart->setMargins(QMargins(2, 2, 2, 2));
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(160);
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(tr("Wheel or + and - zoom the time, drag or Left and Right move it; double-click or "
                  "Home follows the newest values again."));
}

QColor FieldPlotChart::colour(int field)
{
    return kColours[std::size_t(field) % std::size(kColours)];
}

QList<QLineSeries*> FieldPlotChart::runs(int field) const
{
    QList<QLineSeries*> out;
    if (field < 0 || field >= m_fields.size())
        return out;
    for (QLineSeries* run : m_fields[field].runs)
        if (run->count() > 0)
            out << run;
    return out;
}

QLineSeries* FieldPlotChart::addLine(int field)
{
    auto* line = new QLineSeries;
    chart()->addSeries(line);
    line->attachAxis(m_x);
    line->attachAxis(m_y);
    line->setColor(colour(field));
    return line;
}

void FieldPlotChart::setSeries(const QList<PlotSeries>& series, double nowSeconds)
{
    m_series = series;
    m_now = nowSeconds;
    while (m_fields.size() > series.size()) {
        Field gone = m_fields.takeLast();
        for (QLineSeries* run : std::as_const(gone.runs)) {
            chart()->removeSeries(run);
            delete run;
        }
        if (gone.dots) {
            chart()->removeSeries(gone.dots);
            delete gone.dots;
        }
    }
    while (m_fields.size() < series.size()) {
        Field f;
        f.runs << addLine(int(m_fields.size()));
        m_fields.append(f);
    }
    m_lines.clear();
    for (int i = 0; i < m_fields.size(); ++i) {
        m_lines << m_fields[i].runs.first();
        if (m_lines[i]->name() != series[i].label)
            m_lines[i]->setName(series[i].label);
    }
    redraw();
}

void FieldPlotChart::setBufferSeconds(double seconds)
{
    m_buffer = seconds;
    redraw();
}

void FieldPlotChart::setFollowing(bool following)
{
    if (m_following == following)
        return;
    m_following = following;
    chart()->setTitle(following
                          ? QString()
                          : tr("Zoomed or moved: double-click or press Home to follow the newest values"));
    emit followingChanged(following);
}

void FieldPlotChart::follow()
{
    setFollowing(true);
    redraw();
}

void FieldPlotChart::zoom(double factor, double anchor)
{
    double left = m_x->min();
    double right = m_x->max();
    const double span = std::clamp((right - left) * factor, kMinSpan, double(FieldPlotter::kMaxSeconds));
    const double share = right > left ? std::clamp((anchor - left) / (right - left), 0.0, 1.0) : 0.5;
    left = anchor - share * span;
    m_left = left;
    m_right = left + span;
    setFollowing(false);
    redraw();
}

void FieldPlotChart::pan(double seconds)
{
    m_left = m_x->min() + seconds;
    m_right = m_x->max() + seconds;
    setFollowing(false);
    redraw();
}

void FieldPlotChart::redraw()
{
    double oldest = std::numeric_limits<double>::max();
    double newest = std::numeric_limits<double>::lowest();
    for (const PlotSeries& s : std::as_const(m_series)) {
        if (!s.points.isEmpty()) {
            oldest = std::min(oldest, s.points.first().x());
            newest = std::max(newest, s.points.last().x());
        }
    }
    double left = m_left;
    double right = m_right;
    if (m_following) {
        if (oldest > newest) {
            left = 0;
            right = 10;
        } else {
            right = std::max(m_now, newest);
            left = std::max(oldest, right - m_buffer);
            right = std::max(right, left + std::min(10.0, m_buffer));
        }
    }
    m_x->setRange(left, right);

    const int columns = std::max(1, int(chart()->plotArea().width()));
    double bottom = std::numeric_limits<double>::max();
    double top = std::numeric_limits<double>::lowest();
    for (int i = 0; i < m_fields.size(); ++i) {
        Field& f = m_fields[i];
        const QList<QPointF>& points = m_series[i].points;
        const QList<QList<QPointF>> runs
            = PlotSegments::visible(points, left, right, PlotSegments::gapSeconds(points), columns);
        QList<QPointF> dots;
        QList<const QList<QPointF>*> lines;
        for (const QList<QPointF>& run : runs) {
            for (const QPointF& p : run) {
                if (p.x() >= left && p.x() <= right) {
                    bottom = std::min(bottom, p.y());
                    top = std::max(top, p.y());
                }
            }
            if (run.size() == 1)
                dots += run;
            else
                lines << &run;
        }
        // The newest runs are lines; older ones past kMaxRuns are dots, never joined across a gap.
        while (lines.size() > kMaxRuns)
            dots += *lines.takeFirst();
        while (f.runs.size() < std::max<qsizetype>(1, lines.size()))
            f.runs << addLine(i);
        while (f.runs.size() > std::max<qsizetype>(1, lines.size())) {
            QLineSeries* gone = f.runs.takeLast();
            chart()->removeSeries(gone);
            delete gone;
        }
        for (int r = 0; r < f.runs.size(); ++r) {
            f.runs[r]->setColor(colour(i));
            if (r < lines.size())
                f.runs[r]->replace(*lines[r]);
            else
                f.runs[r]->clear();
        }
        if (!dots.isEmpty() && !f.dots) {
            f.dots = new QScatterSeries;
            chart()->addSeries(f.dots);
            f.dots->attachAxis(m_x);
            f.dots->attachAxis(m_y);
            f.dots->setMarkerSize(5);
            f.dots->setBorderColor(Qt::transparent);
        }
        if (f.dots) {
            f.dots->setColor(colour(i));
            f.dots->replace(dots);
        }
    }
    if (bottom > top)
        return; // nothing in view: the value axis stays
    const double pad = top > bottom ? (top - bottom) * 0.05 : std::max(1.0, std::abs(top) * 0.1);
    m_y->setRange(bottom - pad, top + pad);
    m_y->applyNiceNumbers();
}

double FieldPlotChart::timeAt(const QPointF& viewPos) const
{
    const QPointF inChart = chart()->mapFromScene(mapToScene(viewPos.toPoint()));
    if (!chart()->plotArea().contains(inChart))
        return (m_x->min() + m_x->max()) / 2;
    return chart()->mapToValue(inChart).x();
}

void FieldPlotChart::wheelEvent(QWheelEvent* event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0) {
        QChartView::wheelEvent(event);
        return;
    }
    zoom(std::pow(kZoomStep, notches), timeAt(event->position()));
    event->accept();
}

void FieldPlotChart::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QChartView::mousePressEvent(event);
        return;
    }
    m_dragFrom = event->position();
    m_dragLeft = m_x->min();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
}

void FieldPlotChart::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_dragFrom) {
        QChartView::mouseMoveEvent(event);
        return;
    }
    const double width = std::max(1.0, double(chart()->plotArea().width()));
    const double seconds = (m_dragFrom->x() - event->position().x()) / width * (m_x->max() - m_x->min());
    if (seconds != 0)
        pan(m_dragLeft + seconds - m_x->min());
    event->accept();
}

void FieldPlotChart::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_dragFrom && event->button() == Qt::LeftButton) {
        m_dragFrom.reset();
        unsetCursor();
        event->accept();
        return;
    }
    QChartView::mouseReleaseEvent(event);
}

void FieldPlotChart::mouseDoubleClickEvent(QMouseEvent* event)
{
    m_dragFrom.reset();
    unsetCursor();
    follow();
    event->accept();
}

void FieldPlotChart::keyPressEvent(QKeyEvent* event)
{
    const double span = m_x->max() - m_x->min();
    const double middle = (m_x->min() + m_x->max()) / 2;
    switch (event->key()) {
    case Qt::Key_Home:
        follow();
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoom(kZoomStep, middle);
        break;
    case Qt::Key_Minus:
        zoom(1 / kZoomStep, middle);
        break;
    case Qt::Key_Left:
        pan(-span / 10);
        break;
    case Qt::Key_Right:
        pan(span / 10);
        break;
    default:
        QChartView::keyPressEvent(event);
        return;
    }
    event->accept();
}

void FieldPlotChart::changeEvent(QEvent* event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        ChartStyle::apply(chart(), palette());
}

void FieldPlotChart::resizeEvent(QResizeEvent* event)
{
    QChartView::resizeEvent(event);
    redraw(); // as many points as the plot has columns
}
