// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"

#include <deque>
#include <memory>
#include <QHash>
#include <QStringList>
#include <vector>

/// One level of the broker's topic tree: a topic when messages came on exactly it, with its
/// figures, its bounded payload history and the sums of its subtree. What MqttTopicStore keeps,
/// MqttPayloadChecks annotates (types, latencies, payloads that do not decode) and MqttTopicTree
/// shows (rows, which are announced in batches: `pending`, `visible`, `dirty`).
struct MqttTopicNode
{
    struct HistoryEntry
    {
        qint64 receivedNs = 0;
        QByteArray payload;
        bool retained = false;
        quint8 qos = 0;
        quint64 order = 0; ///< arrival order in the tree (1, 2, ...)
    };

    QString name;
    QString path;
    MqttTopicNode* parent = nullptr;
    int row = 0;
    bool visible = false;
    std::vector<std::unique_ptr<MqttTopicNode>> children;
    std::vector<std::unique_ptr<MqttTopicNode>> pending; ///< created in this batch, not yet announced
    QHash<QString, MqttTopicNode*> byName;

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

    void markVisible();
    /// Adds the node to the rows whose figures changed, once.
    void markDirty(std::vector<MqttTopicNode*>& dirty);
};

/// The broker's topics as a tree of levels with their figures, within bounds: at most topicBudget()
/// topics (and $SYS statistics, kept apart), structureBudget() bytes of levels, and a payload
/// history of historyDepth() per topic, 16 MiB per topic and historyBudget() over all topics (past
/// it the oldest payloads of any topic go first). No Qt model: MqttTopicTree (core/models) shows it.
class MqttTopicStore
{
public:
    using Node = MqttTopicNode;
    static constexpr qint64 kDefaultHistoryBudget = 64 * 1024 * 1024;
    static constexpr qint64 kHistoryEntryOverhead = 64;
    static constexpr int kDefaultTopicBudget = 20'000;
    static constexpr qint64 kDefaultStructureBudget = 64 * 1024 * 1024;
    static constexpr qint64 kNodeOverhead = 3072;
    static constexpr qsizetype kPreviewBytes = 256;
    static constexpr qsizetype kMaxSysValueBytes = 1024;

    MqttTopicStore();
    ~MqttTopicStore();

    void setHistoryDepth(int messages) { m_historyDepth = std::max(1, messages); }
    int historyDepth() const { return m_historyDepth; }
    void setHistoryBudget(qint64 bytes) { m_historyBudget = std::max<qint64>(0, bytes); }
    qint64 historyBudget() const { return m_historyBudget; }
    qint64 historyBytes() const { return m_historyBytes; }
    /// Payloads evicted from the history to keep it within historyBudget().
    quint64 evictedPayloads() const { return m_evictedPayloads; }
    void setTopicBudget(int topics) { m_topicBudget = std::max(1, topics); }
    int topicBudget() const { return m_topicBudget; }
    void setStructureBudget(qint64 bytes) { m_structureBudget = std::max<qint64>(0, bytes); }
    qint64 structureBudget() const { return m_structureBudget; }
    qint64 structureBytes() const { return m_structureBytes; }
    /// Messages on topics not added to keep within topicBudget() and structureBudget().
    quint64 untrackedMessages() const { return m_untrackedMessages; }
    quint64 totalMessages() const { return m_totalMessages; }
    void clear();

    /// Counts a message that came (whether or not it is kept).
    void countArrival() { ++m_totalMessages; }
    /// Keeps a $SYS statistic's value (its first kMaxSysValueBytes); false when past a budget.
    bool addStatistic(const MqttMessage& msg);
    const QHash<QString, QString>& statistics() const { return m_sys; }
    /// The topic's node, made with its levels when new and within the budgets (new levels under a
    /// visible one go to its `pending`, that parent to `withPending`); null when past a budget.
    Node* admitTopic(const QString& topic, std::vector<Node*>& withPending);
    /// Counts a message on its topic's node and the levels above, marking them dirty.
    void count(Node* n, const MqttMessage& msg, std::vector<Node*>& dirty);
    /// Keeps the payload in the topic's history, within the bounds.
    void keep(Node* n, MqttMessage&& msg);

    Node* root() const { return m_root.get(); }
    Node* topic(const QString& topic) const { return m_byTopic.value(topic); }
    int topicCount() const { return int(m_byTopic.size()); }
    QStringList topicNames() const { return m_byTopic.keys(); }
    /// The level at a path ("" the root), or null.
    const Node* nodeAt(const QString& path) const;
    /// Every topic at or below a level (a topic itself, or all topics of a subtree).
    QStringList topicsBelow(const QString& path, int limit) const;
    /// Whether the broker may keep a retained message for the topic: one arrived retained, and
    /// the last payload is not the empty one that deletes it.
    bool mayHoldRetained(const QString& topic) const;

private:
    /// What adding the topic would cost the structure budget (its new levels and its entry, and for a
    /// type announcement its data topic's type).
    qint64 newTopicCost(const QString& topic) const;
    /// Whether a new topic (or $SYS statistic) of that cost fits both budgets; counted when not.
    bool admit(qint64 cost);
    Node* nodeFor(const QString& topic, std::vector<Node*>& withPending);
    /// Keeps a topic's history within its depth and bytes, and all topics' within the budget.
    void trimHistory(Node* n);
    void popOldest(Node* n);

    std::unique_ptr<Node> m_root;
    QHash<QString, Node*> m_byTopic;
    QHash<QString, QString> m_sys;
    int m_historyDepth = 20;
    qint64 m_historyBytesPerTopic = 16 * 1024 * 1024;
    quint64 m_totalMessages = 0;
    qint64 m_historyBudget = kDefaultHistoryBudget;
    qint64 m_historyBytes = 0;
    qint64 m_historyEntries = 0;
    quint64 m_historyOrder = 0;
    quint64 m_evictedPayloads = 0;
    int m_topicBudget = kDefaultTopicBudget;
    qint64 m_structureBudget = kDefaultStructureBudget;
    qint64 m_structureBytes = 0;
    quint64 m_untrackedMessages = 0;
    /// Every kept payload's topic and order, oldest first; entries of payloads a topic's own bounds
    /// removed are skipped when met, and swept when they are more than half.
    std::deque<std::pair<Node*, quint64>> m_historyQueue;
};
