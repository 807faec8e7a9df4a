// SPDX-License-Identifier: MIT
#include "mappingmodel.h"

#include "text/topicmime.h"
#include "yaml/yamltree.h"
#include "config/configdocument.h"

#include <QMimeData>

using namespace Qt::StringLiterals;

MappingModel::MappingModel(ConfigDocument* document, QObject* parent)
    : QAbstractTableModel(parent)
    , m_document(document)
{
    connect(document, &ConfigDocument::aboutToReset, this, [this] { beginResetModel(); });
    connect(document, &ConfigDocument::resetDone, this, [this] {
        m_shownSeverity.clear();
        endResetModel();
    });
    connect(document, &ConfigDocument::mappingsAboutToBeInserted, this,
            [this](int first, int last) { beginInsertRows({}, first, last); });
    connect(document, &ConfigDocument::mappingsInserted, this, [this] { endInsertRows(); });
    connect(document, &ConfigDocument::mappingsAboutToBeRemoved, this,
            [this](int first, int last) { beginRemoveRows({}, first, last); });
    connect(document, &ConfigDocument::mappingsRemoved, this, [this] { endRemoveRows(); });
    connect(document, &ConfigDocument::mappingChanged, this,
            [this](int row) { emit dataChanged(index(row, 0), index(row, ColumnCount - 1)); });
    connect(document, &ConfigDocument::problemsChanged, this, &MappingModel::onProblemsChanged);
}

QModelIndex MappingModel::indexOfMapping(quint64 id, int column) const
{
    const int row = m_document->rowOf(id);
    return row < 0 ? QModelIndex() : index(row, column);
}

int MappingModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_document->mappingCount();
}

int MappingModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString MappingModel::directionText(Direction d)
{
    return d == Direction::Ros2Mqtt ? tr("ROS → MQTT") : tr("MQTT → ROS");
}

QString MappingModel::optionsSummary(const Mapping& m)
{
    QStringList parts;
    auto isTrue = [&m](const QString& path) { return YamlText::isTrue(m.value(path)); };
    if (isTrue(u"primitive"_s))
        parts << tr("primitive");
    if (isTrue(u"json"_s))
        parts << tr("JSON");
    if (isTrue(u"inject_timestamp"_s))
        parts << tr("stamped");
    if (m.isSet(u"ros_type"_s))
        parts << m.value(u"ros_type"_s);
    if (m.isSet(u"advanced.mqtt.qos"_s))
        parts << tr("QoS %1").arg(m.value(u"advanced.mqtt.qos"_s));
    if (isTrue(u"advanced.mqtt.retained"_s))
        parts << tr("retained");
    if (isTrue(u"advanced.ros.latched"_s))
        parts << tr("latched");
    if (m.isSet(u"advanced.ros.queue_size"_s))
        parts << tr("queue %1").arg(m.value(u"advanced.ros.queue_size"_s));
    if (m.isSet(u"timestamp_topic_prefix"_s))
        parts << tr("suite stamps");
    return parts.join(u", "_s);
}

QVariant MappingModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Mapping& m = m_document->mapping(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
    case SortRole:
        switch (index.column()) {
        case DirectionColumn:
            return role == SortRole ? QVariant(int(m.direction)) : QVariant(directionText(m.direction));
        case RosTopicColumn:
            return m.rosTopic();
        case MqttTopicColumn:
            return m.mqttTopic();
        case OptionsColumn:
            return optionsSummary(m);
        case HealthColumn: {
            const MappingHealth* h = health(m.id);
            if (role == SortRole)
                return h ? int(h->state) : -1;
            return h ? h->summary : QString();
        }
        }
        break;
    case HealthStateRole: {
        const MappingHealth* h = health(m.id);
        return h ? int(h->state) : -1;
    }
    case Qt::ToolTipRole: {
        if (index.column() == HealthColumn) {
            const MappingHealth* h = health(m.id);
            return h ? QVariant(h->detail) : QVariant();
        }
        QStringList lines;
        for (const Problem& p : m_document->problemsOf(m.id))
            lines << p.message + (p.fix.isEmpty() ? QString() : u"\n  → "_s + p.fix);
        return lines.isEmpty() ? QVariant() : QVariant(lines.join(u'\n'));
    }
    case MappingIdRole:
        return QVariant::fromValue(m.id);
    case DirectionRole:
        return int(m.direction);
    case SeverityRole: {
        bool any = false;
        const Severity s = m_document->worstSeverity(m.id, &any);
        return any ? int(s) : -1;
    }
    case ProblemsRole: {
        QStringList messages;
        for (const Problem& p : m_document->problemsOf(m.id))
            messages << p.message;
        return messages;
    }
    }
    return {};
}

