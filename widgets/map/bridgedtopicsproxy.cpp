// SPDX-License-Identifier: MIT
#include "bridgedtopicsproxy.h"

#include <QFont>

BridgedTopicsProxy::BridgedTopicsProxy(int topicRole, QObject* parent)
    : QIdentityProxyModel(parent)
    , m_topicRole(topicRole)
{ }

void BridgedTopicsProxy::setBridged(const QHash<QString, QString>& topicToMapping)
{
    if (topicToMapping == m_bridged)
        return;
    m_bridged = topicToMapping;
    // Fonts of any row may change, at any depth of a tree; views repaint what they show.
    announceAll({});
}

void BridgedTopicsProxy::announceAll(const QModelIndex& parent)
{
    const int rows = rowCount(parent);
    if (rows == 0)
        return;
    emit dataChanged(index(0, 0, parent), index(rows - 1, columnCount(parent) - 1, parent),
                     {Qt::FontRole, Qt::ToolTipRole});
    for (int r = 0; r < rows; ++r)
        if (hasChildren(index(r, 0, parent)))
            announceAll(index(r, 0, parent));
}

QVariant BridgedTopicsProxy::data(const QModelIndex& index, int role) const
{
    if (role == Qt::FontRole || (role == Qt::ToolTipRole && index.column() <= 1)) {
        const auto it = m_bridged.constFind(QIdentityProxyModel::data(index, m_topicRole).toString());
        if (it != m_bridged.cend()) {
            if (role == Qt::ToolTipRole)
                return tr("Bridged: %1").arg(*it);
            QFont f;
            f.setBold(true);
            return f;
        }
    }
    return QIdentityProxyModel::data(index, role);
}
