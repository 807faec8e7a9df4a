// SPDX-License-Identifier: MIT
#include "fieldplotchart.h"

#include "base/nameelider.h"
#include "widgets/common/chartstyle.h"
#include "wire/fieldpath.h"

#include <algorithm>
#include <limits>
#include <QChart>
#include <QEvent>
#include <QFontMetrics>
#include <QLegend>
#include <QLineSeries>
#include <QValueAxis>

using namespace Qt::StringLiterals;

namespace {
// Apart on light and dark backgrounds alike (the categorical palette of matplotlib).
const QColor kColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                           QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};
} // namespace

FieldPlotChart::FieldPlotChart(QWidget* parent)
    : QChartView(parent)
    , m_x(new QValueAxis)
    , m_y(new QValueAxis)
{
    auto* chart = new QChart;
    chart->addAxis(m_x, Qt::AlignBottom);
    chart->addAxis(m_y, Qt::AlignLeft);
    chart->legend()->setAlignment(Qt::AlignBottom);
    m_x->setTitleText(tr("seconds"));
    m_x->setLabelFormat(QStringLiteral("%.4g"));
    m_y->setLabelFormat(QStringLiteral("%.4g"));
    m_x->setRange(0, 10);
    m_y->setRange(0, 1);
    chart->setMargins(QMargins(2, 2, 2, 2));
    setChart(chart);
    ChartStyle::apply(chart, palette());
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(160);
}

void FieldPlotChart::setSeries(const QList<PlotSeries>& series)
{
    while (m_lines.size() > series.size()) {
        QLineSeries* gone = m_lines.takeLast();
        chart()->removeSeries(gone);
        delete gone;
    }
    while (m_lines.size() < series.size()) {
        auto* line = new QLineSeries;
        chart()->addSeries(line);
        line->attachAxis(m_x);
        line->attachAxis(m_y);
        m_lines.append(line);
    }
    double left = std::numeric_limits<double>::max();
    double right = std::numeric_limits<double>::lowest();
    double bottom = std::numeric_limits<double>::max();
    double top = std::numeric_limits<double>::lowest();
    QList<PlotField> fields;
    for (const PlotSeries& s : series)
        fields << s.field;
    if (fields != m_fields) { // the legend is made again for new fields, not for new points
        m_fields = fields;
        relabel();
    }
    for (int i = 0; i < series.size(); ++i) {
        QLineSeries* line = m_lines[i];
        line->setColor(kColours[i % std::size(kColours)]);
        line->replace(series[i].points);
        for (const QPointF& p : series[i].points) {
            left = std::min(left, p.x());
            right = std::max(right, p.x());
            bottom = std::min(bottom, p.y());
            top = std::max(top, p.y());
        }
    }
    if (left > right)
        return; // no points yet: the axes stay
    m_x->setRange(std::max(left, right - FieldPlotter::kWindowSeconds), std::max(right, left + 10));
    m_x->applyNiceNumbers();
    const double pad = top > bottom ? (top - bottom) * 0.05 : std::max(1.0, std::abs(top) * 0.1);
    m_y->setRange(bottom - pad, top + pad);
    m_y->applyNiceNumbers();
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
    relabel(); // the entries' share of the width changed
}

void FieldPlotChart::relabel()
{
    const QStringList names = legendNames(m_fields);
    for (int i = 0; i < m_lines.size() && i < names.size(); ++i)
        if (m_lines[i]->name() != names[i])
            m_lines[i]->setName(names[i]);
}

QStringList FieldPlotChart::legendNames(const QList<PlotField>& fields) const
{
    // The legend shares the chart's width between its entries and cuts each at its end, which is
    // where the field is: topics give up their namespaces first (NameElider), the field stays.
    QStringList topics;
    for (const PlotField& f : fields)
        topics << f.topic;
    NameElider elider;
    elider.setNames(topics);
    const QFontMetrics fm(chart()->legend()->font());
    const int markers = 40; // the colour marker and the spacing of an entry
    const int room = std::max(60, width() / std::max<int>(1, int(fields.size())) - markers);
    QStringList names;
    for (const PlotField& f : fields) {
        const QString field = u": "_s + FieldPath::text(f.path);
        QString name;
        for (const QString& form : elider.forms(f.topic)) {
            name = form + field;
            if (fm.horizontalAdvance(name) <= room)
                break;
        }
        names << name;
    }
    return names;
}
