// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topictablemodel.h"

#include <functional>
#include <memory>
#include <QAbstractItemModel>
#include <QHash>
#include <QPointer>
#include <vector>

/// The ROS graph's topics as a namespace tree over a TopicTableModel, as rqt and MQTT Explorer show
/// names: a row per namespace (`timestamps/`) with its namespaces and topics below, each row
/// showing its own segment, so that a deep name is read down the tree instead of being cut in
/// a column. The other columns are the table's for topics (the type by its last segment, whole in
/// its tooltip), empty for namespaces.
///
/// Follows the table row by row (its inserts and removes become inserts and removes here, never
/// a reset but for a new table), and its figures' changes. A dragged row carries its topic, a namespace every
/// topic below it; MQTT topics dropped on a row go to the DropHandler with that row's name.
class TopicTree : public QAbstractItemModel
{
    Q_OBJECT
public:
    /// The tree's columns (the table's of the same name).
    enum Column { TopicColumn, TypeColumn, PublishersColumn, ColumnCount };
    /// The table's data roles (TopicRole, TypeRole, …) hold for topic rows; these for every row.
    enum Role {
        /// A row's full name: a topic's name, or a namespace's with its trailing slash ("/a/b/").
        PathRole = TopicTableModel::MonitoredRole + 16,
        IsTopicRole,
    };
    /// Where MQTT topics were dropped: a topic, a namespace ("/a/b/", trailing slash), or beside
    /// every row (empty).
    using DropHandler = std::function<bool(const QMimeData* data, const QString& target)>;

    explicit TopicTree(QObject* parent = nullptr);
    ~TopicTree() override;

    void setSourceModel(TopicTableModel* source);
    TopicTableModel* sourceModel() const { return m_source; }
    void setDropHandler(DropHandler handler) { m_dropHandler = std::move(handler); }
    /// The row of a topic or namespace ("/a/b/"), or an invalid index.
    QModelIndex indexOf(const QString& path, int column = TopicTableModel::TopicColumn) const;
    /// Every topic below a namespace ("/a/"), in tree order.
    QStringList topicsBelow(const QString& ns) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    bool hasChildren(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
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

private:
    struct Node
    {
        QString segment;
        QString path; ///< "/a/b" for a topic, "/a/b/" for a namespace, "/" for the root
        bool isTopic = false;
        Node* parent = nullptr;
        std::vector<std::unique_ptr<Node>> children; ///< namespaces first, then topics, by name
    };
    static bool before(const Node& a, bool topic, const QString& segment);
    static int sourceColumn(int column);
    Node* insertChild(Node* parent, const QString& segment, const QString& path, bool isTopic, bool announce);
    int rowOf(const Node* node) const;
    QModelIndex indexOfNode(const Node* node, int column) const;
    Node* nodeOf(const QModelIndex& index) const;
    void rebuild();
    void addTopic(const QString& name, bool announce);
    void removeTopic(const QString& name);
    void sourceRowsInserted(int first, int last);
    void sourceRowsAboutToBeRemoved(int first, int last);
    void sourceDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight,
                           const QList<int>& roles);
    void collectTopics(const Node* node, QStringList* out) const;

    QPointer<TopicTableModel> m_source;
    QList<QMetaObject::Connection> m_connections;
    std::unique_ptr<Node> m_root;
    QHash<QString, Node*> m_topics; ///< by name
    QHash<QString, Node*> m_namespaces; ///< by path ("/a/")
    DropHandler m_dropHandler;
};
