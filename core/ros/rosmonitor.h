// SPDX-License-Identifier: MIT
#pragma once

#include "latency/messagesource.h"
#include "topics/topicgraph.h"

#include <memory>
#include <QByteArray>
#include <QHash>
#include <QObject>
#include <QString>
#include <vector>

/// Generic subscriptions to ROS topics for monitoring (the only code that uses roscpp).
///
/// The process gets one roscpp node, started on first use, registered with the master given
/// here; subscribing happens on a worker thread (the master may be slow or gone), callbacks on a
/// roscpp spinner thread that only updates the figures under a lock. The GUI takes snapshots.
class RosMonitor : public QObject, public MessageSource
{
    Q_OBJECT
public:
    explicit RosMonitor(QObject* parent = nullptr);
    ~RosMonitor() override;

    /// The master to register with; switches the process's roscpp node when it changes.
    void setMasterUri(const QString& uri);
    /// Subscribes to a topic. Calls are counted: the subscription ends with the unmonitor() that
    /// balances the last monitor(), so that two users (the Discover page's Mon, the Links page)
    /// do not end each other's.
    void monitor(const QString& topic) override;
    void unmonitor(const QString& topic) override;
    bool isMonitored(const QString& topic) const override;
    SourceGraph sourceGraph() const override { return SourceGraph::Ros1; }
    /// Registers every monitored topic again after the master restarted (RosGraphPoller::
    /// masterRestarted()): not when the master still knows this node, or knows it again once told
    /// (RosReregistration::check()). A master that answered a poll late (busy with 10,000 topics)
    /// is the same master; subscribing 10,000 topics again tore down every connection (issue 44).
    void resubscribeAll();
    /// The master's graph: the publishers of a monitored topic that stays without one connected
    /// while the master lists them are asked again (see SilentSubscriptions), checked every
    /// kMendPeriodMs.
    void setGraph(const TopicGraph& graph);
    static constexpr int kMendPeriodMs = 2000;
    /// Silent topics whose publishers were asked again, since the start.
    quint64 publishersAskedAgain() const;
    /// Silent topics subscribed again after their publishers were asked twice in vain
    /// (roscpp waits without end for a request that never comes back), since the start.
    quint64 subscriptionsMadeAgain() const;
    /// Monitored topics silent for SilentSubscriptions::kSilentNs or more at the last check.
    int silentSubscriptions() const;
    /// How many times a topic was subscribed in roscpp (monitor() and resubscriptions).
    quint64 subscriptions() const;
    /// Current figures of every monitored topic (rates computed for `nowNs`).
    QHash<QString, TopicStats> snapshot(qint64 nowNs) const;
    /// How many times a monitored topic's type became known (its first message): a reader of the
    /// types takes snapshot() only when this moved.
    quint64 typesLearned() const;
    /// A type that became known: the n-th (from 0) of typesLearned().
    struct LearnedType
    {
        QString topic;
        QString type;
        QString definition;
    };
    /// The most learned types kept for typesLearnedSince(); a reader further behind takes snapshot().
    static constexpr std::size_t kMaxLearnedKept = 20000;
    /// The types learned from the `from`-th on (a reader's cursor: typesLearned() when it last read),
    /// so that a fleet's 10,000 topics learning their types one by one cost one each, not a snapshot
    /// of all each second. Nothing, and `*complete` false, when some are no longer kept.
    std::vector<LearnedType> typesLearnedSince(quint64 from, bool* complete) const;
    QHash<QString, TopicFigures> figures(qint64 nowNs) const override;
    std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads) override;
    /// While a tap of a topic is open, the topic is monitored for it (one use, counted with the
    /// others); its messages come without their type (the monitor's figures have it).
    std::unique_ptr<Tap> openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override;

signals:
    void monitorFailed(const QString& topic, const QString& why);

private:
    struct Private;
    std::shared_ptr<Private> d;
    class QTimer* m_mend = nullptr; ///< from the first setGraph()
};
