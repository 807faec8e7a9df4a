// SPDX-License-Identifier: MIT
#include "livetext.h"

#include <QClipboard>
#include <QContextMenuEvent>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QKeySequence>
#include <QMenu>
#include <QPainter>

namespace {
/// At most this many characters are laid out: a status is short; what is longer is the tooltip's.
constexpr qsizetype kMaxShown = 2000;
} // namespace

LiveText::LiveText(QWidget* parent)
    : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    setFocusPolicy(Qt::ClickFocus); // for Ctrl+C
    // Opaque: a new text repaints this widget alone, not the parents beneath it up to the window.
    setAutoFillBackground(true);
}

void LiveText::setText(const QString& text)
{
    if (text == m_text)
        return;
    const int before = m_wrap ? heightForWidth(width()) : 0;
    m_text = text;
    setToolTip(text.size() > 80 ? text.left(kMaxShown) : QString());
    if (m_wrap && heightForWidth(width()) != before)
        updateGeometry(); // a line more or less: the layout's business
    update();
}

void LiveText::setWordWrap(bool on)
{
    m_wrap = on;
    QSizePolicy policy = sizePolicy();
    policy.setHeightForWidth(on);
    setSizePolicy(policy);
    updateGeometry();
}

QRect LiveText::textRect(int width) const
{
    return fontMetrics().boundingRect(QRect(0, 0, std::max(1, width), 100000),
                                      Qt::TextWordWrap | Qt::AlignLeft, m_text.left(kMaxShown));
}

int LiveText::heightForWidth(int width) const
{
    return std::max(fontMetrics().height(), textRect(width).height());
}

QSize LiveText::sizeHint() const
{
    return {fontMetrics().averageCharWidth() * 40, fontMetrics().height()};
}

QSize LiveText::minimumSizeHint() const
{
    return {fontMetrics().averageCharWidth() * 12, fontMetrics().height()};
}

void LiveText::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setPen(palette().color(QPalette::WindowText));
    const QString shown = m_text.left(kMaxShown);
    if (m_wrap) {
        p.drawText(rect(), Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, shown);
        return;
    }
    p.drawText(rect(), Qt::AlignLeft | Qt::AlignVCenter, fontMetrics().elidedText(shown, Qt::ElideRight, width()));
}

void LiveText::contextMenuEvent(QContextMenuEvent* event)
{
    QMenu menu;
    menu.addAction(tr("&Copy"), this, [this] { QGuiApplication::clipboard()->setText(m_text); });
    menu.exec(event->globalPos());
}

void LiveText::keyPressEvent(QKeyEvent* event)
{
    if (event->matches(QKeySequence::Copy)) {
        QGuiApplication::clipboard()->setText(m_text);
        return;
    }
    QWidget::keyPressEvent(event);
}
