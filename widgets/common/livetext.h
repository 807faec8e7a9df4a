// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

/// A line of plain text that changes while it is shown (counters, a status), drawn without the
/// cost a QLabel has there: QLabel::setText() asks for a new layout every time, and a layout asks
/// its parent's, up to the window, whose tab widget then repaints the whole page (four times a
/// second for a counter of messages). This one asks for a layout only when the lines it needs
/// change (with word wrap), and otherwise repaints itself alone. The text is elided when it does
/// not fit (the whole of it is the tooltip) and can be copied (Ctrl+C, context menu).
class LiveText : public QWidget
{
    Q_OBJECT
public:
    explicit LiveText(QWidget* parent = nullptr);
    void setText(const QString& text);
    QString text() const { return m_text; }
    void setWordWrap(bool on);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override { return m_wrap; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QRect textRect(int width) const;
    QString m_text;
    bool m_wrap = false;
};
