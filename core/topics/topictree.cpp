// SPDX-License-Identifier: MIT
#include "topictree.h"

#include "text/topicmime.h"

#include <algorithm>
#include <QMimeData>
#include <QSet>

using namespace Qt::StringLiterals;

TopicTree::TopicTree(QObject* parent)
    : QAbstractItemModel(parent)
    , m_root(std::make_unique<Node>())
{
    m_root->path = u"/"_s;
}

TopicTree::~TopicTree() = default;

void TopicTree::setSourceModel(TopicTableModel* source)
{
    if (source == m_source)
        return;
    for (const QMetaObject::Connection& c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_source = source;
    if (source) {
        m_connections << connect(
            source, &QAbstractItemModel::rowsInserted, this,
            [this](const QModelIndex&, int first, int last) { sourceRowsInserted(first, last); })
                      << connect(source, &QAbstractItemModel::rowsAboutToBeRemoved, this,
                                 [this](const QModelIndex&, int first, int last) {
                                     sourceRowsAboutToBeRemoved(first, last);
                                 })
                      << connect(source, &QAbstractItemModel::dataChanged, this,
                                 &TopicTree::sourceDataChanged)
                      << connect(source, &QAbstractItemModel::modelReset, this, &TopicTree::rebuild)
                      << connect(source, &QAbstractItemModel::layoutChanged, this, &TopicTree::rebuild)
                      << connect(source, &QObject::destroyed, this, [this] { setSourceModel(nullptr); });
    }
    rebuild();
}

int TopicTree::sourceColumn(int column)
{
    switch (column) {
    case TypeColumn:
        return TopicTableModel::TypeColumn;
    case PublishersColumn:
        return TopicTableModel::PublishersColumn;
    default:
        return TopicTableModel::TopicColumn;
    }
}

bool TopicTree::before(const Node& a, bool topic, const QString& segment)
{
    // Namespaces first, then topics, each by name (as file managers list folders and files).
    if (a.isTopic != topic)
        return !a.isTopic;
    return a.segment < segment;
}

int TopicTree::rowOf(const Node* node) const
{
    const Node* parent = node->parent;
    auto it = std::lower_bound(
        parent->children.cbegin(), parent->children.cend(), node,
        [](const std::unique_ptr<Node>& c, const Node* n) { return before(*c, n->isTopic, n->segment); });
    while (it != parent->children.cend() && it->get() != node) // equal segments ("/a//b" and "/a/b")
        ++it;
    return int(it - parent->children.cbegin());
}

QModelIndex TopicTree::indexOfNode(const Node* node, int column) const
{
    if (!node || node == m_root.get())
        return {};
    return createIndex(rowOf(node), column, const_cast<Node*>(node));
}

TopicTree::Node* TopicTree::nodeOf(const QModelIndex& index) const
{
    return index.isValid() ? static_cast<Node*>(index.internalPointer()) : m_root.get();
}

QModelIndex TopicTree::indexOf(const QString& path, int column) const
{
    const Node* n = path.endsWith(u'/') ? m_namespaces.value(path) : m_topics.value(path);
    return n ? indexOfNode(n, column) : QModelIndex();
}

void TopicTree::rebuild()
{
    beginResetModel();
    m_root->children.clear();
    m_topics.clear();
    m_namespaces.clear();
    if (m_source) {
        for (int r = 0; r < m_source->rowCount(); ++r)
            addTopic(m_source->index(r, TopicTableModel::TopicColumn).data(TopicTableModel::TopicRole).toString(),
                     false);
    }
    endResetModel();
}

TopicTree::Node* TopicTree::insertChild(Node* parent, const QString& segment, const QString& path,
                                              bool isTopic, bool announce)
{
    auto& children = parent->children;
    const auto it = std::lower_bound(
        children.begin(), children.end(), segment,
        [isTopic](const std::unique_ptr<Node>& c, const QString& s) { return before(*c, isTopic, s); });
    const int row = int(it - children.begin());
    if (announce)
        beginInsertRows(indexOfNode(parent, 0), row, row);
    auto node = std::make_unique<Node>();
    node->segment = segment;
    node->path = path;
    node->isTopic = isTopic;
    node->parent = parent;
    Node* raw = node.get();
    children.insert(children.begin() + row, std::move(node));
    (isTopic ? m_topics : m_namespaces).insert(path, raw);
    if (announce)
        endInsertRows();
    return raw;
}

void TopicTree::addTopic(const QString& name, bool announce)
{
    const QStringList parts = name.split(u'/', Qt::SkipEmptyParts);
    if (parts.isEmpty() || m_topics.contains(name))
        return;
    Node* parent = m_root.get();
    QString path = u"/"_s;
    for (qsizetype i = 0; i + 1 < parts.size(); ++i) {
        path += parts[i] + u'/';
        Node* ns = m_namespaces.value(path);
        parent = ns ? ns : insertChild(parent, parts[i], path, false, announce);
    }
    insertChild(parent, parts.last(), name, true, announce);
}

void TopicTree::removeTopic(const QString& name)
{
    Node* n = m_topics.value(name);
    // The topic's row, then every namespace it leaves empty.
    while (n && n != m_root.get()) {
        Node* parent = n->parent;
        const int row = rowOf(n);
        beginRemoveRows(indexOfNode(parent, 0), row, row);
        (n->isTopic ? m_topics : m_namespaces).remove(n->path);
        parent->children.erase(parent->children.begin() + row);
        endRemoveRows();
        n = parent->children.empty() ? parent : nullptr;
    }
}

void TopicTree::sourceRowsInserted(int first, int last)
{
    for (int r = first; r <= last; ++r)
        addTopic(m_source->index(r, TopicTableModel::TopicColumn).data(TopicTableModel::TopicRole).toString(),
                 true);
}

void TopicTree::sourceRowsAboutToBeRemoved(int first, int last)
{
    for (int r = first; r <= last; ++r)
        removeTopic(m_source->index(r, TopicTableModel::TopicColumn).data(TopicTableModel::TopicRole).toString());
}

void TopicTree::sourceDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight,
                                     const QList<int>& roles)
{
    // One signal per namespace whose topics changed, spanning their rows.
    QHash<const Node*, std::pair<int, int>> spans;
    for (int r = topLeft.row(); r <= bottomRight.row(); ++r) {
        const Node* n = m_topics.value(
            m_source->index(r, TopicTableModel::TopicColumn).data(TopicTableModel::TopicRole).toString());
        if (!n)
            continue;
        const int row = rowOf(n);
        auto it = spans.find(n->parent);
        if (it == spans.end())
            spans.insert(n->parent, {row, row});
        else
            *it = {std::min(it->first, row), std::max(it->second, row)};
    }
    for (auto it = spans.cbegin(); it != spans.cend(); ++it) {
        const QModelIndex parent = indexOfNode(it.key(), 0);
        emit dataChanged(index(it->first, 0, parent), index(it->second, ColumnCount - 1, parent), roles);
    }
}

