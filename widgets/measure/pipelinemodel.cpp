// SPDX-License-Identifier: MIT
#include "pipelinemodel.h"

#include "text/topicmime.h"

#include <algorithm>
#include <QMimeData>

using namespace Qt::StringLiterals;

PipelineModel::PipelineModel(QObject* parent)
    : QAbstractTableModel(parent)
{ }

void PipelineModel::setPipeline(const Pipeline& pipeline)
{
    if (pipeline == m_pipeline)
        return;
    if (pipeline.topics() == m_pipeline.topics()) {
        m_pipeline = pipeline; // hosts or window only
        if (rowCount() > 0)
            emit dataChanged(index(0, HostColumn), index(rowCount() - 1, HostColumn));
        return;
    }
    beginResetModel();
    m_pipeline = pipeline;
    endResetModel();
}

void PipelineModel::refreshCounts()
{
    if (rowCount() > 0)
        emit dataChanged(index(0, StampsColumn), index(rowCount() - 1, StampsColumn), {Qt::DisplayRole});
}

Pipeline PipelineModel::withTopics(const QStringList& topics, int row) const
{
    QStringList order = m_pipeline.topics();
    if (row < 0 || row > order.size())
        row = int(order.size());
    for (const QString& t : topics) {
        const int at = m_pipeline.indexOf(t);
        if (at >= 0) {
            order[at].clear(); // moves: the old place goes
        }
    }
    QStringList inserted;
    for (const QString& t : topics) {
        const int at = m_pipeline.indexOf(t);
        inserted << (at >= 0 ? m_pipeline.topics()[at] : t);
    }
    QStringList result = order.mid(0, row) + inserted + order.mid(row);
    result.removeAll(QString());
    Pipeline p = m_pipeline;
    p.setTopics(result);
    return p;
}

Pipeline PipelineModel::withoutRows(QList<int> rows) const
{
    QStringList topics = m_pipeline.topics();
    std::sort(rows.begin(), rows.end(), std::greater<>());
    for (int r : rows)
        if (r >= 0 && r < topics.size())
            topics.removeAt(r);
    Pipeline p = m_pipeline;
    p.setTopics(topics);
    return p;
}

Pipeline PipelineModel::withRowMoved(int from, int to) const
{
    QStringList topics = m_pipeline.topics();
    if (from < 0 || from >= topics.size() || to < 0 || to >= topics.size())
        return m_pipeline;
    topics.move(from, to);
    Pipeline p = m_pipeline;
    p.setTopics(topics);
    return p;
}

int PipelineModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_pipeline.topicCount();
}

int PipelineModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant PipelineModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const QString& topic = m_pipeline.topics()[index.row()];
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case IndexColumn:
            return index.row() + 1;
        case TopicColumn:
            return topic;
        case HostColumn:
            return m_pipeline.host(index.row());
        case StampsColumn:
            return m_counter ? QVariant(qulonglong(m_counter(topic))) : QVariant();
        default:
            return {};
        }
    case Qt::EditRole:
        return index.column() == HostColumn ? QVariant(m_pipeline.host(index.row())) : QVariant();
    case Qt::ToolTipRole:
        if (index.column() == HostColumn)
            return tr(
                "The machine whose clock stamps this topic; stages between different hosts are crossings.");
        if (index.row() > 0 && m_pipeline.isCrossing(index.row() - 1))
            return tr("%1\nThe stage from the previous stamp crosses from %2 to %3.")
                .arg(topic, m_pipeline.host(index.row() - 1), m_pipeline.host(index.row()));
        return topic;
    case TopicRole:
        return topic;
    default:
        return {};
    }
}

bool PipelineModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || index.column() != HostColumn || role != Qt::EditRole)
        return false;
    Pipeline p = m_pipeline;
    p.setHost(p.topics()[index.row()], value.toString());
    if (p == m_pipeline)
        return false;
    emit edited(p);
    return true;
}

QVariant PipelineModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case IndexColumn:
        return tr("#");
    case TopicColumn:
        return tr("Stamp topic");
    case HostColumn:
        return tr("Host");
    case StampsColumn:
        return tr("Stamps");
    default:
        return {};
    }
}

Qt::ItemFlags PipelineModel::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index) | Qt::ItemIsDropEnabled;
    if (!index.isValid())
        return f;
    f |= Qt::ItemIsDragEnabled;
    if (index.column() == HostColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

QStringList PipelineModel::mimeTypes() const
{
    return {rowMimeType(), TopicMime::rosType(), TopicMime::mqttType()};
}

QMimeData* PipelineModel::mimeData(const QModelIndexList& indexes) const
{
    QList<int> rows;
    for (const QModelIndex& i : indexes)
        if (!rows.contains(i.row()))
            rows << i.row();
    std::sort(rows.begin(), rows.end());
    QStringList topics;
    for (int r : rows)
        topics << m_pipeline.topics()[r];
    auto* data = new QMimeData;
    data->setData(rowMimeType(), topics.join(u'\n').toUtf8());
    data->setText(topics.join(u'\n'));
    return data;
}

QStringList PipelineModel::droppedTopics(const QMimeData* data) const
{
    if (data->hasFormat(rowMimeType()))
        return QString::fromUtf8(data->data(rowMimeType())).split(u'\n', Qt::SkipEmptyParts);
    QStringList out;
    for (const QString& type : {TopicMime::rosType(), TopicMime::mqttType()})
        for (const TopicMime::Topic& t : TopicMime::decode(data, type))
            out << t.name;
    return out;
}

bool PipelineModel::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex&) const
{
    return data && !droppedTopics(data).isEmpty();
}

bool PipelineModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int,
                                 const QModelIndex& parent)
{
    if (action == Qt::IgnoreAction)
        return true;
    const QStringList topics = data ? droppedTopics(data) : QStringList();
    if (topics.isEmpty())
        return false;
    if (row < 0 && parent.isValid())
        row = parent.row();
    const Pipeline p = withTopics(topics, row);
    if (p == m_pipeline)
        return false;
    emit edited(p);
    // The change arrives through setPipeline(); the view must not remove the dragged rows itself.
    return false;
}
