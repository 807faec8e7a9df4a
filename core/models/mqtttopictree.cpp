// SPDX-License-Identifier: MIT
#include "mqtttopictree.h"

#include "text/topicmime.h"
#include "wire/rosmessage.h"

#include <algorithm>
#include <QDateTime>
#include <QLocale>
#include <QMimeData>
#include <QSet>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
constexpr qsizetype kSearchTextChars = 256;

bool looksLikeText(const QByteArray& payload)
{
    const qsizetype n = std::min<qsizetype>(payload.size(), 512);
    for (qsizetype i = 0; i < n; ++i) {
        const uchar c = uchar(payload[i]);
        if (c < 0x09 || (c > 0x0d && c < 0x20))
            return false;
    }
    return true;
}

/// A payload's first bytes as one line of at most `chars` characters: text with its line breaks
/// and runs of blanks as single spaces, anything else as hex; `…` when more of it is not shown
/// (`size` is the whole payload's).
QString previewText(const QByteArray& preview, int size, qsizetype chars)
{
    if (size == 0)
        return MqttTopicTree::tr("(empty)");
    QString text;
    if (looksLikeText(preview)) {
        text = QString::fromUtf8(preview);
        if (preview.size() < size && text.endsWith(QChar::ReplacementCharacter)) // a character cut
            text.chop(1);
        text = text.simplified();
    } else {
        text = QString::fromLatin1(preview.left((chars + 1) / 3).toHex(' '));
    }
    const bool more = text.size() > chars || preview.size() < size;
    if (text.size() > chars)
        text.truncate(chars);
    return more ? QString(text + u'…') : text;
}

} // namespace

MqttTopicTree::MqttTopicTree(QObject* parent)
    : QAbstractItemModel(parent)
{
}

MqttTopicTree::~MqttTopicTree() = default;

void MqttTopicTree::clear()
{
    beginResetModel();
    m_dirty.clear(); // of the nodes that go now
    m_topics.clear();
    endResetModel();
    emit brokerStatisticsChanged();
}

void MqttTopicTree::setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry)
{
    m_topics.setRos2Registry(std::move(registry));
    // Announced ROS 2 types may decode now, or no longer: their rows show it.
    for (const QString& topic : m_topics.checks().ros2Topics()) {
        if (const Node* n = m_topics.store().topic(topic); n && n->visible)
            emit dataChanged(indexOf(n, 0), indexOf(n, ColumnCount - 1));
    }
}

void MqttTopicTree::apply(std::vector<MqttMessage>&& batch)
{
    if (batch.empty())
        return;
    const MqttTopics::Applied applied = m_topics.apply(std::move(batch), m_dirty);
    insertPending(applied.withPending);
    if (m_figuresIntervalNs == 0)
        sayFigures();
    if (applied.statisticsChanged)
        emit brokerStatisticsChanged();
}

void MqttTopicTree::insertPending(const std::vector<Node*>& withPending)
{
    for (Node* parent : withPending) {
        const int first = int(parent->children.size());
        const int last = first + int(parent->pending.size()) - 1;
        beginInsertRows(indexOf(parent, 0), first, last);
        for (auto& child : parent->pending) {
            child->row = int(parent->children.size());
            parent->children.push_back(std::move(child));
            parent->children.back()->markVisible();
        }
        parent->pending.clear();
        endInsertRows();
    }
}

void MqttTopicTree::sayFigures()
{
    // Changed figures: one dataChanged per parent, spanning the changed rows.
    QHash<Node*, std::pair<int, int>> spans;
    for (Node* n : std::exchange(m_dirty, {})) {
        n->dirty = false;
        if (n == m_topics.store().root() || !n->visible)
            continue;
        auto it = spans.find(n->parent);
        if (it == spans.end())
            spans.insert(n->parent, {n->row, n->row});
        else
            *it = {std::min(it->first, n->row), std::max(it->second, n->row)};
    }
    for (auto it = spans.cbegin(); it != spans.cend(); ++it) {
        const QModelIndex parent = indexOf(it.key(), 0);
        emit dataChanged(index(it->first, MessagesColumn, parent),
                         index(it->second, ColumnCount - 1, parent));
    }
}

