// SPDX-License-Identifier: MIT
#include "topictablemodel.h"

#include "text/topicmime.h"

#include <algorithm>
#include <cmath>
#include <QLocale>
#include <QMimeData>

using namespace Qt::StringLiterals;

TopicTableModel::TopicTableModel(QObject* parent)
    : QAbstractTableModel(parent)
{ }

int TopicTableModel::rowOf(const QString& topic) const
{
    const auto it = std::lower_bound(m_graph.topics.cbegin(), m_graph.topics.cend(), topic,
                                     [](const TopicInfo& t, const QString& n) { return t.name < n; });
    return it != m_graph.topics.cend() && it->name == topic ? int(it - m_graph.topics.cbegin()) : -1;
}

void TopicTableModel::setGraph(const TopicGraph& graph)
{
    // Both lists are sorted: remove what went away (from the back), insert what is new in place,
    // then tell about rows whose type or nodes changed.
    QSet<QString> next;
    for (const TopicInfo& t : graph.topics)
        next.insert(t.name);
    for (int row = int(m_graph.topics.size()) - 1; row >= 0; --row) {
        if (!next.contains(m_graph.topics[row].name)) {
            beginRemoveRows({}, row, row);
            m_graph.topics.removeAt(row);
            endRemoveRows();
        }
    }
    for (int row = 0; row < graph.topics.size(); ++row) {
        const TopicInfo& t = graph.topics[row];
        if (row < m_graph.topics.size() && m_graph.topics[row].name == t.name) {
            if (!(m_graph.topics[row] == t)) {
                m_graph.topics[row] = t;
                emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
            }
            continue;
        }
        beginInsertRows({}, row, row);
        m_graph.topics.insert(row, t);
        endInsertRows();
    }
    m_graph.nodes = graph.nodes;
}

void TopicTableModel::setMonitorStats(const QHash<QString, TopicStats>& stats, qint64 nowNs)
{
    m_stats = stats;
    m_nowNs = nowNs;
    if (!m_graph.topics.isEmpty() && !m_monitored.isEmpty())
        emit dataChanged(index(0, RateColumn), index(int(m_graph.topics.size()) - 1, AgeColumn));
}

void TopicTableModel::setMonitored(const QString& topic, bool on)
{
    if (on == m_monitored.contains(topic))
        return;
    if (on)
        m_monitored.insert(topic);
    else
        m_monitored.remove(topic);
    const int row = rowOf(topic);
    if (row >= 0)
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    emit monitorRequested(topic, on);
}

const TopicStats* TopicTableModel::stats(const QString& topic) const
{
    const auto it = m_stats.constFind(topic);
    return it == m_stats.cend() ? nullptr : &*it;
}

int TopicTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_graph.topics.size());
}

int TopicTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TopicTableModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const TopicInfo& t = m_graph.topics[index.row()];
    const bool monitored = m_monitored.contains(t.name);
    const TopicStats* s = monitored ? stats(t.name) : nullptr;
    const bool any = s && s->messages > 0;
    switch (role) {
    case Qt::CheckStateRole:
        return index.column() == MonitorColumn ? QVariant(monitored ? Qt::Checked : Qt::Unchecked)
                                               : QVariant();
    case Qt::DisplayRole:
        switch (index.column()) {
        case TopicColumn:
            return t.name;
        case TypeColumn:
            return t.type;
        case PublishersColumn:
            return QString::number(t.publishers.size());
        case SubscribersColumn:
            return QString::number(t.subscribers.size());
        case RateColumn:
            return any ? QString::number(s->rateHz, 'f', s->rateHz < 10 ? 2 : 1) : QString();
        case BandwidthColumn:
            return any ? QLocale::system().formattedDataSize(qint64(s->bytesPerSecond), 1,
                                                             QLocale::DataSizeTraditionalFormat)
                    + tr("/s")
                       : QString();
        case SizeColumn:
            return any
                ? QLocale::system().formattedDataSize(s->lastSize, 1, QLocale::DataSizeTraditionalFormat)
                : QString();
        case AgeColumn:
            if (any)
                return tr("%1 s").arg(double(m_nowNs - s->lastNs) / 1e9, 0, 'f', 1);
            return monitored ? tr("waiting…") : QString();
        }
        break;
    case Qt::ToolTipRole:
        if (index.column() == PublishersColumn)
            return t.publishers.join(u'\n');
        if (index.column() == SubscribersColumn)
            return t.subscribers.join(u'\n');
        if (index.column() == MonitorColumn)
            return tr("Subscribe and show rate, bandwidth and the last message");
        if (index.column() == AgeColumn && any && std::isfinite(s->ageMs))
            return tr("The last message came %1 s ago; the messages were %2 ms old when they came (median "
                      "of the last %3, by their DDS source timestamps: the writer's clock).")
                .arg(double(m_nowNs - s->lastNs) / 1e9, 0, 'f', 1)
                .arg(s->ageMs, 0, 'f', 2)
                .arg(TopicFigures::kAgeSamples);
        return t.name;
    case SortRole:
        switch (index.column()) {
        case MonitorColumn:
            return monitored;
        case PublishersColumn:
            return int(t.publishers.size());
        case SubscribersColumn:
            return int(t.subscribers.size());
        case RateColumn:
            return any ? s->rateHz : -1.0;
        case BandwidthColumn:
            return any ? s->bytesPerSecond : -1.0;
        case SizeColumn:
            return any ? s->lastSize : -1;
        case AgeColumn:
            return any ? s->lastNs : qint64(0);
        default:
            return data(index, Qt::DisplayRole);
        }
    case TopicRole:
        return t.name;
    case TypeRole:
        return t.type;
    case MonitoredRole:
        return monitored;
    }
    return {};
}

bool TopicTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (role != Qt::CheckStateRole || index.column() != MonitorColumn
        || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return false;
    setMonitored(m_graph.topics[index.row()].name, value.toInt() == Qt::Checked);
    return true;
}

Qt::ItemFlags TopicTableModel::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index) | Qt::ItemIsDropEnabled;
    if (index.isValid())
        f |= Qt::ItemIsDragEnabled;
    if (index.isValid() && index.column() == MonitorColumn)
        f |= Qt::ItemIsUserCheckable;
    return f;
}

QStringList TopicTableModel::mimeTypes() const
{
    return {TopicMime::rosType()};
}

QMimeData* TopicTableModel::mimeData(const QModelIndexList& indexes) const
{
    QList<TopicMime::Topic> topics;
    QSet<int> rows;
    for (const QModelIndex& i : indexes) {
        if (!i.isValid() || rows.contains(i.row()))
            continue;
        rows.insert(i.row());
        const TopicInfo& t = m_graph.topics[i.row()];
        topics.append({t.name, t.type});
    }
    return topics.isEmpty() ? nullptr : TopicMime::encode(TopicMime::rosType(), topics);
}

bool TopicTableModel::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex&) const
{
    return m_dropHandler && data && data->hasFormat(TopicMime::mqttType());
}

bool TopicTableModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                 const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    const int target = parent.isValid() ? parent.row() : -1;
    return m_dropHandler(
        data, target >= 0 && target < m_graph.topics.size() ? m_graph.topics[target].name : QString());
}

QVariant TopicTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole && section == MonitorColumn)
        return tr("Monitor: subscribe and show rate, bandwidth and the last message");
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case MonitorColumn:
        return tr("Mon");
    case TopicColumn:
        return tr("Topic");
    case TypeColumn:
        return tr("Type");
    case PublishersColumn:
        return tr("Pubs");
    case SubscribersColumn:
        return tr("Subs");
    case RateColumn:
        return tr("Rate (Hz)");
    case BandwidthColumn:
        return tr("Bandwidth");
    case SizeColumn:
        return tr("Size");
    case AgeColumn:
        return tr("Last");
    }
    return {};
}
