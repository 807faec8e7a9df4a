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
#include <QScrollBar>
#include <QStyle>
#include <QStyleOptionHeader>
#include <QStyleOptionViewItem>
#include <QTableView>
#include <QTreeView>

namespace {
/// Grows the columns towards their targets with what is left, evenly (water filling): the
/// narrowest deficits are met first, the rest shared by those that still want more.
void grow(QHash<int, int>& widths, const QList<int>& columns, const QHash<int, int>& targets, int& left)
{
    QList<int> wanting;
    for (int c : columns)
        if (targets.value(c) > widths.value(c))
            wanting << c;
    while (left > 0 && !wanting.isEmpty()) {
        const int each = std::max(1, left / int(wanting.size()));
        QList<int> still;
        for (int c : std::as_const(wanting)) {
            const int more = std::min({each, targets.value(c) - widths.value(c), left});
            widths[c] += more;
            left -= more;
            if (targets.value(c) > widths.value(c))
                still << c;
        }
        wanting = still;
    }
}
} // namespace

ColumnFitter::ColumnFitter(QTableView* view)
    : ColumnFitter(view, view->horizontalHeader())
{
}

ColumnFitter::ColumnFitter(QTreeView* view)
    : ColumnFitter(view, view->header())
{
}

ColumnFitter::ColumnFitter(QAbstractItemView* view, QHeaderView* header)
    : QObject(view)
    , m_view(view)
    , m_headerObject(header)
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
    // Rows moved (and the parents noted with them perhaps gone): every shown row is measured at
    // the next paint, new rows too (before the refit).
    const auto allShown = [this] { noteAllShownChanged(); };
    connect(model, &QAbstractItemModel::rowsAboutToBeInserted, this, allShown);
    connect(model, &QAbstractItemModel::rowsAboutToBeRemoved, this, allShown);
    connect(model, &QAbstractItemModel::modelAboutToBeReset, this, allShown);
    connect(model, &QAbstractItemModel::layoutAboutToBeChanged, this, allShown);
    connect(view->verticalScrollBar(), &QScrollBar::valueChanged, this, allShown);
    if (auto* tree = qobject_cast<QTreeView*>(view)) {
        connect(tree, &QTreeView::expanded, this, allShown);
        connect(tree, &QTreeView::collapsed, this, allShown);
    }
    // Changed cells matter in the fill columns (topics edited); in the figure columns where they
    // are painted (growToShownChanges), the other columns sharing the room anew once a kGrowMs
    // at most; not in the others, whose figures change every second (they would twitch).
    m_growTimer.setSingleShot(true);
    m_growTimer.setInterval(kGrowMs);
    connect(&m_growTimer, &QTimer::timeout, this, [this] {
        // Hidden: measured when shown (the viewport's Show event refits).
        if (!m_view->isVisible())
            return;
        // Sized by hand or restored: the figures grow all the same, the other columns stay.
        const bool grown = std::exchange(m_grown, false);
        if ((fitFigures(true) || grown) && !keepsWidths())
            fitTheRest(); // the fill and fitted columns share what is left
    });
    connect(model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex& from, const QModelIndex& to) {
                for (int c : std::as_const(m_fills))
                    if (c >= from.column() && c <= to.column())
                        m_timer.start();
                noteChanged(from, to);
            });
    // Sized by hand: a handle dragged or double-clicked. (A model's reset resizes sections too,
    // and is no reason to stop fitting.) Once the drag ends, what it cut is widened again.
    connect(header, &QHeaderView::sectionResized, this, [this](int column, int before, int now) {
        if (m_fitting)
            return;
        if (manages(column) && QGuiApplication::mouseButtons() != Qt::NoButton) {
            m_userSized = true;
            m_timer.start();
        } else if (before == 0 || now == 0) {
            m_timer.start(); // a column shown or hidden: the others share the room anew
        }
    });
    connect(header, &QHeaderView::sectionHandleDoubleClicked, this, [this] { m_userSized = true; });
    // WindowMemory marks the header before it restores it (perhaps later, when its columns come).
    header->installEventFilter(this);
    QWidget* viewport = view->viewport();
    m_viewport = viewport;
    viewport->installEventFilter(this);
}

