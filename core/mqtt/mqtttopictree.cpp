// SPDX-License-Identifier: MIT
#include "mqtttopictree.h"

#include "base/topicmime.h"
#include "wire/ros2definitions.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"

#include <algorithm>
#include <QDateTime>
#include <QLocale>
#include <QMimeData>
#include <QSet>
#include <utility>

using namespace Qt::StringLiterals;

namespace {
constexpr int kLatencyWindow = 100;
constexpr int kRateHistory = 120;
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

/// The bundled ROS 2 definitions, parsed once for every tree that is given no others.
std::shared_ptr<const RosTypeRegistry> bundledRos2Registry()
{
    static const std::shared_ptr<const RosTypeRegistry> registry
        = std::make_shared<const RosTypeRegistry>(Ros2Definitions::registry());
    return registry;
}
} // namespace

struct MqttTopicTree::Node
{
    QString name;
    QString path;
    Node* parent = nullptr;
    int row = 0;
    bool visible = false;
    std::vector<std::unique_ptr<Node>> children;
    std::vector<std::unique_ptr<Node>> pending; ///< created in this batch, not yet announced
    QHash<QString, Node*> byName;

    bool isTopic = false;
    quint64 messages = 0;
    quint64 bytes = 0;
    quint64 retainedMessages = 0;
    int lastSize = 0;
    bool retained = false;
    quint8 qos = 0;
    qint64 lastNs = 0;
    std::deque<HistoryEntry> history;
    qint64 historyBytes = 0;
    QByteArray preview; ///< the last payload's first kPreviewBytes

    quint64 subMessages = 0;
    quint64 subBytes = 0;
    quint64 subMessagesAtTick = 0;
    double rate = 0;
    std::deque<float> rateHistory;

    std::deque<double> latencies;
    double latencySum = 0;
    double lastLatencyMs = 0;
    quint64 latencySamples = 0;
    quint64 malformed = 0;
    QString payloadError;
    QString typeError;
    bool dirty = false;
    bool typedTouched = false;

    void markVisible()
    {
        visible = true;
        for (auto& c : children)
            c->markVisible();
    }
};

struct MqttTopicTree::TypeState
{
    RosMsgTypeInfo info;
    std::shared_ptr<const RosTypeRegistry> registry; ///< ROS 1: from the announced definition
    QString error;
};

MqttTopicTree::MqttTopicTree(QObject* parent)
    : QAbstractItemModel(parent)
    , m_root(std::make_unique<Node>())
{
    m_root->visible = true;
}

MqttTopicTree::~MqttTopicTree() = default;

void MqttTopicTree::setHistoryDepth(int messages)
{
    m_historyDepth = std::max(1, messages);
}

void MqttTopicTree::setHistoryBudget(qint64 bytes)
{
    m_historyBudget = std::max<qint64>(0, bytes);
}

void MqttTopicTree::setTopicBudget(int topics)
{
    m_topicBudget = std::max(1, topics);
}

void MqttTopicTree::setStructureBudget(qint64 bytes)
{
    m_structureBudget = std::max<qint64>(0, bytes);
}

qint64 MqttTopicTree::newTopicCost(const QString& topic) const
{
    // Every new level keeps its name and its path (a prefix of the topic): a deep topic costs the
    // sum of its prefixes, which is what is counted, before anything is made.
    qint64 cost = 2 * qint64(topic.size()) + 64;
    // A type announcement keeps its data topic's name and type (with a ROS 1 definition parsed).
    if (const QString prefix = MqttClientWire::typeTopicPrefix(); topic.startsWith(prefix))
        cost += 2 * qint64(topic.size() - prefix.size()) + kNodeOverhead;
    const Node* node = m_root.get();
    qsizetype start = 0;
    while (true) {
        const qsizetype slash = topic.indexOf(u'/', start);
        const qsizetype end = slash < 0 ? topic.size() : slash;
        if (node)
            node = node->byName.value(topic.mid(start, end - start));
        if (!node)
            cost += kNodeOverhead + 2 * qint64(end - start) + 2 * qint64(end);
        if (slash < 0)
            return cost;
        start = slash + 1;
    }
}

