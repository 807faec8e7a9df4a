// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"
#include "mqtt/mqtttopics.h"
#include "wire/mqttclientwire.h"

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <QAbstractItemModel>
#include <QHash>
#include <vector>

class RosTypeRegistry;

/// The broker's topics as a tree of levels, with live figures, updated in batches.
///
/// Every topic keeps its message and byte counts, rate, last size, retained flag and QoS, the time
/// of its last message, and a bounded history of payloads (historyDepth() per topic, 16 MiB per
/// topic, and historyBudget() over all topics: past it the oldest payloads of any topic go first,
/// counted by evictedPayloads()); every level sums its subtree. The last payload's first
/// kPreviewBytes are kept apart for a one-line preview (ValueColumn). What a broker's clients announce
/// is bounded too: at most topicBudget() topics, and structureBudget() bytes of levels (their names,
/// paths and nodes; a name may be as long as MQTT allows). A topic past either is not added, and
/// its messages are counted by untrackedMessages(); the topics kept go on updating. Topics
/// that mqtt_client (ROS 1 or ROS 2) announces get their ROS type; stamped ones their one-way
/// latency. A ROS 1 announcement carries its definition; a ROS 2 one names its type only, which
/// decodes with the ROS 2 definitions the tree is given (setRos2Registry()). $SYS topics
/// are kept apart as broker statistics. Batches come from the GUI drain timer (apply()); one batch
/// gives one row-insert per parent and one dataChanged per parent, never a signal per message.
/// The figures and budgets named here are the topic store's (topicData().store()).
///
/// The tree is the Qt model of the kept topics (MqttTopics in core/mqtt: the topic store and the
/// payload checks), which it owns and feeds: what is not rows (figures, history, types, budgets) is
/// there, and topicData() hands it to readers that need no model.
class MqttTopicTree : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column {
        TopicColumn,
        MessagesColumn,
        RateColumn,
        BytesColumn,
        SizeColumn,
        RetainedColumn,
        QosColumn,
        LastColumn,
        RosTypeColumn,
        LatencyColumn,
        ValueColumn, ///< the last payload, shortened to one line (MQTT Explorer's habit)
        ColumnCount
    };
    enum Role {
        FullTopicRole = Qt::UserRole + 1, ///< "a/b/c"
        IsTopicRole, ///< bool: messages arrived on exactly this topic
        SortRole,
        SearchTextRole, ///< the last payload as text (for filtering by content)
        RosTypeRole,
        StampedRole,
    };

    using HistoryEntry = MqttTopicNode::HistoryEntry;
    /// The default of historyBudget(): the bytes the payload history of all topics may hold.
    static constexpr qint64 kDefaultHistoryBudget = MqttTopicStore::kDefaultHistoryBudget;
    /// What one kept payload costs beside its bytes (its entry and the array's header), counted in the
    /// budget.
    static constexpr qint64 kHistoryEntryOverhead = MqttTopicStore::kHistoryEntryOverhead;
    /// The default of topicBudget(): the topics (and $SYS statistics) the tree keeps.
    static constexpr int kDefaultTopicBudget = MqttTopicStore::kDefaultTopicBudget;
    /// The default of structureBudget(): the bytes the levels of all topics may take.
    static constexpr qint64 kDefaultStructureBudget = MqttTopicStore::kDefaultStructureBudget;
    /// What one level costs beside its name and path: the node (about 600 bytes), the blocks its
    /// three deques allocate when made (about 600 bytes each) and its hash entries.
    static constexpr qint64 kNodeOverhead = MqttTopicStore::kNodeOverhead;
    /// A topic's last payload is kept up to this many bytes for ValueColumn's preview (beside the
    /// history, which a busy broker may evict): at most topicBudget() × this (5 MiB by default).
    static constexpr qsizetype kPreviewBytes = MqttTopicStore::kPreviewBytes;
    /// The characters ValueColumn shows of it, on one line.
    static constexpr qsizetype kPreviewChars = 80;
    /// A $SYS statistic's value is kept up to this many bytes.
    static constexpr qsizetype kMaxSysValueBytes = MqttTopicStore::kMaxSysValueBytes;

    using TopicInfo = MqttTopics::TopicInfo;

    /// Handles ROS topics dropped on a level (its path) or beside the tree (empty).
    using DropHandler = std::function<bool(const QMimeData* data, const QString& targetPath)>;

    explicit MqttTopicTree(QObject* parent = nullptr);
    void setDropHandler(DropHandler handler) { m_dropHandler = std::move(handler); }
    /// Whether a level has levels below it.
    bool hasChildren(const QString& path) const;
    ~MqttTopicTree() override;

    void setHistoryDepth(int messages) { m_topics.store().setHistoryDepth(messages); }
    /// The bytes the history of all topics may hold (payloads and kHistoryEntryOverhead each).
    void setHistoryBudget(qint64 bytes) { m_topics.store().setHistoryBudget(bytes); }
    /// The topics the tree keeps at most (at least 1); a new topic past it is not added.
    void setTopicBudget(int topics) { m_topics.store().setTopicBudget(topics); }
    /// The bytes the levels may take (names and paths as UTF-16, kNodeOverhead each); a new topic
    /// whose levels do not fit is not added.
    void setStructureBudget(qint64 bytes) { m_topics.store().setStructureBudget(bytes); }
    void apply(std::vector<MqttMessage>&& batch);
    /// Updates rates once a second, and says the figures that changed since the last time once a
    /// figures interval; `nowNs` is wall-clock time.
    void tick(qint64 nowNs);
    /// The changed figures of rows (messages, bytes, sizes, latencies) are said (dataChanged) at
    /// most once per `ms`, at a tick(); new rows at once. 0, the default: at every apply(). A
    /// window sets it: a view repaints and re-measures its rows for every dataChanged, and a busy
    /// broker changes some row at every drain.
    void setFiguresInterval(int ms) { m_figuresIntervalNs = qint64(ms) * 1'000'000; }
    void clear();

    QModelIndex indexOf(const QString& topic, int column = 0) const;
    /// The ROS 2 definitions announced ROS 2 types decode with; until set, the bundled ones
    /// (Ros2Definitions::registry(), built once and shared by every tree).
    void setRos2Registry(std::shared_ptr<const RosTypeRegistry> registry);
    /// The kept topics the rows show: their figures, history, types and budgets (what the tree
    /// keeps at most is set here).
    const MqttTopics& topicData() const { return m_topics; }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
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

signals:
    void brokerStatisticsChanged();

private:
    using Node = MqttTopicNode;
    QModelIndex indexOf(const Node* node, int column) const;
    /// Announces the levels made in a batch: one row-insert per parent.
    void insertPending(const std::vector<Node*>& withPending);
    void sayFigures();

    MqttTopics m_topics;
    std::vector<Node*> m_dirty; ///< rows whose figures changed since sayFigures()
    qint64 m_figuresIntervalNs = 0;
    qint64 m_figuresSaidNs = 0;
    DropHandler m_dropHandler;
};