void MqttTopicTree::tick(qint64 nowNs)
{
    if (!m_dirty.empty() && nowNs - m_figuresSaidNs >= m_figuresIntervalNs) {
        m_figuresSaidNs = nowNs;
        sayFigures();
    }
    if (!m_topics.updateRates(nowNs))
        return;
    // Walk the visible tree; one dataChanged of the rate column per parent.
    std::vector<Node*> stack {m_topics.store().root()};
    while (!stack.empty()) {
        Node* parent = stack.back();
        stack.pop_back();
        for (auto& c : parent->children) {
            if (!c->children.empty())
                stack.push_back(c.get());
        }
        if (!parent->children.empty()) {
            const QModelIndex p = indexOf(parent, 0);
            emit dataChanged(index(0, RateColumn, p), index(int(parent->children.size()) - 1, RateColumn, p));
        }
    }
}

QModelIndex MqttTopicTree::indexOf(const Node* node, int column) const
{
    if (!node || node == m_topics.store().root() || !node->visible)
        return {};
    return createIndex(node->row, column, const_cast<Node*>(node));
}

QModelIndex MqttTopicTree::indexOf(const QString& topic, int column) const
{
    return indexOf(m_topics.store().topic(topic), column);
}

QModelIndex MqttTopicTree::index(int row, int column, const QModelIndex& parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    const Node* p = parent.isValid() ? static_cast<const Node*>(parent.internalPointer()) : m_topics.store().root();
    if (row >= int(p->children.size()))
        return {};
    return createIndex(row, column, p->children[size_t(row)].get());
}

QModelIndex MqttTopicTree::parent(const QModelIndex& child) const
{
    if (!child.isValid())
        return {};
    const Node* n = static_cast<const Node*>(child.internalPointer());
    return indexOf(n->parent, 0);
}

int MqttTopicTree::rowCount(const QModelIndex& parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    const Node* p = parent.isValid() ? static_cast<const Node*>(parent.internalPointer()) : m_topics.store().root();
    return int(p->children.size());
}

int MqttTopicTree::columnCount(const QModelIndex&) const
{
    return ColumnCount;
}

QVariant MqttTopicTree::data(const QModelIndex& index, int role) const
{
    if (!index.isValid())
        return {};
    const Node* n = static_cast<const Node*>(index.internalPointer());
    const auto type = n->isTopic ? m_topics.checks().typeOf(n->path) : nullptr;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case TopicColumn:
            return n->name.isEmpty() ? tr("(empty level)") : n->name;
        case MessagesColumn:
            return QString::number(n->subMessages);
        case RateColumn:
            return QString::number(n->rate, 'f', n->rate < 10 ? 1 : 0);
        case BytesColumn:
            return QLocale::system().formattedDataSize(qint64(n->subBytes), 1,
                                                       QLocale::DataSizeTraditionalFormat);
        case SizeColumn:
            return n->isTopic
                ? QLocale::system().formattedDataSize(n->lastSize, 1, QLocale::DataSizeTraditionalFormat)
                : QString();
        case RetainedColumn:
            return n->isTopic && n->retained ? tr("retained") : QString();
        case QosColumn:
            return n->isTopic ? QString::number(n->qos) : QString();
        case LastColumn:
            return n->isTopic
                ? QDateTime::fromMSecsSinceEpoch(n->lastNs / 1000000).toString(u"HH:mm:ss.zzz"_s)
                : QString();
        case RosTypeColumn:
            if (!n->typeError.isEmpty())
                return tr("malformed type announcement");
            return type ? type->info.name + (type->info.stamped ? tr(" (stamped)") : QString()) : QString();
        case LatencyColumn:
            return n->latencySamples ? tr("%1 ms").arg(n->lastLatencyMs, 0, 'f', 1) : QString();
        case ValueColumn:
            return n->isTopic ? previewText(n->preview, n->lastSize, kPreviewChars) : QString();
        }
        break;
    case SortRole:
        switch (index.column()) {
        case TopicColumn:
            return n->name;
        case MessagesColumn:
            return n->subMessages;
        case RateColumn:
            return n->rate;
        case BytesColumn:
            return n->subBytes;
        case SizeColumn:
            return n->lastSize;
        case RetainedColumn:
            return n->retained;
        case QosColumn:
            return n->qos;
        case LastColumn:
            return n->lastNs;
        case RosTypeColumn:
            return type ? type->info.name : QString();
        case LatencyColumn:
            return n->lastLatencyMs;
        case ValueColumn:
            return n->isTopic ? previewText(n->preview, n->lastSize, kPreviewChars) : QString();
        }
        break;
    case Qt::ToolTipRole:
        if (index.column() == ValueColumn && n->isTopic && !n->preview.isEmpty())
            return previewText(n->preview, n->lastSize, kPreviewBytes);
        if (index.column() == LatencyColumn && n->latencySamples)
            return tr(
                "Receive time minus the stamp mqtt_client injected on the sending host: valid only as far as "
                "the two clocks agree.");
        if (!n->typeError.isEmpty())
            return n->typeError;
        if (type) {
            if (const QString note = m_topics.checks().typeNoteOf(*type); !note.isEmpty())
                return QString(n->path + u'\n' + note);
        }
        if (n->malformed && !n->payloadError.isEmpty())
            return tr("%1\n%2 payloads did not decode; the last: %3")
                .arg(n->path)
                .arg(n->malformed)
                .arg(n->payloadError);
        return n->path;
    case FullTopicRole:
        return n->path;
    case IsTopicRole:
        return n->isTopic;
    case SearchTextRole:
        if (n->history.empty() || !looksLikeText(n->history.back().payload))
            return QString();
        return QString::fromUtf8(n->history.back().payload.left(kSearchTextChars));
    case RosTypeRole:
        return type ? type->info.name : QString();
    case StampedRole:
        return type && type->info.stamped;
    }
    return {};
}

