// SPDX-License-Identifier: MIT
#pragma once

#include "widgets/common/columnfitter.h"
#include "widgets/common/namedelegate.h"

#include <functional>
#include <QAbstractItemView>
#include <QFontMetrics>
#include <QHash>
#include <QHeaderView>
#include <QStyleOptionViewItem>
#include <QTableView>
#include <QTreeView>

/// Whether every row's name in `column` of `view` is shown as a text of its own that keeps the
/// name's last segment and fits the column, in the row's own font (bridged topics are bold).
/// Empty when so; otherwise what is wrong. For GUI tests (links the widgets).
inline QString namesShownProblem(QAbstractItemView* view, int column, int minimumRows)
{
    using namespace Qt::StringLiterals;
    auto* delegate = qobject_cast<NameDelegate*>(view->itemDelegateForColumn(column));
    if (!delegate)
        return view->objectName() + u": no NameDelegate"_s;
    const QAbstractItemModel* model = view->model();
    if (model->rowCount() < minimumRows)
        return u"%1: %2 rows"_s.arg(view->objectName()).arg(model->rowCount());
    auto* table = qobject_cast<QTableView*>(view);
    const int width = table ? table->columnWidth(column) : view->viewport()->width();
    QHash<QString, QString> nameOf;
    for (int r = 0; r < model->rowCount(); ++r) {
        const QModelIndex index = model->index(r, column);
        const QString name = index.data().toString();
        const QString shown = delegate->displayedText(index);
        const QVariant font = index.data(Qt::FontRole);
        const QFontMetrics fm(font.isValid() ? qvariant_cast<QFont>(font).resolve(view->font())
                                             : view->font());
        if (fm.horizontalAdvance(shown) > width)
            return u"%1: %2 wider than %3 px"_s.arg(view->objectName(), shown).arg(width);
        // The last segment, which tells names apart most often, is never cut.
        if (!shown.endsWith(name.section(u'/', -1)))
            return u"%1: %2 shows as %3"_s.arg(view->objectName(), name, shown);
        const QString other = nameOf.value(shown, name);
        if (other != name)
            return u"%1: %2 and %3 both show as %4"_s.arg(view->objectName(), name, other, shown);
        nameOf.insert(shown, name);
    }
    return {};
}

/// The style option a view's delegate gets for its cells (as NameDelegate::displayedText builds it).
inline QStyleOptionViewItem cellOption(QAbstractItemView* view)
{
    QStyleOptionViewItem option;
    option.initFrom(view->viewport());
    option.widget = view;
    option.font = view->font();
    option.fontMetrics = view->fontMetrics();
    return option;
}

/// The width a table's column needs for every row's text and its title, as ColumnFitter and
/// QHeaderView::ResizeToContents measure it.
inline int neededWidth(QTableView* view, int column)
{
    const QAbstractItemModel* model = view->model();
    const QStyleOptionViewItem option = cellOption(view);
    int width = ColumnFitter::titleWidth(view->horizontalHeader(), column);
    for (int r = 0; r < model->rowCount(); ++r) {
        const QModelIndex index = model->index(r, column);
        width = std::max(width,
                         view->itemDelegateForIndex(index)->sizeHint(option, index).width()
                             + (view->showGrid() ? 1 : 0));
    }
    return width;
}

/// "No column's text is cut when the window has room for it": when the widths every shown column
/// of `view` needs add up to no more than its viewport, no cell shows less than its text (a name
/// column shows its whole names, every other cell is as wide as its text). Empty when so, or when
/// the view has no such room; otherwise what is cut. `roomy`, when given, says whether it had room.
inline QString cutWithRoomProblem(QTableView* view, bool* roomy = nullptr)
{
    using namespace Qt::StringLiterals;
    const QAbstractItemModel* model = view->model();
    int needed = 0;
    QList<int> columns;
    for (int c = 0; c < model->columnCount(); ++c) {
        if (view->isColumnHidden(c))
            continue;
        columns << c;
        needed += neededWidth(view, c);
    }
    if (roomy)
        *roomy = needed <= view->viewport()->width();
    if (needed > view->viewport()->width())
        return {};
    const QStyleOptionViewItem option = cellOption(view);
    for (int c : std::as_const(columns)) {
        const QString title = model->headerData(c, Qt::Horizontal).toString();
        for (int r = 0; r < model->rowCount(); ++r) {
            const QModelIndex index = model->index(r, c);
            const QString text = index.data().toString();
            const int width = view->itemDelegateForIndex(index)->sizeHint(option, index).width();
            auto* names = qobject_cast<NameDelegate*>(view->itemDelegateForColumn(c));
            if ((names && names->displayedText(index) != text) || width > view->columnWidth(c))
                return u"%1: '%2' cut in column '%3' (%4 px, needs %5; all columns need %6 of %7 px)"_s
                    .arg(view->objectName(), names ? names->displayedText(index) : text, title)
                    .arg(view->columnWidth(c))
                    .arg(width)
                    .arg(needed)
                    .arg(view->viewport()->width());
        }
    }
    return {};
}

