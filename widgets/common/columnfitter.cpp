// SPDX-License-Identifier: MIT
#include "columnfitter.h"

#include "widgets/common/namedelegate.h"
#include "widgets/common/viewsetup.h"

#include <algorithm>
#include <QEvent>
#include <QGuiApplication>
#include <QHash>
#include <QHeaderView>
#include <QScopedValueRollback>
#include <QTableView>

ColumnFitter::ColumnFitter(QTableView* view)
    : QObject(view)
    , m_view(view)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(100);
    connect(&m_timer, &QTimer::timeout, this, &ColumnFitter::apply);
    const auto refit = [this] { m_timer.start(); };
    QAbstractItemModel* model = view->model();
    connect(model, &QAbstractItemModel::rowsInserted, this, refit);
    connect(model, &QAbstractItemModel::rowsRemoved, this, refit);
    connect(model, &QAbstractItemModel::modelReset, this, refit);
    connect(model, &QAbstractItemModel::layoutChanged, this, refit);
    // Changed cells matter in the fill columns (topics edited); in the figure columns once a
    // kGrowMs at most; not in the others, whose figures change every second (they would twitch).
    m_growTimer.setSingleShot(true);
    m_growTimer.setInterval(kGrowMs);
    connect(&m_growTimer, &QTimer::timeout, this, [this] {
        // Hidden: measured when shown (the viewport's Show event refits); sized by hand: the user's.
        const QHeaderView* header = m_view->horizontalHeader();
        if (!m_view->isVisible() || m_userSized || header->property(ViewSetup::RestoredProperty).toBool())
            return;
        if (fitFigures(true))
            fitTheRest(); // the fill and fitted columns share what is left
    });
    connect(model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex& from, const QModelIndex& to) {
                for (int c : std::as_const(m_fills))
                    if (c >= from.column() && c <= to.column())
                        m_timer.start();
                for (int c : std::as_const(m_figures))
                    if (c >= from.column() && c <= to.column() && !m_growTimer.isActive())
                        m_growTimer.start();
            });
    // Sized by hand: a handle dragged or double-clicked. (A model's reset resizes sections too,
    // and is no reason to stop fitting.)
    QHeaderView* header = view->horizontalHeader();
    connect(header, &QHeaderView::sectionResized, this, [this](int column) {
        if (!m_fitting && manages(column) && QGuiApplication::mouseButtons() != Qt::NoButton)
            m_userSized = true;
    });
    connect(header, &QHeaderView::sectionHandleDoubleClicked, this, [this] { m_userSized = true; });
    QWidget* viewport = view->viewport();
    m_viewport = viewport;
    viewport->installEventFilter(this);
}

void ColumnFitter::fit(int column, double share)
{
    m_fits.append({column, share});
    m_timer.start();
}

void ColumnFitter::fill(const QList<int>& columns)
{
    m_fills = columns;
    m_timer.start();
}

void ColumnFitter::figures(const QList<int>& columns)
{
    m_figures = columns;
    for (int c : columns)
        m_view->horizontalHeader()->setSectionResizeMode(c, QHeaderView::Interactive);
    m_timer.start();
}

bool ColumnFitter::fitFigures(bool growOnly)
{
    const QScopedValueRollback fitting(m_fitting, true);
    bool changed = false;
    for (int c : std::as_const(m_figures)) {
        // Hidden ones too (a few cells each): shown again from a menu, they have their width.
        // The header's own text counts, as with ResizeToContents.
        const int width = std::max(static_cast<QAbstractItemView*>(m_view)->sizeHintForColumn(c),
                                   m_view->horizontalHeader()->sectionSizeHint(c));
        if (width != m_view->columnWidth(c) && (!growOnly || width > m_view->columnWidth(c))) {
            m_view->setColumnWidth(c, width);
            changed = true;
        }
    }
    return changed;
}

bool ColumnFitter::eventFilter(QObject* watched, QEvent* event)
{
    // Compared with the viewport kept at construction: while the view is destroyed its viewport
    // still gets events, and the view is no longer one to ask (UBSan: a member call on a QWidget).
    if (watched == m_viewport && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
        m_timer.start();
    return QObject::eventFilter(watched, event);
}

bool ColumnFitter::manages(int column) const
{
    return m_fills.contains(column) || m_figures.contains(column)
        || std::any_of(m_fits.begin(), m_fits.end(), [column](const auto& f) { return f.first == column; });
}

int ColumnFitter::floorOf(int column) const
{
    auto* delegate = qobject_cast<NameDelegate*>(m_view->itemDelegateForColumn(column));
    return std::max(60, delegate ? delegate->tailWidth() : 0);
}

void ColumnFitter::apply()
{
    QHeaderView* header = m_view->horizontalHeader();
    for (int c : std::as_const(m_figures)) // a header state saved by an older version may bring them back
        if (c < header->count() && header->sectionResizeMode(c) != QHeaderView::Interactive)
            header->setSectionResizeMode(c, QHeaderView::Interactive);
    if (m_userSized || header->property(ViewSetup::RestoredProperty).toBool()) // the last session's
        return;
    fitFigures(false);
    fitTheRest();
}

void ColumnFitter::fitTheRest()
{
    const QHeaderView* header = m_view->horizontalHeader();
    const QScopedValueRollback fitting(m_fitting, true);
    const int room = m_view->viewport()->width();
    const auto usable = [&](int column) {
        return !m_view->isColumnHidden(column)
            && header->sectionResizeMode(column) == QHeaderView::Interactive;
    };
    // Each floor once: a name column's walks every row.
    QHash<int, int> floors;
    const auto floor = [&](int column) {
        auto it = floors.constFind(column);
        return it != floors.constEnd() ? *it : *floors.insert(column, floorOf(column));
    };
    QList<int> fills;
    int reserved = 0; // the fill columns' floors: names before figures
    for (int c : std::as_const(m_fills))
        if (usable(c)) {
            fills << c;
            reserved += floor(c);
        }
    int left = room - reserved;
    for (int c = 0; c < header->count(); ++c)
        if (!m_view->isColumnHidden(c) && (!manages(c) || m_figures.contains(c)))
            left -= m_view->columnWidth(c);
    // Fitted columns first, each within its share (and, beside fill columns, what they leave).
    for (const auto& [column, share] : std::as_const(m_fits)) {
        if (!usable(column))
            continue;
        const int least = floor(column);
        const int most
            = std::max(least, fills.isEmpty() ? int(room * share) : std::min(int(room * share), left));
        const int width
            = std::clamp(static_cast<QAbstractItemView*>(m_view)->sizeHintForColumn(column), least, most);
        m_view->setColumnWidth(column, width);
        left -= width;
    }
    if (fills.isEmpty())
        return;
    const int each = (left + reserved) / int(fills.size());
    for (int c : fills)
        m_view->setColumnWidth(c, std::max(floor(c), each));
}
