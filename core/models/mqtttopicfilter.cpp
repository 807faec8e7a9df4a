// SPDX-License-Identifier: MIT
#include "mqtttopicfilter.h"

#include "models/mqtttopictree.h"

MqttTopicFilter::MqttTopicFilter(QObject* parent)
    : QSortFilterProxyModel(parent)
{
    setRecursiveFilteringEnabled(true);
    setSortRole(MqttTopicTree::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
    // Live figures change every tick: re-sorting or re-filtering on each change would cost more
    // than the tick itself. Sorting by a figure re-sorts on demand (a header click).
    setDynamicSortFilter(false);
}

void MqttTopicFilter::setText(const QString& text)
{
    if (text == m_text)
        return;
    m_text = text;
    invalidateRowsFilter();
}

void MqttTopicFilter::setSearchPayloads(bool on)
{
    if (on == m_payloads)
        return;
    m_payloads = on;
    invalidateRowsFilter();
}

bool MqttTopicFilter::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const
{
    if (m_text.isEmpty())
        return true;
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    if (index.data(MqttTopicTree::FullTopicRole).toString().contains(m_text, Qt::CaseInsensitive))
        return true;
    return m_payloads
        && index.data(MqttTopicTree::SearchTextRole).toString().contains(m_text, Qt::CaseInsensitive);
}