QVariant MappingModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case DirectionColumn:
        return tr("Direction");
    case RosTopicColumn:
        return tr("ROS topic");
    case MqttTopicColumn:
        return tr("MQTT topic");
    case OptionsColumn:
        return tr("Options");
    case HealthColumn:
        return tr("Health");
    }
    return {};
}

Qt::ItemFlags MappingModel::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index) | Qt::ItemIsDropEnabled;
    if (index.isValid() && (index.column() == RosTopicColumn || index.column() == MqttTopicColumn))
        f |= Qt::ItemIsEditable;
    return f;
}

bool MappingModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (role != Qt::EditRole || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return false;
    if (index.column() != RosTopicColumn && index.column() != MqttTopicColumn)
        return false;
    const Mapping& before = m_document->mapping(index.row());
    const QString field = index.column() == RosTopicColumn ? u"ros_topic"_s : u"mqtt_topic"_s;
    const QString text = value.toString().trimmed();
    if (before.value(field) == text)
        return false;
    Mapping after = before;
    after.set(field, text);
    if (m_editHandler)
        m_editHandler(before, after);
    else
        m_document->replaceMapping(after);
    return true;
}

QHash<int, QByteArray> MappingModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractTableModel::roleNames();
    names.insert(MappingIdRole, "mappingId");
    names.insert(DirectionRole, "direction");
    names.insert(SeverityRole, "severity");
    names.insert(ProblemsRole, "problems");
    return names;
}

void MappingModel::setHealth(const QHash<quint64, MappingHealth>& health)
{
    m_health = health;
    if (rowCount() > 0)
        emit dataChanged(index(0, HealthColumn), index(rowCount() - 1, HealthColumn),
                         {Qt::DisplayRole, HealthStateRole, Qt::ToolTipRole});
}

const MappingHealth* MappingModel::health(quint64 id) const
{
    const auto it = m_health.constFind(id);
    return it == m_health.cend() ? nullptr : &*it;
}

QStringList MappingModel::mimeTypes() const
{
    return {TopicMime::rosType(), TopicMime::mqttType()};
}

Qt::DropActions MappingModel::supportedDropActions() const
{
    return Qt::CopyAction | Qt::MoveAction | Qt::LinkAction;
}

bool MappingModel::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex&) const
{
    return m_dropHandler && data
        && (data->hasFormat(TopicMime::rosType()) || data->hasFormat(TopicMime::mqttType()));
}

bool MappingModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    // Dropped on a mapping: the parent index is that mapping; between rows or below: a new one.
    return m_dropHandler(data, parent.isValid() ? parent.row() : -1);
}

void MappingModel::onProblemsChanged()
{
    // Tell views only about rows whose worst problem changed.
    QHash<quint64, int> now;
    for (int row = 0; row < m_document->mappingCount(); ++row) {
        const quint64 id = m_document->mapping(row).id;
        bool any = false;
        const Severity s = m_document->worstSeverity(id, &any);
        const int sev = any ? int(s) : -1;
        now.insert(id, sev);
        if (m_shownSeverity.value(id, -2) != sev && m_shownSeverity.contains(id))
            emit dataChanged(index(row, 0), index(row, ColumnCount - 1),
                             {SeverityRole, ProblemsRole, Qt::ToolTipRole});
    }
    m_shownSeverity = now;
}