bool MqttTopicTree::admit(qint64 cost)
{
    if (m_byTopic.size() + m_sys.size() >= m_topicBudget || m_structureBytes + cost > m_structureBudget) {
        ++m_untrackedMessages;
        return false;
    }
    m_structureBytes += cost;
    return true;
}

void MqttTopicTree::popOldest(Node* n)
{
    const qint64 cost = n->history.front().payload.size() + kHistoryEntryOverhead;
    n->historyBytes -= cost;
    m_historyBytes -= cost;
    --m_historyEntries;
    n->history.pop_front();
}

void MqttTopicTree::trimHistory(Node* n)
{
    while (n->history.size() > 1
           && (int(n->history.size()) > m_historyDepth || n->historyBytes > m_historyBytesPerTopic))
        popOldest(n);
    while (m_historyBytes > m_historyBudget && !m_historyQueue.empty()) {
        const auto [oldest, order] = m_historyQueue.front();
        m_historyQueue.pop_front();
        if (!oldest->history.empty() && oldest->history.front().order == order) {
            popOldest(oldest);
            ++m_evictedPayloads;
        }
    }
    if (qint64(m_historyQueue.size()) > 2 * m_historyEntries + 1024) {
        const auto kept = [](const std::pair<Node*, quint64>& e) {
            return !e.first->history.empty() && e.second >= e.first->history.front().order;
        };
        std::deque<std::pair<Node*, quint64>> live;
        std::copy_if(m_historyQueue.cbegin(), m_historyQueue.cend(), std::back_inserter(live), kept);
        m_historyQueue.swap(live);
    }
}

void MqttTopicTree::clear()
{
    beginResetModel();
    m_dirty.clear(); // of the nodes that go now
    m_root = std::make_unique<Node>();
    m_root->visible = true;
    m_byTopic.clear();
    m_types.clear();
    m_sys.clear();
    m_totalMessages = 0;
    m_malformedTypes = 0;
    m_malformedPayloads = 0;
    m_historyQueue.clear();
    m_historyBytes = 0;
    m_historyEntries = 0;
    m_evictedPayloads = 0;
    m_structureBytes = 0;
    m_untrackedMessages = 0;
    endResetModel();
    emit brokerStatisticsChanged();
}

MqttTopicTree::Node* MqttTopicTree::nodeFor(const QString& topic, std::vector<Node*>& withPending)
{
    if (Node* n = m_byTopic.value(topic))
        return n;
    Node* node = m_root.get();
    qsizetype start = 0;
    while (true) {
        const qsizetype slash = topic.indexOf(u'/', start);
        const QString level = topic.mid(start, slash < 0 ? -1 : slash - start);
        Node* child = node->byName.value(level);
        if (!child) {
            auto created = std::make_unique<Node>();
            created->name = level;
            created->path = slash < 0 ? topic : topic.left(slash);
            created->parent = node;
            child = created.get();
            node->byName.insert(level, child);
            if (node->visible) {
                // Announced in one go for this parent at the end of the batch.
                if (node->pending.empty())
                    withPending.push_back(node);
                node->pending.push_back(std::move(created));
            } else {
                child->row = int(node->children.size());
                node->children.push_back(std::move(created));
            }
        }
        node = child;
        if (slash < 0)
            break;
        start = slash + 1;
    }
    return node;
}

bool MqttTopicTree::absorbTypeAnnouncement(const QString& dataTopic, const QByteArray& payload,
                                           Node* typeNode)
{
    if (payload.isEmpty())
        return false; // a retained announcement being deleted
    QString error;
    const std::optional<RosMsgTypeInfo> info = MqttClientWire::decodeType(payload, &error);
    if (!info) {
        ++m_malformedTypes;
        ++typeNode->malformed;
        typeNode->typeError = error;
        return false;
    }
    typeNode->typeError.clear();
    std::shared_ptr<TypeState>& state = m_types[dataTopic];
    if (state && state->info == *info)
        return false;
    state = std::make_shared<TypeState>();
    state->info = *info;
    if (info->dialect == RosTypeRegistry::Dialect::Ros2)
        return true; // no definition on the wire: the ROS 2 registry's, looked up when needed
    auto registry = std::make_shared<RosTypeRegistry>();
    if (registry->addDefinition(info->name, info->definition, &state->error)) {
        state->registry = registry;
    } else {
        ++m_malformedTypes;
        ++typeNode->malformed;
        typeNode->typeError = tr("the definition of %1 does not read: %2").arg(info->name, state->error);
    }
    return true;
}