QHeaderView* ColumnFitter::header() const
{
    // Asked each time: NameHeader::install() may put another header in place.
    if (auto* tree = qobject_cast<QTreeView*>(m_view))
        return tree->header();
    return static_cast<QTableView*>(m_view)->horizontalHeader();
}

int ColumnFitter::width(int column) const
{
    return header()->sectionSize(column);
}

void ColumnFitter::setWidth(int column, int width)
{
    header()->resizeSection(column, width);
}

bool ColumnFitter::isHidden(int column) const
{
    return header()->isSectionHidden(column);
}

bool ColumnFitter::keepsWidths() const
{
    return m_userSized || header()->property(ViewSetup::RestoredProperty).toBool();
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

void ColumnFitter::values(const QList<int>& columns)
{
    m_values = columns;
    m_timer.start();
}

void ColumnFitter::figures(const QList<int>& columns)
{
    m_figures = columns;
    for (int c : columns)
        header()->setSectionResizeMode(c, QHeaderView::Interactive);
    m_timer.start();
}

bool ColumnFitter::fitFigures(bool growOnly)
{
    const QScopedValueRollback fitting(m_fitting, true);
    bool changed = false;
    for (int c : std::as_const(m_figures)) {
        // Hidden ones too (a few cells each): shown again from a menu, they have their width.
        if (c >= header()->count())
            continue;
        const int need = needOf(c);
        if (need != width(c) && (!growOnly || need > width(c))) {
            setWidth(c, need);
            changed = true;
        }
    }
    return changed;
}

void ColumnFitter::noteChanged(const QModelIndex& from, const QModelIndex& to)
{
    // Bounded: past this many noted ranges, the shown rows are measured instead (a viewport's worth).
    constexpr int kMaxNoted = 64;
    if (std::none_of(m_figures.begin(), m_figures.end(),
                     [&](int c) { return c >= from.column() && c <= to.column(); }))
        return;
    if (!m_growTimer.isActive())
        m_growTimer.start(); // rows not shown yet, and the room shared anew
    if (m_allShownChanged)
        return;
    if (m_changed.size() >= kMaxNoted)
        noteAllShownChanged();
    else
        m_changed.append({from.parent(), from.row(), to.row(), from.column(), to.column()});
}

void ColumnFitter::noteAllShownChanged()
{
    m_changed.clear();
    m_allShownChanged = !m_figures.isEmpty();
}

bool ColumnFitter::growToShownChanges()
{
    if (m_changed.isEmpty() && !m_allShownChanged)
        return false;
    const QList<Changed> changed = std::exchange(m_changed, {});
    const bool all = std::exchange(m_allShownChanged, false);
    const QAbstractItemModel* model = m_view->model();
    QStyleOptionViewItem option;
    option.initFrom(m_view->viewport());
    option.widget = m_view;
    option.font = m_view->font();
    option.fontMetrics = m_view->fontMetrics();
    QHash<int, int> needs; // the widest changed cell shown, by column
    // The rows shown, top to bottom: a viewport's worth at most.
    const int height = m_view->viewport()->height();
    for (int y = 0; y < height;) {
        const QModelIndex shown = m_view->indexAt(QPoint(0, y));
        if (!shown.isValid())
            break;
        const QRect rect = m_view->visualRect(shown);
        y = std::max(y + 1, rect.bottom() + 1);
        const QModelIndex parent = shown.parent();
        for (int c : std::as_const(m_figures)) {
            if (c >= header()->count() || isHidden(c))
                continue;
            const auto holds = [&](const Changed& n) {
                return n.parent == parent && shown.row() >= n.first && shown.row() <= n.last
                    && c >= n.firstColumn && c <= n.lastColumn;
            };
            if (!all && std::none_of(changed.begin(), changed.end(), holds))
                continue;
            const QModelIndex index = model->index(shown.row(), c, parent);
            if (const QAbstractItemDelegate* delegate = m_view->itemDelegateForIndex(index))
                needs[c] = std::max(needs.value(c), delegate->sizeHint(option, index).width());
        }
    }
    const QScopedValueRollback fitting(m_fitting, true);
    bool grown = false;
    for (auto it = needs.cbegin(); it != needs.cend(); ++it)
        if (it.value() > width(it.key())) {
            setWidth(it.key(), it.value());
            grown = true;
        }
    if (grown) {
        m_grown = true;
        if (!m_growTimer.isActive())
            m_growTimer.start();
    }
    return grown;
}

bool ColumnFitter::eventFilter(QObject* watched, QEvent* event)
{
    // Compared with the viewport kept at construction: while the view is destroyed its viewport
    // still gets events, and the view is no longer one to ask (UBSan: a member call on a QWidget).
    // A figure is never painted cut: the changed cells about to be painted are measured first.
    if (watched == m_viewport && event->type() == QEvent::Paint)
        growToShownChanges();
    else if (watched == m_viewport && (event->type() == QEvent::Resize || event->type() == QEvent::Show)) {
        noteAllShownChanged(); // rows come into sight (figures changed while hidden)
        m_timer.start();
    } else if (watched == m_headerObject && event->type() == QEvent::DynamicPropertyChange)
        m_timer.start(); // restored: its widths are checked once they are back
    return QObject::eventFilter(watched, event);
}

bool ColumnFitter::manages(int column) const
{
    return m_fills.contains(column) || m_figures.contains(column) || m_values.contains(column)
        || std::any_of(m_fits.begin(), m_fits.end(), [column](const auto& f) { return f.first == column; });
}

int ColumnFitter::floorOf(int column) const
{
    auto* delegate = qobject_cast<NameDelegate*>(m_view->itemDelegateForColumn(column));
    return std::max(60, delegate ? delegate->tailWidth() : 0);
}

void ColumnFitter::apply()
{
    for (int c : std::as_const(m_figures)) // a header state saved by an older version may bring them back
        if (c < header()->count() && header()->sectionResizeMode(c) != QHeaderView::Interactive)
            header()->setSectionResizeMode(c, QHeaderView::Interactive);
    if (keepsWidths()) {
        // The user's (or the last session's) widths, where they are wide enough: what the last
        // session's figures and names needed is not what this one's need (1234 ms, not 4 ms).
        fitFigures(true);
        widenCutNames();
        return;
    }
    fitFigures(false);
    fitTheRest();
}

void ColumnFitter::widenCutNames()
{
    const QScopedValueRollback fitting(m_fitting, true);
    QList<int> names = m_fills + m_values;
    for (const auto& [column, share] : std::as_const(m_fits))
        names << column;
    int left = m_view->viewport()->width();
    for (int c = 0; c < header()->count(); ++c)
        if (!isHidden(c))
            left -= width(c);
    QHash<int, int> widths;
    QHash<int, int> needs;
    QList<int> cut;
    for (int c : std::as_const(names)) {
        if (c >= header()->count() || isHidden(c)
            || header()->sectionResizeMode(c) != QHeaderView::Interactive)
            continue;
        const int floor = floorOf(c);
        widths.insert(c, std::max(width(c), floor));
        left -= widths.value(c) - width(c);
        const int need = std::max(floor, needOf(c));
        if (need > widths.value(c)) {
            cut << c;
            needs.insert(c, need);
        }
    }
    // Room the columns leave empty is nobody's choice: it goes to the names still cut.
    if (left > 0 && !cut.isEmpty())
        grow(widths, cut, needs, left);
    for (auto it = widths.cbegin(); it != widths.cend(); ++it)
        if (it.value() != width(it.key()))
            setWidth(it.key(), it.value());
}

int ColumnFitter::titleWidth(const QHeaderView* header, int column)
{
    int width = header->sectionSizeHint(column);
    // Qt makes room for a sort indicator in every title; only the sorted column shows one (a
    // column sorted later is fitted again: sorting changes the layout).
    if (header->isSortIndicatorShown() && header->sortIndicatorSection() != column) {
        QStyleOptionHeader option;
        option.initFrom(header);
        width
            -= header->style()->sizeFromContents(QStyle::CT_HeaderSection, &option, QSize(), header).height()
            + header->style()->pixelMetric(QStyle::PM_HeaderMargin, &option, header);
    }
    return width;
}

int ColumnFitter::needOf(int column) const
{
    // The header's text counts too: a column whose title is cut is a cut column.
    return std::max(m_view->sizeHintForColumn(column), titleWidth(header(), column));
}


void ColumnFitter::fitTheRest()
{
    const QHeaderView* header = this->header();
    const QScopedValueRollback fitting(m_fitting, true);
    const int room = m_view->viewport()->width();
    const auto usable = [&](int column) {
        return !isHidden(column) && header->sectionResizeMode(column) == QHeaderView::Interactive;
    };
    QList<int> names; // the fill columns
    for (int c : std::as_const(m_fills))
        if (usable(c))
            names << c;
    QList<int> values; // the value columns: after the names and the fitted columns' shares
    for (int c : std::as_const(m_values))
        if (usable(c))
            values << c;
    QList<int> fitted;
    QHash<int, int> shares;
    for (const auto& [column, share] : std::as_const(m_fits))
        if (usable(column)) {
            fitted << column;
            shares.insert(column, int(room * share));
        }
    // What the other columns take; a Stretch column takes what the fitted ones leave. Columns
    // after the last value column are reached by scrolling: the room is shared before them.
    int lastShared = -1;
    for (int c : std::as_const(values))
        lastShared = std::max(lastShared, header->visualIndex(c));
    int left = room;
    QList<int> stretched;
    for (int c = 0; c < header->count(); ++c) {
        if (isHidden(c))
            continue;
        if (header->sectionResizeMode(c) == QHeaderView::Stretch)
            stretched << c;
        else if (!names.contains(c) && !fitted.contains(c) && !values.contains(c)
                 && (lastShared < 0 || header->visualIndex(c) < lastShared))
            left -= width(c);
    }
    QHash<int, int> needs;
    QHash<int, int> widths; // each floor once: a name column's walks every row
    int needed = 0;
    for (int c : names + fitted + values + stretched) {
        widths.insert(c, floorOf(c));
        needed += *needs.insert(c, std::max(widths.value(c), needOf(c)));
    }
    if (needed <= left) {
        // Room for every column's content: each gets it (shares are for when room is short, so
        // that no column is cut that the window has room for), the names (or else the values)
        // share what is over.
        const QList<int> wider = names.isEmpty() ? values : names;
        const int extra = wider.isEmpty() || !stretched.isEmpty() ? 0 : (left - needed) / int(wider.size());
        for (int c : names + fitted + values)
            setWidth(c, needs.value(c) + (wider.contains(c) ? extra : 0));
        return;
    }
    if (names.isEmpty() && stretched.isEmpty() && values.isEmpty()) {
        // Only fitted columns: each within its share of the view (a scroll bar rather than a
        // name cut to nothing), what the shares leave to those still cut.
        left = room;
        for (int c = 0; c < header->count(); ++c)
            if (!isHidden(c) && !fitted.contains(c))
                left -= width(c);
        for (int c : std::as_const(fitted)) {
            widths[c]
                = std::clamp(needs.value(c), widths.value(c), std::max(widths.value(c), shares.value(c)));
            left -= widths.value(c);
        }
        grow(widths, fitted, needs, left);
        for (int c : std::as_const(fitted))
            setWidth(c, widths.value(c));
        return;
    }
    // Short of room: every column its floor; then names before the rest: the names grow towards
    // their content, the fitted columns towards theirs within their shares, the values towards
    // theirs, then the fitted columns beyond their shares (a Stretch column takes whatever is left).
    for (int c : names + fitted + values + stretched)
        left -= widths.value(c);
    grow(widths, names + stretched, needs, left); // a Stretch column holds names too (the Map's topics)
    QHash<int, int> withinShare;
    for (int c : std::as_const(fitted))
        withinShare.insert(c, std::min(needs.value(c), std::max(widths.value(c), shares.value(c))));
    grow(widths, fitted, withinShare, left);
    grow(widths, values, needs, left);
    if (stretched.isEmpty())
        grow(widths, fitted, needs, left);
    for (int c : names + fitted + values)
        setWidth(c, widths.value(c));
}
