// SPDX-License-Identifier: MIT
#include "mappingfilterproxy.h"

#include "config/mappingmodel.h"

MappingFilterProxy::MappingFilterProxy(QObject* parent)
    : QSortFilterProxyModel(parent)
{
    setSortRole(MappingModel::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
    setDynamicSortFilter(true);
}

void MappingFilterProxy::setText(const QString& text)
{
    m_text = text.trimmed();
    invalidateRowsFilter();
}

void MappingFilterProxy::setDirection(int direction)
{
    m_direction = direction;
    invalidateRowsFilter();
}

void MappingFilterProxy::setOnlyProblems(bool only)
{
    m_onlyProblems = only;
    invalidateRowsFilter();
}

bool MappingFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const
{
    const QAbstractItemModel* m = sourceModel();
    const QModelIndex first = m->index(sourceRow, 0, sourceParent);
    if (m_direction != AllDirections && first.data(MappingModel::DirectionRole).toInt() != m_direction)
        return false;
    if (m_onlyProblems && first.data(MappingModel::SeverityRole).toInt() < 0)
        return false;
    if (m_text.isEmpty())
        return true;
    for (int column :
         {MappingModel::RosTopicColumn, MappingModel::MqttTopicColumn, MappingModel::OptionsColumn}) {
        if (m->index(sourceRow, column, sourceParent).data().toString().contains(m_text, Qt::CaseInsensitive))
            return true;
    }
    return false;
}
