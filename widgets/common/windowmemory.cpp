// SPDX-License-Identifier: MIT
#include "windowmemory.h"

#include "widgets/common/viewsetup.h"

#include <memory>
#include <QEvent>
#include <QHeaderView>
#include <QLineEdit>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>

using namespace Qt::StringLiterals;

namespace {
bool isFilter(const QLineEdit* edit)
{
    return edit->objectName().endsWith(u"Filter"_s) || edit->objectName().endsWith(u"filter"_s);
}

/// The column headers (a view's row header holds nothing the user sets).
bool isColumnHeader(const QHeaderView* header)
{
    return header->orientation() == Qt::Horizontal;
}

/// Restores a splitter when it is first shown: before, it has not its final size (a page not
/// yet shown has none at all), and sizes restored then come out skewed.
class RestoreOnShow : public QObject
{
public:
    RestoreOnShow(QSplitter* splitter, QByteArray state)
        : QObject(splitter)
        , m_state(std::move(state))
    {
        splitter->installEventFilter(this);
    }

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Show) {
            static_cast<QSplitter*>(watched)->restoreState(m_state);
            watched->removeEventFilter(this);
            deleteLater();
        }
        return false;
    }

private:
    QByteArray m_state;
};
} // namespace

QString WindowMemory::keyOf(const QObject* object, const QObject* root)
{
    QStringList parts;
    for (const QObject* o = object; o && o != root; o = o->parent()) {
        if (!o->objectName().isEmpty()) {
            parts.prepend(o->objectName());
            continue;
        }
        // Unnamed: its class and its place among its parent's children of that class.
        int index = 0;
        if (const QObject* parent = o->parent())
            for (const QObject* sibling : parent->children()) {
                if (sibling == o)
                    break;
                index += qstrcmp(sibling->metaObject()->className(), o->metaObject()->className()) == 0;
            }
        parts.prepend(QString::fromLatin1(o->metaObject()->className()) + u'#' + QString::number(index));
    }
    return parts.join(u'/');
}

void WindowMemory::save(const QWidget* root, QSettings& settings, const QString& group)
{
    settings.beginGroup(group);
    settings.remove(QString()); // what is no longer there goes
    for (const QSplitter* s : root->findChildren<QSplitter*>())
        settings.setValue(u"splitters/"_s + keyOf(s, root), s->saveState());
    for (const QHeaderView* h : root->findChildren<QHeaderView*>())
        if (isColumnHeader(h) && h->count() > 0) {
            const QString key = u"headers/"_s + keyOf(h, root);
            settings.setValue(key + u"/state"_s, h->saveState());
            settings.setValue(key + u"/count"_s, h->count());
        }
    for (const QTabWidget* t : root->findChildren<QTabWidget*>())
        settings.setValue(u"tabs/"_s + keyOf(t, root), t->currentIndex());
    for (const QLineEdit* e : root->findChildren<QLineEdit*>())
        if (isFilter(e))
            settings.setValue(u"filters/"_s + keyOf(e, root), e->text());
    settings.endGroup();
}

void WindowMemory::restore(QWidget* root, QSettings& settings, const QString& group)
{
    settings.beginGroup(group);
    for (QSplitter* s : root->findChildren<QSplitter*>())
        if (const QVariant v = settings.value(u"splitters/"_s + keyOf(s, root)); v.isValid()) {
            s->setProperty(ViewSetup::RestoredProperty, true);
            if (s->isVisible())
                s->restoreState(v.toByteArray());
            else
                new RestoreOnShow(s, v.toByteArray());
        }
    for (QHeaderView* h : root->findChildren<QHeaderView*>()) {
        if (!isColumnHeader(h))
            continue;
        const QString key = u"headers/"_s + keyOf(h, root);
        const QByteArray state = settings.value(key + u"/state"_s).toByteArray();
        const int count = settings.value(key + u"/count"_s, -1).toInt();
        if (state.isEmpty() || count <= 0)
            continue;
        h->setProperty(ViewSetup::RestoredProperty, true); // ColumnFitter leaves it alone
        if (h->count() == count) {
            h->restoreState(state);
            continue;
        }
        // Its model has no columns yet: once it has the ones saved, they come back (once).
        auto connection = std::make_shared<QMetaObject::Connection>();
        *connection = QObject::connect(h, &QHeaderView::sectionCountChanged, h,
                                       [h, state, count, connection](int, int now) {
                                           if (now != count)
                                               return;
                                           QObject::disconnect(*connection);
                                           h->restoreState(state);
                                       });
    }
    // Not a tab hidden now: which ones show follows this session (Discover's ROS 2 tab in a ROS 1
    // session showed an empty list under "ROS graph: ROS 1").
    for (QTabWidget* t : root->findChildren<QTabWidget*>())
        if (const QVariant v = settings.value(u"tabs/"_s + keyOf(t, root));
            v.isValid() && v.toInt() >= 0 && v.toInt() < t->count() && t->isTabVisible(v.toInt()))
            t->setCurrentIndex(v.toInt());
    for (QLineEdit* e : root->findChildren<QLineEdit*>())
        if (isFilter(e))
            if (const QVariant v = settings.value(u"filters/"_s + keyOf(e, root)); v.isValid())
                e->setText(v.toString().left(1000));
    settings.endGroup();
}
