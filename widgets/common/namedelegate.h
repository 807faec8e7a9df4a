// SPDX-License-Identifier: MIT
#pragma once

#include "text/nameelider.h"

#include <QHash>
#include <QPointer>
#include <QStyledItemDelegate>

class QAbstractItemView;
class QLabel;

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
    /// The leading namespaces every row's name shares (`/benchmarking_suite/timestamps/`), when the
    /// column is too narrow for the widest full name: the rows then show the rest of their names,
    /// and the header (NameHeader) shows this prefix once. Empty when the rows show whole names.
    QString strippedPrefix() const;
    /// A list has no title: `label` (above it) says the prefix instead, `Stamp topics seen in
    /// /a/b/:`, its text otherwise as it is now.
    void setCaption(QLabel* label);
    /// The leading namespaces every row's name shares, ending with `/` (empty when none, or when
    /// the view has fewer than two rows).
    static QString sharedPrefix(const QStringList& names);

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
    /// The widest of the rows' names (`tails`: of their `…/last` forms) in their cells.
    int widest(bool tails) const;
    /// Whether a cell of this width strips the shared prefix: the widest full name does not fit.
    bool strips(int cellWidth) const;

    QAbstractItemView* m_view;
    int m_column;
    mutable NameElider m_elider;
    mutable bool m_stale = true;
    mutable QHash<QString, QString> m_shortened;
    mutable QStringList m_fullNames; ///< the rows' names, as the model has them
    mutable QString m_prefix; ///< sharedPrefix() of the rows' names
    mutable int m_widest = 0; ///< the width the widest full name needs in its cell
    void updateCaption() const;
    QPointer<QLabel> m_caption;
    QString m_captionText; ///< the label's own text
    mutable QString m_captionPrefix; ///< the prefix the label shows now
};