std::shared_ptr<const RosTypeRegistry> MqttTopicTree::registryOf(const TypeState& type) const
{
    if (type.info.dialect != RosTypeRegistry::Dialect::Ros2)
        return type.registry;
    if (!m_ros2Registry)
        m_ros2Registry = bundledRos2Registry();
    return m_ros2Registry->contains(RosTypeRegistry::ros2TypeName(type.info.name)) ? m_ros2Registry : nullptr;
}

QString MqttTopicTree::typeNoteOf(const TypeState& type) const
{
    if (type.info.dialect != RosTypeRegistry::Dialect::Ros2 || registryOf(type))
        return {};
    return tr("No ROS 2 definition of %1 is known: its payloads show raw.").arg(type.info.name);
}

void MqttTopicTree::setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry)
{
    m_ros2Registry = std::move(registry);
    // Announced ROS 2 types may decode now, or no longer: their rows show it.
    for (auto it = m_types.cbegin(); it != m_types.cend(); ++it) {
        if (it.value()->info.dialect != RosTypeRegistry::Dialect::Ros2)
            continue;
        if (const Node* n = m_byTopic.value(it.key()); n && n->visible)
            emit dataChanged(indexOf(n, 0), indexOf(n, ColumnCount - 1));
    }
}

int MqttTopicTree::unknownTypeTopics() const
{
    int n = 0;
    for (const auto& type : m_types)
        n += type->info.dialect == RosTypeRegistry::Dialect::Ros2 && !registryOf(*type) ? 1 : 0;
    return n;
}

void MqttTopicTree::apply(std::vector<MqttMessage>&& batch)
{
    if (batch.empty())
        return;
    std::vector<Node*> withPending;
    std::vector<Node*>& dirty = m_dirty;
    std::vector<Node*> typed;
    bool sysChanged = false;
    const QString typePrefix = MqttClientWire::typeTopicPrefix();
    for (MqttMessage& msg : batch) {
        ++m_totalMessages;
        if (msg.topic.startsWith(u"$SYS/"_s)) {
            auto sys = m_sys.find(msg.topic);
            if (sys == m_sys.end()) {
                if (!admit(2 * qint64(msg.topic.size() + kMaxSysValueBytes) + kNodeOverhead))
                    continue;
                sys = m_sys.insert(msg.topic, QString());
            }
            *sys = QString::fromUtf8(msg.payload.left(kMaxSysValueBytes));
            sysChanged = true;
            continue;
        }
        if (!m_byTopic.contains(msg.topic) && !admit(newTopicCost(msg.topic)))
            continue; // past a budget: counted, not kept
        Node* n = nodeFor(msg.topic, withPending);
        if (!n->isTopic) {
            n->isTopic = true;
            m_byTopic.insert(msg.topic, n);
        }
        const int size = int(msg.payload.size());
        ++n->messages;
        n->bytes += quint64(size);
        n->lastSize = size;
        n->retained = msg.retained;
        n->retainedMessages += msg.retained ? 1 : 0;
        n->qos = msg.qos;
        n->lastNs = msg.receivedNs;
        n->preview = msg.payload.left(kPreviewBytes);
        for (Node* p = n; p; p = p->parent) {
            ++p->subMessages;
            p->subBytes += quint64(size);
            if (!p->dirty) {
                p->dirty = true;
                dirty.push_back(p);
            }
        }
        if (msg.topic.startsWith(typePrefix)) {
            const QString dataTopic = msg.topic.mid(typePrefix.size());
            // The data topic's row shows the new type (its figures did not change).
            if (absorbTypeAnnouncement(dataTopic, msg.payload, n)) {
                Node* data = m_byTopic.value(dataTopic);
                if (data && !data->dirty) {
                    data->dirty = true;
                    dirty.push_back(data);
                }
            }
        }
        if (const auto type = m_types.value(msg.topic)) {
            if (type->info.stamped) {
                QString why;
                if (const auto stamped
                    = MqttClientWire::splitStamped(msg.payload, type->info.dialect, &why)) {
                    const double ms = double(msg.receivedNs - stamped->stampNs) / 1e6;
                    n->lastLatencyMs = ms;
                    n->latencies.push_back(ms);
                    n->latencySum += ms;
                    if (n->latencies.size() > kLatencyWindow) {
                        n->latencySum -= n->latencies.front();
                        n->latencies.pop_front();
                    }
                    ++n->latencySamples;
                } else {
                    ++n->malformed;
                    ++m_malformedPayloads;
                    n->payloadError = why;
                }
            }
            if (!n->typedTouched) {
                n->typedTouched = true;
                typed.push_back(n);
            }
        }
        n->historyBytes += size + kHistoryEntryOverhead;
        m_historyBytes += size + kHistoryEntryOverhead;
        ++m_historyEntries;
        n->history.push_back(
            {msg.receivedNs, std::move(msg.payload), msg.retained, msg.qos, ++m_historyOrder});
        m_historyQueue.emplace_back(n, m_historyOrder);
        trimHistory(n);
    }

    // New topics: one insert per parent.
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

    // Payloads of announced types must decode: check the newest one of each topic in the batch.
    for (Node* n : typed) {
        n->typedTouched = false;
        const auto type = m_types.value(n->path);
        const auto registry = type ? registryOf(*type) : nullptr;
        if (!registry || n->history.empty())
            continue;
        const QByteArray& payload = n->history.back().payload;
        if (type->info.stamped && !MqttClientWire::splitStamped(payload, type->info.dialect))
            continue; // counted above
        RosDecodeLimits limits;
        limits.maxArrayElements = 1;
        limits.maxStringChars = 64;
        QString error;
        if (!SourceMessage::decode(*registry, {SourceGraph::Mqtt, type->info.name, type->info}, payload, &error,
                                   limits)) {
            ++n->malformed;
            ++m_malformedPayloads;
            n->payloadError = error;
        }
    }

    if (m_figuresIntervalNs == 0)
        sayFigures();
    if (sysChanged)
        emit brokerStatisticsChanged();
}

