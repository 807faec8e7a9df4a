// SPDX-License-Identifier: MIT
#include "nameheader.h"

#include "widgets/common/namedelegate.h"

#include <QHelpEvent>
#include <QStyleOptionHeader>
#include <QTableView>
#include <QToolTip>

NameHeader::NameHeader(QWidget* parent)
    : QHeaderView(Qt::Horizontal, parent)
{ }

NameHeader* NameHeader::install(QTableView* table)
{
    if (auto* header = qobject_cast<NameHeader*>(table->horizontalHeader()))
        return header;
    QHeaderView* old = table->horizontalHeader();
    const QByteArray state = old->saveState();
    const bool clickable = old->sectionsClickable();
    auto* header = new NameHeader(table);
    table->setHorizontalHeader(header); // deletes the old one; keeps sorting as it was
    header->restoreState(state);
    header->setSectionsClickable(clickable);
    // setHorizontalHeader sorted by the new header's default indicator: sort as the old one did.
    if (table->isSortingEnabled())
        table->sortByColumn(header->sortIndicatorSection(), header->sortIndicatorOrder());
    return header;
}

QString NameHeader::strippedPrefix(int logicalIndex) const
{
    const auto* table = qobject_cast<const QTableView*>(parentWidget());
    const auto* delegate
        = table ? qobject_cast<const NameDelegate*>(table->itemDelegateForColumn(logicalIndex)) : nullptr;
    return delegate ? delegate->strippedPrefix() : QString();
}

QString NameHeader::title(int logicalIndex) const
{
    const QString text = model() ? model()->headerData(logicalIndex, orientation()).toString() : QString();
    const QString prefix = strippedPrefix(logicalIndex);
    return prefix.isEmpty() ? text : tr("%1 in %2").arg(text, prefix);
}

void NameHeader::initStyleOptionForIndex(QStyleOptionHeader* option, int logicalIndex) const
{
    QHeaderView::initStyleOptionForIndex(option, logicalIndex);
    if (const QString prefix = strippedPrefix(logicalIndex); !prefix.isEmpty()) {
        option->text = tr("%1 in %2").arg(option->text, prefix);
        option->textAlignment = Qt::AlignLeft | Qt::AlignVCenter;
        // Cut from the left when narrow: the prefix's end is what the rows continue (the whole
        // title is in the tooltip).
        const int margin = style()->pixelMetric(QStyle::PM_HeaderMargin, option, this);
        int room = sectionSize(logicalIndex) - 2 * margin;
        if (option->sortIndicator != QStyleOptionHeader::None)
            room -= style()->pixelMetric(QStyle::PM_HeaderMarkSize, option, this) + margin;
        // Measured bold: a section over selected rows is drawn bold (highlightSections).
        QFont bold = font();
        bold.setBold(true);
        option->text = QFontMetrics(bold).elidedText(option->text, Qt::ElideLeft, std::max(0, room));
    }
}

bool NameHeader::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const int section = logicalIndexAt(help->pos());
        if (section >= 0 && !strippedPrefix(section).isEmpty()) {
            QToolTip::showText(help->globalPos(), title(section), this);
            return true;
        }
    }
    return QHeaderView::viewportEvent(event);
}
