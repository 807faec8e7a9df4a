// SPDX-License-Identifier: MIT
#pragma once

#include <QIdentityProxyModel>
#include <QSet>

/// Shows which discovered topics the open config bridges: in bold, with the mapping in the tooltip.
class BridgedTopicsProxy : public QIdentityProxyModel
{
    Q_OBJECT
public:
    BridgedTopicsProxy(int topicRole, QObject* parent = nullptr);
    void setBridged(const QHash<QString, QString>& topicToMapping);
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;

private:
    void announceAll(const QModelIndex& parent);
    int m_topicRole;
    QHash<QString, QString> m_bridged;
};