void MqttTopicTree::sayFigures()
{
    // Changed figures: one dataChanged per parent, spanning the changed rows.
    QHash<Node*, std::pair<int, int>> spans;
    for (Node* n : std::exchange(m_dirty, {})) {
        n->dirty = false;
        if (n == m_root.get() || !n->visible)
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
    if (m_lastTickNs == 0) {
        m_lastTickNs = nowNs;
        return;
    }
    const qint64 elapsed = nowNs - m_lastTickNs;
    if (elapsed < 1000000000LL)
        return;
    m_lastTickNs = nowNs;
    const double seconds = double(elapsed) / 1e9;
    // Walk the visible tree; one dataChanged of the rate column per parent.
    std::vector<Node*> stack {m_root.get()};
    while (!stack.empty()) {
        Node* parent = stack.back();
        stack.pop_back();
        for (auto& c : parent->children) {
            Node* n = c.get();
            n->rate = double(n->subMessages - n->subMessagesAtTick) / seconds;
            n->subMessagesAtTick = n->subMessages;
            n->rateHistory.push_back(float(n->rate));
            if (n->rateHistory.size() > kRateHistory)
                n->rateHistory.pop_front();
            if (!n->children.empty())
                stack.push_back(n);
        }
        if (!parent->children.empty()) {
            const QModelIndex p = indexOf(parent, 0);
            emit dataChanged(index(0, RateColumn, p), index(int(parent->children.size()) - 1, RateColumn, p));
        }
    }
}

QModelIndex MqttTopicTree::indexOf(const Node* node, int column) const
{
    if (!node || node == m_root.get() || !node->visible)
        return {};
    return createIndex(node->row, column, const_cast<Node*>(node));
}

QModelIndex MqttTopicTree::indexOf(const QString& topic, int column) const
{
    return indexOf(m_byTopic.value(topic), column);
}

std::optional<RosMsgTypeInfo> MqttTopicTree::announcedType(const QString& topic) const
{
    const auto type = m_types.value(topic);
    return type ? std::optional<RosMsgTypeInfo>(type->info) : std::nullopt;
}

std::optional<MqttTopicTree::TopicInfo> MqttTopicTree::info(const QString& topic) const
{
    const Node* n = m_byTopic.value(topic);
    if (!n)
        return std::nullopt;
    TopicInfo i;
    i.topic = topic;
    i.messages = n->messages;
    i.bytes = n->bytes;
    i.retainedMessages = n->retainedMessages;
    i.lastSize = n->lastSize;
    i.retained = n->retained;
    i.qos = n->qos;
    i.lastNs = n->lastNs;
    i.rate = n->rate;
    if (const auto type = m_types.value(topic)) {
        i.rosType = type->info;
        i.typeNote = typeNoteOf(*type);
    }
    i.typeError = n->typeError;
    i.malformedPayloads = n->malformed;
    i.payloadError = n->payloadError;
    i.lastLatencyMs = n->lastLatencyMs;
    i.meanLatencyMs = n->latencies.empty() ? 0 : n->latencySum / double(n->latencies.size());
    i.latencySamples = n->latencySamples;
    for (float r : n->rateHistory)
        i.rateHistory << double(r);
    return i;
}

QList<MqttTopicTree::TopicInfo> MqttTopicTree::topics() const
{
    QStringList names = m_byTopic.keys();
    names.sort();
    QList<TopicInfo> out;
    out.reserve(names.size());
    for (const QString& t : std::as_const(names))
        out << *info(t);
    return out;
}

const std::deque<MqttTopicTree::HistoryEntry>* MqttTopicTree::history(const QString& topic) const
{
    const Node* n = m_byTopic.value(topic);
    return n ? &n->history : nullptr;
}

std::shared_ptr<const RosTypeRegistry> MqttTopicTree::registryFor(const QString& topic) const
{
    const auto type = m_types.value(topic);
    return type ? registryOf(*type) : nullptr;
}

QModelIndex MqttTopicTree::index(int row, int column, const QModelIndex& parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    const Node* p = parent.isValid() ? static_cast<const Node*>(parent.internalPointer()) : m_root.get();
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
    const Node* p = parent.isValid() ? static_cast<const Node*>(parent.internalPointer()) : m_root.get();
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
    const auto type = n->isTopic ? m_types.value(n->path) : nullptr;
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
            if (const QString note = typeNoteOf(*type); !note.isEmpty())
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

const MqttTopicTree::Node* MqttTopicTree::nodeAt(const QString& path) const
{
    const Node* n = m_root.get();
    if (path.isEmpty())
        return n;
    for (const QString& level : path.split(u'/')) {
        n = n->byName.value(level);
        if (!n)
            return nullptr;
    }
    return n;
}

bool MqttTopicTree::hasChildren(const QString& path) const
{
    const Node* n = nodeAt(path);
    return n && !n->children.empty();
}

QStringList MqttTopicTree::topicsBelow(const QString& path, int limit) const
{
    QStringList out;
    const Node* start = nodeAt(path);
    if (!start)
        return out;
    std::vector<const Node*> stack {start};
    while (!stack.empty() && out.size() < limit) {
        const Node* n = stack.back();
        stack.pop_back();
        if (n->isTopic)
            out << n->path;
        for (auto it = n->children.rbegin(); it != n->children.rend(); ++it)
            stack.push_back(it->get());
    }
    return out;
}

bool MqttTopicTree::mayHoldRetained(const QString& topic) const
{
    const Node* n = m_byTopic.value(topic);
    return n && n->retainedMessages > 0 && n->lastSize > 0;
}

QStringList MqttTopicTree::retainedBelow(const QString& path, int limit) const
{
    QStringList out;
    for (const QString& t : topicsBelow(path, limit)) {
        if (mayHoldRetained(t))
            out << t;
    }
    return out;
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
        const QStringList names = n->isTopic ? QStringList {n->path} : topicsBelow(n->path);
        for (const QString& t : names) {
            if (seen.contains(t))
                continue;
            seen.insert(t);
            const auto type = m_types.value(t);
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