/// Whether every row of a tree (every depth, expanded) shows its own text in `column` whole, and
/// each NameDelegate column keeps its names' last segments within the column, in the row's font.
/// Empty when so; otherwise what is wrong. `minimumLeaves`: rows without children expected.
inline QString treeNamesShownProblem(QTreeView* view, int column, int minimumLeaves)
{
    using namespace Qt::StringLiterals;
    const QAbstractItemModel* model = view->model();
    const QStyleOptionViewItem option = cellOption(view);
    int leaves = 0;
    QString problem;
    std::function<void(const QModelIndex&)> walk = [&](const QModelIndex& parent) {
        for (int r = 0; r < model->rowCount(parent) && problem.isEmpty(); ++r) {
            const QModelIndex index = model->index(r, column, parent);
            const QModelIndex first = index.siblingAtColumn(0);
            if (model->hasChildren(first)) {
                if (!view->isExpanded(first)) {
                    problem = u"%1: %2 not expanded"_s.arg(view->objectName(), first.data().toString());
                    return;
                }
                walk(first);
            } else {
                ++leaves;
            }
            const QString text = index.data().toString();
            const int has = view->visualRect(index).width();
            auto* names = qobject_cast<NameDelegate*>(view->itemDelegateForColumn(column));
            const QString shown = names ? names->displayedText(index) : text;
            const QVariant font = index.data(Qt::FontRole);
            const QFontMetrics fm(font.isValid() ? qvariant_cast<QFont>(font).resolve(view->font())
                                                 : view->font());
            const int needs = names ? fm.horizontalAdvance(shown)
                                    : view->itemDelegateForIndex(index)->sizeHint(option, index).width();
            if (needs > has)
                problem
                    = u"%1: '%2' needs %3 px, has %4"_s.arg(view->objectName(), shown).arg(needs).arg(has);
            else if (!shown.endsWith(text.section(u'/', -1)))
                problem = u"%1: %2 shows as %3"_s.arg(view->objectName(), text, shown);
        }
    };
    walk({});
    if (problem.isEmpty() && leaves < minimumLeaves)
        problem = u"%1: %2 leaves"_s.arg(view->objectName()).arg(leaves);
    return problem;
}

/// "A figure is never elided": every cell of the figure `columns` of `view` (a table, or a tree's
/// rows under expanded levels) is as wide as its text needs, and so is each such column's title.
/// No escape when the view is short of room: a scroll bar, never a cut figure. Empty when so;
/// otherwise the first cut cell. Hidden columns are not shown, so not checked.
inline QString figuresCutProblem(QAbstractItemView* view, const QList<int>& columns)
{
    using namespace Qt::StringLiterals;
    auto* table = qobject_cast<QTableView*>(view);
    auto* tree = qobject_cast<QTreeView*>(view);
    QHeaderView* header = table ? table->horizontalHeader() : tree->header();
    const QAbstractItemModel* model = view->model();
    const QStyleOptionViewItem option = cellOption(view);
    const int grid = table && table->showGrid() ? 1 : 0;
    QList<QModelIndex> parents {QModelIndex()};
    int rows = 0;
    for (qsizetype p = 0; p < parents.size() && rows < 20000; ++p) {
        const QModelIndex parent = parents[p];
        for (int r = 0; r < model->rowCount(parent) && rows < 20000; ++r, ++rows) {
            const QModelIndex first = model->index(r, 0, parent);
            if (tree && tree->isExpanded(first))
                parents << first;
            for (int c : columns) {
                if (header->isSectionHidden(c))
                    continue;
                const QModelIndex index = model->index(r, c, parent);
                const QString text = index.data().toString();
                if (text.isEmpty())
                    continue;
                const int needs = view->itemDelegateForIndex(index)->sizeHint(option, index).width() + grid;
                if (needs > header->sectionSize(c))
                    return u"%1: '%2' cut in column '%3' (%4 px, needs %5)"_s
                        .arg(view->objectName(), text, model->headerData(c, Qt::Horizontal).toString())
                        .arg(header->sectionSize(c))
                        .arg(needs);
            }
        }
    }
    for (int c : columns)
        if (!header->isSectionHidden(c) && ColumnFitter::titleWidth(header, c) > header->sectionSize(c))
            return u"%1: title '%2' cut (%3 px, needs %4)"_s
                .arg(view->objectName(), model->headerData(c, Qt::Horizontal).toString())
                .arg(header->sectionSize(c))
                .arg(ColumnFitter::titleWidth(header, c));
    return {};
}