QModelIndex TopicTree::index(int row, int column, const QModelIndex& parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount || (parent.isValid() && parent.column() != 0))
        return {};
    const Node* p = nodeOf(parent);
    if (row >= int(p->children.size()))
        return {};
    return createIndex(row, column, p->children[size_t(row)].get());
}

QModelIndex TopicTree::parent(const QModelIndex& child) const
{
    if (!child.isValid())
        return {};
    return indexOfNode(static_cast<const Node*>(child.internalPointer())->parent, 0);
}

int TopicTree::rowCount(const QModelIndex& parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    return int(nodeOf(parent)->children.size());
}

int TopicTree::columnCount(const QModelIndex&) const
{
    return ColumnCount;
}

bool TopicTree::hasChildren(const QModelIndex& parent) const
{
    return rowCount(parent) > 0;
}

QVariant TopicTree::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Node* n = nodeOf(index);
    if (role == PathRole)
        return n->path;
    if (role == IsTopicRole)
        return n->isTopic;
    if (!n->isTopic) {
        if (index.column() != TopicColumn)
            return {};
        if (role == Qt::DisplayRole || role == TopicTableModel::SortRole)
            return QString(n->segment + u'/');
        if (role == Qt::ToolTipRole)
            return tr("Namespace %1: drop MQTT topics here to bridge them below it").arg(n->path);
        return {};
    }
    if (index.column() == TopicColumn && role == Qt::DisplayRole)
        return n->segment; // its namespaces are the rows above it
    const int row = m_source ? m_source->rowOf(n->path) : -1;
    if (row < 0)
        return {};
    const QVariant value = m_source->index(row, sourceColumn(index.column())).data(role);
    if (index.column() == TypeColumn && role == Qt::DisplayRole)
        return value.toString().section(u'/', -1); // `PoseStamped`: the package in the tooltip
    if (index.column() == TypeColumn && role == Qt::ToolTipRole)
        return m_source->index(row, TopicTableModel::TypeColumn).data(Qt::DisplayRole);
    return value;
}

QVariant TopicTree::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (!m_source || section < 0 || section >= ColumnCount)
        return {};
    return m_source->headerData(sourceColumn(section), orientation, role);
}

Qt::ItemFlags TopicTree::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractItemModel::flags(index) | Qt::ItemIsDropEnabled;
    if (index.isValid())
        f |= Qt::ItemIsDragEnabled;
    return f;
}

QStringList TopicTree::mimeTypes() const
{
    return {TopicMime::rosType()};
}

void TopicTree::collectTopics(const Node* node, QStringList* out) const
{
    for (const auto& c : node->children) {
        if (c->isTopic)
            *out << c->path;
        else
            collectTopics(c.get(), out);
    }
}

QStringList TopicTree::topicsBelow(const QString& ns) const
{
    QStringList out;
    if (const Node* n = ns == u"/"_s ? m_root.get() : m_namespaces.value(ns))
        collectTopics(n, &out);
    return out;
}

QMimeData* TopicTree::mimeData(const QModelIndexList& indexes) const
{
    // A topic drags itself; a namespace every topic below it.
    QList<TopicMime::Topic> topics;
    QSet<QString> seen;
    for (const QModelIndex& i : indexes) {
        if (!i.isValid())
            continue;
        const Node* n = nodeOf(i);
        QStringList names;
        if (n->isTopic)
            names << n->path;
        else
            collectTopics(n, &names);
        for (const QString& name : std::as_const(names)) {
            if (seen.contains(name))
                continue;
            seen.insert(name);
            const int row = m_source ? m_source->rowOf(name) : -1;
            topics.append({name, row >= 0 ? m_source->graph().topics[row].type : QString()});
        }
    }
    return topics.isEmpty() ? nullptr : TopicMime::encode(TopicMime::rosType(), topics);
}

bool TopicTree::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex&) const
{
    return m_dropHandler && data && data->hasFormat(TopicMime::mqttType());
}

bool TopicTree::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    // On a row: that topic or namespace; between rows: the namespace they are in.
    const Node* target = nodeOf(parent);
    return m_dropHandler(data, target == m_root.get() ? QString() : target->path);
}
