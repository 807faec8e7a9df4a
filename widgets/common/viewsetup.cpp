// SPDX-License-Identifier: MIT
#include "viewsetup.h"

#include <QHeaderView>
#include <QTableView>
#include <QTreeView>

namespace ViewSetup {

void records(QTableView* view, int sortColumn)
{
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->verticalHeader()->hide();
    view->setWordWrap(false);
    view->setTextElideMode(Qt::ElideMiddle);
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 6);
    if (sortColumn >= 0) {
        view->setSortingEnabled(true);
        view->sortByColumn(sortColumn, Qt::AscendingOrder);
    }
}

void topicTree(QTreeView* view, int sortColumn)
{
    view->setUniformRowHeights(true);
    view->setSortingEnabled(true);
    view->sortByColumn(sortColumn, Qt::AscendingOrder);
}

void dragsCopies(QAbstractItemView* view)
{
    view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    view->setDragDropMode(QAbstractItemView::DragDrop);
    view->setDefaultDropAction(Qt::CopyAction);
    view->setDropIndicatorShown(true);
}

} // namespace ViewSetup
