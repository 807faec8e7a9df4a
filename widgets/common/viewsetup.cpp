// SPDX-License-Identifier: MIT
#include "viewsetup.h"

#include <QEvent>
#include <QHeaderView>
#include <QSplitter>
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

namespace {
class SizesOnShow : public QObject
{
public:
    SizesOnShow(QSplitter* splitter, const QList<int>& sizes)
        : QObject(splitter)
        , m_sizes(sizes)
    {
        splitter->installEventFilter(this);
    }

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Show)
            return false;
        auto* splitter = static_cast<QSplitter*>(watched);
        if (!splitter->property(RestoredProperty).toBool()) {
            const int room
                = splitter->orientation() == Qt::Horizontal ? splitter->width() : splitter->height();
            qint64 sum = 0;
            for (int s : m_sizes)
                sum += s;
            if (room > 0 && sum > 0) {
                QList<int> scaled;
                for (int s : m_sizes)
                    scaled << int(qint64(s) * room / sum);
                splitter->setSizes(scaled);
            }
        }
        watched->removeEventFilter(this);
        deleteLater();
        return false;
    }

private:
    QList<int> m_sizes;
};
} // namespace

void initialSizes(QSplitter* splitter, const QList<int>& sizes)
{
    splitter->setSizes(sizes); // until it is shown
    new SizesOnShow(splitter, sizes);
}


bool hiddenInShownWindow(const QWidget* page)
{
    return !page->isVisible() && page->window()->isVisible();
}
} // namespace ViewSetup
