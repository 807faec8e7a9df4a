// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QAbstractItemView>
#include <QCoreApplication>
#include <QDropEvent>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QTest>

/// What GUI tests do to item views: find rows, and drag between views as a real drag would.
namespace ViewHelpers {
/// The child of `parent` (any depth) of type W named `name`; stops the test naming what is missing
/// instead of letting it crash on a null pointer (tests find widgets by object name, issue 42).
template<typename W> W* named(const QObject& parent, const QString& name)
{
    W* w = parent.findChild<W*>(name);
    if (!w)
        qFatal("%s has no %s named %s", parent.metaObject()->className(), W::staticMetaObject.className(),
               qPrintable(name));
    return w;
}

/// The one child of `parent` (any depth) of type W; stops the test when there is none or more.
/// For containers the window memory keys by their class: a name would move where the sizes and
/// columns of everything inside them are saved (WindowMemory::keyOf), so they have none.
template<typename W> W* only(const QObject& parent)
{
    const QList<W*> found = parent.findChildren<W*>();
    if (found.size() != 1)
        qFatal("%s has %lld %s, not one", parent.metaObject()->className(), qlonglong(found.size()),
               W::staticMetaObject.className());
    return found.first();
}

/// The action `text` of the menu `menu` in `w`'s menu bar (accelerators ignored), or nullptr.
inline QAction* menuAction(QMainWindow& w, const QString& menu, const QString& text)
{
    for (QAction* top : w.menuBar()->actions()) {
        if (top->text().remove(u'&') != menu)
            continue;
        for (QAction* a : top->menu()->actions()) {
            if (a->text().remove(u'&') == text)
                return a;
        }
    }
    return nullptr;
}

/// The first index (column 0, any depth) whose `role` holds `name`.
inline QModelIndex find(QAbstractItemModel* model, const QString& name, int role,
                        const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        if (i.data(role).toString() == name)
            return i;
        const QModelIndex deeper = find(model, name, role, i);
        if (deeper.isValid())
            return deeper;
    }
    return {};
}

/// A drag from `from` (its model makes the MIME data, as in a real drag) dropped at `pos` of `to`.
inline void dragAndDrop(QAbstractItemView* from, const QModelIndexList& dragged, QAbstractItemView* to,
                        const QPoint& pos, Qt::DropActions actions = Qt::CopyAction | Qt::LinkAction)
{
    std::unique_ptr<QMimeData> data(from->model()->mimeData(dragged));
    QVERIFY(data);
    QDragEnterEvent enter(pos, actions, data.get(), Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(to->viewport(), &enter);
    QDragMoveEvent move(pos, actions, data.get(), Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(to->viewport(), &move);
    QVERIFY2(move.isAccepted(), "the view refused the drag");
    QDropEvent drop(QPointF(pos), actions, data.get(), Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(to->viewport(), &drop);
}

inline QPoint centre(QAbstractItemView* view, const QModelIndex& index)
{
    return view->visualRect(index).center();
}

/// Just above the bottom edge of the viewport, below every row.
inline QPoint below(QAbstractItemView* view)
{
    return QPoint(view->viewport()->width() / 2, view->viewport()->height() - 3);
}
} // namespace ViewHelpers
