// SPDX-License-Identifier: MIT
#include "namedelegate.h"

#include "widgets/common/nameheader.h"

#include <algorithm>
#include <optional>
#include <QAbstractItemView>
#include <QApplication>
#include <QHeaderView>
#include <QHelpEvent>
#include <QLabel>
#include <QTableView>
#include <QToolTip>

namespace {
/// Characters of a last segment measured at most (wider than any screen at any font).
constexpr qsizetype kTailCharacters = 400;

/// QCommonStyle's margin between an item's text rectangle and its text, on each side.
int textMargin(const QStyle* style, const QWidget* widget)
{
    return style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, widget) + 1;
}
} // namespace

NameDelegate::NameDelegate(QAbstractItemView* view, int column)
    : QStyledItemDelegate(view)
    , m_view(view)
    , m_column(column)
{
    // The names a view shows change with its rows and with a filter; re-read them when painted next.
    const auto stale = [this] { m_stale = true; };
    const auto watch = [this, stale](QAbstractItemModel* model) {
        if (!model)
            return;
        connect(model, &QAbstractItemModel::modelReset, this, stale);
        connect(model, &QAbstractItemModel::layoutChanged, this, stale);
        connect(model, &QAbstractItemModel::rowsInserted, this, stale);
        connect(model, &QAbstractItemModel::rowsRemoved, this, stale);
        connect(model, &QAbstractItemModel::dataChanged, this,
                [this](const QModelIndex& from, const QModelIndex& to, const QList<int>& roles) {
                    if (from.column() <= m_column && to.column() >= m_column
                        && (roles.isEmpty() || roles.contains(Qt::DisplayRole)))
                        m_stale = true;
                });
    };
    watch(view->model());
}

NameDelegate* NameDelegate::install(QAbstractItemView* view, int column)
{
    auto* delegate = new NameDelegate(view, column);
    view->setItemDelegateForColumn(column, delegate);
    if (auto* table = qobject_cast<QTableView*>(view))
        NameHeader::install(table); // the title shows the prefix the rows leave out
    return delegate;
}

void NameDelegate::refreshNames() const
{
    if (!m_stale)
        return;
    m_stale = false;
    QStringList names;
    const QAbstractItemModel* model = m_view->model();
    // Flat models only (tables): a tree's rows show one segment each and need no shortening.
    if (model) {
        const int rows = model->rowCount();
        names.reserve(rows);
        for (int r = 0; r < rows; ++r)
            names << model->index(r, m_column).data(Qt::DisplayRole).toString();
    }
    if (names == m_fullNames)
        return;
    m_fullNames = names;
    m_widest = widest(false);
    const QString prefix = sharedPrefix(names);
    if (prefix != m_prefix) {
        m_prefix = prefix;
        if (auto* table = qobject_cast<QTableView*>(m_view)) // its title shows the prefix
            table->horizontalHeader()->viewport()->update();
    }
    // The shortenings are those of the names without the prefix: it is shown once, in the header.
    if (!m_prefix.isEmpty())
        for (QString& name : names)
            name.remove(0, m_prefix.size());
    m_elider.setNames(names);
    m_shortened.clear();
}

QString NameDelegate::sharedPrefix(const QStringList& names)
{
    if (names.size() < 2)
        return {};
    // Bounded work: a prefix longer than this is not looked for (hostile names are kilobytes).
    constexpr qsizetype kMaxPrefix = 1000;
    QStringView shared = QStringView(names.first()).left(kMaxPrefix);
    for (const QString& name : names) {
        qsizetype n = 0;
        const qsizetype most = std::min(shared.size(), name.size());
        while (n < most && shared[n] == name[n])
            ++n;
        shared = shared.left(n);
    }
    // Whole namespaces only, and never a whole name (the rest of every name is not empty).
    shared = shared.left(shared.lastIndexOf(u'/') + 1);
    for (const QString& name : names)
        if (name.size() == shared.size())
            return {};
    // A lone `/` tells nothing: every ROS name starts with it.
    return shared.size() > 1 ? shared.toString() : QString();
}

bool NameDelegate::strips(int cellWidth) const
{
    return !m_prefix.isEmpty() && m_widest > cellWidth;
}

void NameDelegate::setCaption(QLabel* label)
{
    m_caption = label;
    m_captionText = label->text();
    // A longer caption gives way (cut at the pane's edge, whole in its tooltip), never widens the pane.
    label->setSizePolicy(QSizePolicy::Ignored, label->sizePolicy().verticalPolicy());
    m_captionPrefix.clear();
}

void NameDelegate::updateCaption() const
{
    if (!m_caption)
        return;
    const QString prefix = strippedPrefix();
    if (prefix == m_captionPrefix)
        return;
    m_captionPrefix = prefix;
    // `Stamp &topics seen:` becomes `Stamp &topics seen in /a/b/:`.
    QString text = m_captionText;
    if (!prefix.isEmpty()) {
        const bool colon = text.endsWith(u':');
        if (colon)
            text.chop(1);
        text = tr("%1 in %2").arg(text, prefix) + (colon ? QStringLiteral(":") : QString());
    }
    m_caption->setText(text);
    m_caption->setToolTip(prefix.isEmpty() ? QString() : tr("Every name below starts with %1").arg(prefix));
}

QString NameDelegate::strippedPrefix() const
{
    refreshNames();
    auto* table = qobject_cast<QTableView*>(m_view);
    return strips(table ? table->columnWidth(m_column) : m_view->viewport()->width()) ? m_prefix : QString();
}

