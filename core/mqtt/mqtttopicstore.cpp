// SPDX-License-Identifier: MIT
#include "mqtttopicstore.h"

#include "wire/mqttclientwire.h"

#include <algorithm>
#include <iterator>

void MqttTopicNode::markVisible()
{
    visible = true;
    for (auto& c : children)
        c->markVisible();
}

void MqttTopicNode::markDirty(std::vector<MqttTopicNode*>& rows)
{
    if (!dirty) {
        dirty = true;
        rows.push_back(this);
    }
}

MqttTopicStore::MqttTopicStore()
    : m_root(std::make_unique<Node>())
{
    m_root->visible = true;
}

MqttTopicStore::~MqttTopicStore() = default;

void MqttTopicStore::clear()
{
    m_root = std::make_unique<Node>();
    m_root->visible = true;
    m_byTopic.clear();
    m_sys.clear();
    m_totalMessages = 0;
    m_historyQueue.clear();
    m_historyBytes = 0;
    m_historyEntries = 0;
    m_evictedPayloads = 0;
    m_structureBytes = 0;
    m_untrackedMessages = 0;
}

qint64 MqttTopicStore::newTopicCost(const QString& topic) const
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

bool MqttTopicStore::admit(qint64 cost)
{
    if (m_byTopic.size() + m_sys.size() >= m_topicBudget || m_structureBytes + cost > m_structureBudget) {
        ++m_untrackedMessages;
        return false;
    }
    m_structureBytes += cost;
    return true;
}

bool MqttTopicStore::addStatistic(const MqttMessage& msg)
{
    auto sys = m_sys.find(msg.topic);
    if (sys == m_sys.end()) {
        if (!admit(2 * qint64(msg.topic.size() + kMaxSysValueBytes) + kNodeOverhead))
            return false;
        sys = m_sys.insert(msg.topic, QString());
    }
    *sys = QString::fromUtf8(msg.payload.left(kMaxSysValueBytes));
    return true;
}

MqttTopicStore::Node* MqttTopicStore::admitTopic(const QString& topic, std::vector<Node*>& withPending)
{
    if (!m_byTopic.contains(topic) && !admit(newTopicCost(topic)))
        return nullptr; // past a budget: counted, not kept
    Node* n = nodeFor(topic, withPending);
    if (!n->isTopic) {
        n->isTopic = true;
        m_byTopic.insert(topic, n);
    }
    return n;
}

MqttTopicStore::Node* MqttTopicStore::nodeFor(const QString& topic, std::vector<Node*>& withPending)
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

void MqttTopicStore::count(Node* n, const MqttMessage& msg, std::vector<Node*>& dirty)
{
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
        p->markDirty(dirty);
    }
}

void MqttTopicStore::keep(Node* n, MqttMessage&& msg)
{
    const qint64 size = msg.payload.size();
    n->historyBytes += size + kHistoryEntryOverhead;
    m_historyBytes += size + kHistoryEntryOverhead;
    ++m_historyEntries;
    n->history.push_back({msg.receivedNs, std::move(msg.payload), msg.retained, msg.qos, ++m_historyOrder});
    m_historyQueue.emplace_back(n, m_historyOrder);
    trimHistory(n);
}

void MqttTopicStore::popOldest(Node* n)
{
    const qint64 cost = n->history.front().payload.size() + kHistoryEntryOverhead;
    n->historyBytes -= cost;
    m_historyBytes -= cost;
    --m_historyEntries;
    n->history.pop_front();
}

void MqttTopicStore::trimHistory(Node* n)
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

const MqttTopicStore::Node* MqttTopicStore::nodeAt(const QString& path) const
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

QStringList MqttTopicStore::topicsBelow(const QString& path, int limit) const
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

bool MqttTopicStore::mayHoldRetained(const QString& topic) const
{
    const Node* n = m_byTopic.value(topic);
    return n && n->retainedMessages > 0 && n->lastSize > 0;
}