bool MqttTopicTree::hasChildren(const QString& path) const
{
    const Node* n = m_topics.store().nodeAt(path);
    return n && !n->children.empty();
}

Qt::ItemFlags MqttTopicTree::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractItemModel::flags(index) | Qt::ItemIsDropEnabled;
    if (index.isValid())
        f |= Qt::ItemIsDragEnabled;
    return f;
}

QStringList MqttTopicTree::mimeTypes() const
{
    return {TopicMime::mqttType()};
}

QMimeData* MqttTopicTree::mimeData(const QModelIndexList& indexes) const
{
    // A topic drags itself; a level drags every topic below it.
    QList<TopicMime::Topic> topics;
    QSet<QString> seen;
    for (const QModelIndex& i : indexes) {
        if (!i.isValid() || i.column() != 0)
            continue;
        const Node* n = static_cast<const Node*>(i.internalPointer());
        const QStringList names
            = n->isTopic ? QStringList {n->path} : m_topics.store().topicsBelow(n->path, 1000);
        for (const QString& t : names) {
            if (seen.contains(t))
                continue;
            seen.insert(t);
            const auto type = m_topics.checks().typeOf(t);
            topics.append({t, type ? type->info.name : QString()});
        }
    }
    return topics.isEmpty() ? nullptr : TopicMime::encode(TopicMime::mqttType(), topics);
}

bool MqttTopicTree::canDropMimeData(const QMimeData* data, Qt::DropAction, int, int, const QModelIndex&) const
{
    return m_dropHandler && data && data->hasFormat(TopicMime::rosType());
}

bool MqttTopicTree::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                 const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    const Node* target = parent.isValid() ? static_cast<const Node*>(parent.internalPointer()) : nullptr;
    return m_dropHandler(data, target ? target->path : QString());
}

QVariant MqttTopicTree::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TopicColumn:
        return tr("Topic");
    case MessagesColumn:
        return tr("Messages");
    case RateColumn:
        return tr("Rate (Hz)");
    case BytesColumn:
        return tr("Bytes");
    case SizeColumn:
        return tr("Last size");
    case RetainedColumn:
        return tr("Retained");
    case QosColumn:
        return tr("QoS");
    case LastColumn:
        return tr("Last message");
    case RosTypeColumn:
        return tr("ROS type");
    case LatencyColumn:
        return tr("Latency");
    case ValueColumn:
        return tr("Value");
    }
    return {};
}