QString NameDelegate::shortened(const QStyleOptionViewItem& option) const
{
    const QString& text = option.text;
    if (text.isEmpty())
        return text;
    refreshNames(); // the forms depend on the other names: a change of them empties the cache
    updateCaption();
    // Painting a cell again (30 times a second on a live page) lays out its text again, and the
    // style's text rectangle lays it out once more: the result is kept per cell width and font.
    const QString key = text + QChar(0) + QString::number(option.rect.width()) + QChar(0)
        + QString::number(int(option.features)) + QChar(0) + option.font.key();
    if (key.size() > kMaxShortenedKey) // a name longer than any screen: not kept (memory stays bounded)
        return shorten(option);
    if (const auto it = m_shortened.constFind(key); it != m_shortened.constEnd())
        return *it;
    if (m_shortened.size() >= kMaxShortened)
        m_shortened.clear();
    return *m_shortened.insert(key, shorten(option));
}

QString NameDelegate::shorten(const QStyleOptionViewItem& option) const
{
    const QString& text = option.text;
    const QStyle* style = option.widget ? option.widget->style() : QApplication::style();
    // The room QCommonStyle gives the text: the text rectangle less the focus frame's margins.
    const int margin = textMargin(style, option.widget);
    const int room
        = style->subElementRect(QStyle::SE_ItemViewItemText, &option, option.widget).width() - 2 * margin;
    const QFontMetrics& fm = option.fontMetrics;
    if (!strips(option.rect.width()) && fm.horizontalAdvance(text) <= room)
        return text;
    const QString rest
        = strips(option.rect.width()) && text.startsWith(m_prefix) ? text.mid(m_prefix.size()) : text;
    if (fm.horizontalAdvance(rest) <= room)
        return rest;
    const QStringList forms = m_elider.forms(rest);
    for (const QString& form : forms)
        if (fm.horizontalAdvance(form) <= room)
            return form;
    return fm.elidedText(forms.last(), Qt::ElideMiddle, room);
}

QString NameDelegate::displayedText(const QModelIndex& index) const
{
    QStyleOptionViewItem option;
    option.initFrom(m_view->viewport());
    option.widget = m_view;
    option.font = m_view->font();
    option.fontMetrics = m_view->fontMetrics();
    if (auto* table = qobject_cast<QTableView*>(m_view)) // rows scrolled out of sight too
        option.rect = QRect(0, 0, table->columnWidth(index.column()), table->rowHeight(index.row()));
    else
        option.rect = m_view->visualRect(index);
    initStyleOption(&option, index);
    return shortened(option);
}

int NameDelegate::tailWidth() const
{
    return widest(true);
}

int NameDelegate::widest(bool tails) const
{
    const QAbstractItemModel* model = m_view->model();
    if (!model)
        return 0;
    // In the row's own font: bridged topics are bold, and wider.
    const QFontMetrics plain = m_view->fontMetrics();
    std::optional<QFont> lastFont;
    std::optional<QFontMetrics> lastMetrics;
    int widest = 0;
    for (int r = 0, rows = model->rowCount(); r < rows; ++r) {
        const QModelIndex index = model->index(r, m_column);
        const QString name = index.data(Qt::DisplayRole).toString();
        const qsizetype slash = tails ? name.lastIndexOf(u'/') : -1;
        // Bounded work per row: a hostile name is measured no further than a screen.
        const QString shown = tails
            ? (slash < 0 ? name : QStringLiteral("…") + name.mid(slash)).left(kTailCharacters)
            : NameElider::elideTail(name, kTailCharacters);
        const QVariant font = index.data(Qt::FontRole);
        const QFontMetrics* fm = &plain;
        if (font.isValid()) {
            const QFont f = qvariant_cast<QFont>(font).resolve(m_view->font());
            if (lastFont != f) {
                lastFont = f;
                lastMetrics.emplace(f);
            }
            fm = &*lastMetrics;
        }
        widest = std::max(widest, fm->horizontalAdvance(shown));
    }
    if (widest == 0)
        return 0;
    // The style's text margin around the text rectangle, and shortened()'s own inside it.
    return widest + 4 * textMargin(m_view->style(), m_view) + 2;
}

void NameDelegate::paint(QPainter* painter, const QStyleOptionViewItem& option,
                         const QModelIndex& index) const
{
    QStyleOptionViewItem shown = option;
    initStyleOption(&shown, index);
    shown.text = shortened(shown);
    const QStyle* style = option.widget ? option.widget->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &shown, painter, option.widget);
}

QSize NameDelegate::sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const
{
    QSize size = QStyledItemDelegate::sizeHint(option, index);
    if (!qobject_cast<QTableView*>(m_view)) {
        size.setWidth(std::min(size.width(), m_view->viewport()->width()));
        return size;
    }
    // In a table, the width at which the whole name shows: shortened() keeps a margin of its own
    // inside the style's (as tailWidth() and the prefix's test count it).
    QStyleOptionViewItem shown = option;
    initStyleOption(&shown, index);
    const int whole = shown.fontMetrics.horizontalAdvance(NameElider::elideTail(shown.text, kTailCharacters))
        + 4 * textMargin(m_view->style(), m_view) + 2;
    size.setWidth(std::max(size.width(), whole));
    return size;
}

bool NameDelegate::helpEvent(QHelpEvent* event, QAbstractItemView* view, const QStyleOptionViewItem& option,
                             const QModelIndex& index)
{
    // The model's own tooltip first; otherwise the whole name when the cell shows less of it.
    if (event->type() == QEvent::ToolTip && !index.data(Qt::ToolTipRole).isValid()) {
        QStyleOptionViewItem shown = option;
        initStyleOption(&shown, index);
        if (shortened(shown) != shown.text) {
            QToolTip::showText(event->globalPos(), shown.text, view);
            return true;
        }
    }
    return QStyledItemDelegate::helpEvent(event, view, option, index);
}
