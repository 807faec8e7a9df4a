// SPDX-License-Identifier: MIT
#pragma once

#include "widgets/common/namedelegate.h"

#include <QAbstractItemView>
#include <QChartView>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QRegularExpression>
#include <QStyleOptionViewItem>
#include <QTableView>
#include <QTreeView>
#include <QWidget>

/// What a user sees in every item view of a window, checked as a whole: issue 40's "a figure is
/// never elided, in any view, whatever was restored". No "when the view has room" escape: a figure
/// cell that shows less than its text is a problem, whatever the other columns take.
namespace ViewAudit {
/// A figure: digits with the signs, separators and units figures are written with ("12.3 ms",
/// "−9.86", "10.0 → 10.7 Hz", "50.0 %", "1.2 MB", "3/12"), and nothing else.
inline bool isFigure(const QString& text)
{
    static const QRegularExpression units(
        QStringLiteral("(ms|µs|msg/s|Hz|KiB|MiB|GiB|kB|KB|MB|GB|B/s|B|min|s|h)(?![A-Za-z])"));
    static const QRegularExpression figure(QStringLiteral("^[-−+±~≈<>→%/.,:()\\s\\d]*\\d[-−+±~≈<>→%/.,:()\\s\\d]*$"));
    QString t = text;
    t.remove(units);
    return !text.trimmed().isEmpty() && figure.match(t).hasMatch();
}

/// The width the view gives a cell of `column` for its text (a tree's first column less its
/// indentation at `depth`).
inline int cellRoom(QAbstractItemView* view, int column, int depth)
{
    if (auto* table = qobject_cast<QTableView*>(view))
        return table->columnWidth(column) - (table->showGrid() ? 1 : 0);
    if (auto* tree = qobject_cast<QTreeView*>(view)) {
        int room = tree->columnWidth(column);
        if (column == tree->header()->logicalIndex(0))
            room -= tree->indentation() * (depth + (tree->rootIsDecorated() ? 1 : 0));
        return room;
    }
    return view->viewport()->width();
}

inline bool columnHidden(QAbstractItemView* view, int column)
{
    if (auto* table = qobject_cast<QTableView*>(view))
        return table->isColumnHidden(column);
    if (auto* tree = qobject_cast<QTreeView*>(view))
        return tree->isColumnHidden(column);
    return column != 0;
}

/// Figures shown cut in `view`: "view: 'text' in column 'title' (N px, needs M)", a line each (at
/// most `limit`). Walks at most `maxRows` rows, expanded tree rows included.
inline QStringList elidedFigures(QAbstractItemView* view, int maxRows = 400, int limit = 5)
{
    QStringList problems;
    const QAbstractItemModel* model = view->model();
    if (!model || !view->isVisible())
        return problems;
    QStyleOptionViewItem option;
    option.initFrom(view->viewport());
    option.widget = view;
    option.font = view->font();
    option.fontMetrics = view->fontMetrics();
    auto* tree = qobject_cast<QTreeView*>(view);
    int walked = 0;
    std::function<void(const QModelIndex&, int)> walk = [&](const QModelIndex& parent, int depth) {
        for (int r = 0; r < model->rowCount(parent) && walked < maxRows && problems.size() < limit; ++r, ++walked) {
            for (int c = 0; c < model->columnCount(parent); ++c) {
                if (columnHidden(view, c))
                    continue;
                const QModelIndex index = model->index(r, c, parent);
                const QString text = index.data().toString();
                if (!isFigure(text) || qobject_cast<NameDelegate*>(view->itemDelegateForColumn(c)))
                    continue;
                const QAbstractItemDelegate* delegate = view->itemDelegateForIndex(index);
                if (!delegate)
                    continue;
                const int need = delegate->sizeHint(option, index).width();
                const int room = cellRoom(view, c, depth);
                if (need > room)
                    problems << QStringLiteral("%1: '%2' in column '%3' (%4 px, needs %5)")
                                    .arg(view->objectName(), text,
                                         model->headerData(c, Qt::Horizontal).toString())
                                    .arg(room)
                                    .arg(need);
            }
            const QModelIndex first = model->index(r, 0, parent);
            if (tree && tree->isExpanded(first))
                walk(first, depth + 1);
        }
    };
    walk({}, 0);
    return problems;
}

/// elidedFigures of every item view shown in `root`.
inline QStringList elidedFiguresIn(QWidget* root)
{
    QStringList problems;
    for (QAbstractItemView* view : root->findChildren<QAbstractItemView*>())
        if (view->isVisible() && !qobject_cast<QHeaderView*>(view)) // a header is a view of titles
            problems << elidedFigures(view);
    return problems;
}
/// Texts the charts shown in `root` draw cut: Qt Charts elides an axis label, axis title or
/// QLegend entry that has no room with "..." (`23:2...`, `highest ...`); "chart: 'text'" each.
inline QStringList elidedChartTexts(QWidget* root)
{
    QStringList problems;
    for (QChartView* view : root->findChildren<QChartView*>()) {
        if (!view->isVisible())
            continue;
        for (QGraphicsItem* item : view->scene()->items()) {
            if (!item->isVisible())
                continue;
            QString text;
            if (auto* rich = dynamic_cast<QGraphicsTextItem*>(item))
                text = rich->toPlainText();
            else if (auto* simple = dynamic_cast<QGraphicsSimpleTextItem*>(item))
                text = simple->text();
            if (text.endsWith(QStringLiteral("...")) || text.contains(QChar(0x2026)))
                problems << QStringLiteral("%1: '%2'").arg(view->objectName(), text);
        }
    }
    return problems;
}
} // namespace ViewAudit
