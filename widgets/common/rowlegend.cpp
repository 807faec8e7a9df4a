// SPDX-License-Identifier: MIT
#include "rowlegend.h"

#include <algorithm>
#include <cmath>
#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QTextDocument>

RowLegend::RowLegend(QChart* chart)
    : QObject(chart)
    , m_chart(chart)
    , m_bottomMargin(chart->margins().bottom())
{
    chart->legend()->setVisible(false);
    connect(chart, &QGraphicsWidget::geometryChanged, this, &RowLegend::layOut);
}

int RowLegend::addEntry(QGraphicsItem* swatch, const QString& text)
{
    m_entries.push_back({swatch, new QGraphicsTextItem(text, m_chart)});
    layOut();
    return int(m_entries.size()) - 1;
}

void RowLegend::setText(int entry, const QString& text)
{
    QGraphicsTextItem* item = m_entries.at(std::size_t(entry)).text;
    if (item->toPlainText() == text)
        return;
    item->setPlainText(text);
    layOut();
}

QString RowLegend::text(int entry) const
{
    return m_entries.at(std::size_t(entry)).text->toPlainText();
}

void RowLegend::layOut()
{
    const QFont font = m_chart->legend()->font();
    const QColor colour = m_chart->legend()->labelColor();
    const QFontMetricsF fm(font);
    const qreal margin = 8;
    const qreal row = std::ceil(fm.height()) + 6;
    const qreal width = std::max<qreal>(60, m_chart->size().width() - 2 * margin);
    struct Placed
    {
        const Entry* entry;
        qreal x, y;
    };
    std::vector<Placed> placed;
    qreal x = 0;
    qreal y = 0;
    qreal rowBottom = 0;
    for (const Entry& e : m_entries) {
        const bool shown = !e.text->toPlainText().isEmpty();
        e.swatch->setVisible(shown);
        e.text->setVisible(shown);
        if (!shown)
            continue;
        e.text->setFont(font);
        e.text->setDefaultTextColor(colour);
        const qreal indent = e.swatch->boundingRect().width() + 4;
        e.text->setTextWidth(-1);
        if (indent + e.text->boundingRect().width() > width)
            e.text->setTextWidth(width - indent); // wrapped, never cut
        const qreal extent = indent + e.text->boundingRect().width();
        if (x > 0 && x + extent > width) {
            x = 0;
            y = rowBottom;
        }
        placed.push_back({&e, x, y});
        rowBottom = std::max(rowBottom, y + std::max(row, e.text->boundingRect().height()));
        x += extent + 12;
    }
    const int height = placed.empty() ? 0 : int(std::ceil(rowBottom)) + 4;
    const qreal top = m_chart->size().height() - height;
    for (const Placed& p : placed) {
        const qreal textHeight = fm.height() + 2 * p.entry->text->document()->documentMargin();
        const QRectF swatch = p.entry->swatch->boundingRect();
        p.entry->swatch->setPos(margin + p.x, top + p.y + (textHeight - swatch.height()) / 2);
        p.entry->text->setPos(margin + p.x + swatch.width() + 4, top + p.y);
    }
    if (height != m_height) {
        m_height = height;
        QMargins margins = m_chart->margins();
        margins.setBottom(m_bottomMargin + height);
        m_chart->setMargins(margins);
    }
}
