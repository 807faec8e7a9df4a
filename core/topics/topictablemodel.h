// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicgraph.h"

#include <functional>
#include <QAbstractTableModel>
#include <QSet>

/// A ROS graph's topics (ROS 1 or ROS 2) as a table: name, type, publishers, subscribers, and for monitored
/// topics rate, bandwidth, size and the time since the last message.
///
/// A new graph is merged in row by row (inserts and removes, never a reset); checking the
/// Monitor column asks for a subscription through monitorRequested().
class TopicTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        MonitorColumn,
        TopicColumn,
        TypeColumn,
        PublishersColumn,
        SubscribersColumn,
        RateColumn,
        BandwidthColumn,
        SizeColumn,
        AgeColumn,
        ColumnCount
    };
    enum Role { TopicRole = Qt::UserRole + 1, TypeRole, SortRole, MonitoredRole };
    /// Handles MQTT topics dropped on a ROS topic (its name) or beside the topics (empty).
    using DropHandler = std::function<bool(const QMimeData* data, const QString& targetTopic)>;

    explicit TopicTableModel(QObject* parent = nullptr);

    void setGraph(const TopicGraph& graph);
    void setMonitorStats(const QHash<QString, TopicStats>& stats, qint64 nowNs);
    void setMonitored(const QString& topic, bool on);
    int monitoredCount() const { return int(m_monitored.size()); }
    void setDropHandler(DropHandler handler) { m_dropHandler = std::move(handler); }
    const TopicGraph& graph() const { return m_graph; }
    const TopicStats* stats(const QString& topic) const;
    int rowOf(const QString& topic) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    Qt::DropActions supportedDragActions() const override { return Qt::CopyAction | Qt::LinkAction; }
    Qt::DropActions supportedDropActions() const override
    {
        return Qt::CopyAction | Qt::LinkAction | Qt::MoveAction;
    }
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

signals:
    void monitorRequested(const QString& topic, bool on);

private:
    TopicGraph m_graph;
    QSet<QString> m_monitored;
    QHash<QString, TopicStats> m_stats;
    qint64 m_nowNs = 0;
    DropHandler m_dropHandler;
};
