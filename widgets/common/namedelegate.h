// SPDX-License-Identifier: MIT
#pragma once

#include "base/nameelider.h"

#include <QHash>
#include <QStyledItemDelegate>

class QAbstractItemView;

/// Draws a column of names (topics, types) so that rows stay told apart when the column is narrow:
/// NameElider's shortenings over the names the view shows, the first that fits, and the full name
/// as a tooltip. Set it on a column with `NameDelegate::install(view, column)`.
class NameDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    NameDelegate(QAbstractItemView* view, int column);
    static NameDelegate* install(QAbstractItemView* view, int column);

    /// The text the cell shows at the view's current column width.
    QString displayedText(const QModelIndex& index) const;
    /// The column width below which a name would lose part of its last segment (`…/last`), the
    /// part that tells names apart most often: a column that fits itself stays at least this wide.
    int tailWidth() const;

    void paint(QPainter* painter, const QStyleOptionViewItem& option,
               const QModelIndex& index) const override;
    /// In a list, no wider than the view: names shorten instead of scrolling sideways.
    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    bool helpEvent(QHelpEvent* event, QAbstractItemView* view, const QStyleOptionViewItem& option,
                   const QModelIndex& index) override;

private:
    /// shorten(), kept per text, cell width and font (at most kMaxShortened of them).
    QString shortened(const QStyleOptionViewItem& option) const;
    QString shorten(const QStyleOptionViewItem& option) const;
    static constexpr qsizetype kMaxShortened = 4096;
    static constexpr qsizetype kMaxShortenedKey = 2048; ///< characters: at most 4096 × 2 × 2048 × 2 B kept
    void refreshNames() const;

    QAbstractItemView* m_view;
    int m_column;
    mutable NameElider m_elider;
    mutable bool m_stale = true;
    mutable QHash<QString, QString> m_shortened;
};
