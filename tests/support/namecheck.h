// SPDX-License-Identifier: MIT
#pragma once

#include "widgets/common/namedelegate.h"

#include <QAbstractItemView>
#include <QFontMetrics>
#include <QHash>
#include <QTableView>

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
