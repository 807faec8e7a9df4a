// SPDX-License-Identifier: MIT
#include "rosmonitor.h"

#include "base/logging.h"
#include "base/ratewindow.h"
#include "base/wallclock.h"
#include "latency/headhub.h"
#include "latency/taphub.h"
#include "ros/rosbytes.h"
#include "ros/rosmasterapi.h"
#include "ros/rosnode.h"
#include "ros/rosreregistration.h"
#include "ros/silentsubscriptions.h"

#include <algorithm>
#include <atomic>
#include <deque>
#include <mutex>
#include <optional>
#include <QDeadlineTimer>
#include <QPointer>
#include <QSet>
#include <QTimer>
#include <ros/ros.h>
#include <ros/xmlrpc_manager.h>
#include <topic_tools/shape_shifter.h>
#include <tuple>

using namespace Qt::StringLiterals;

namespace {

struct TopicState
{
    TopicStats stats;
    RateWindow rates;
};
} // namespace

struct RosMonitor::Private
{
    /// A tapped topic is subscribed as a monitored one is: one use of it while a tap is open.
    explicit Private(QPointer<RosMonitor> owner)
        : taps([owner](const QString& topic, bool tapped) {
            if (!owner)
                return;
            if (tapped)
                owner->monitor(topic);
            else
                owner->unmonitor(topic);
        })
    { }

    mutable std::mutex mutex;
    QHash<QString, TopicState> topics;
    std::atomic<quint64> typesLearned {0};
    std::atomic<quint64> subscriptions {0};
    std::deque<LearnedType> learned; ///< under `mutex`: the last kMaxLearnedKept learned types
    QHash<QString, int> wanted; ///< monitor() calls not yet balanced by unmonitor(), per topic
    std::shared_ptr<RosNode> rosNode = RosNode::acquire();
    int hook = 0;
    QHash<QString, ros::Subscriber> subscribers; ///< touched on the node's worker thread only
    TopicGraph graph; ///< under `mutex`: the master's, from setGraph()
    quint64 graphVersion = 0; ///< under `mutex`
    quint64 graphListed = 0; ///< the worker's: the graph version `silence` lists
    SilentSubscriptions silence; ///< the worker's only
    QHash<QString, QStringList> publishersOf; ///< the worker's: the graph's publishers but this node
    QHash<QString, QString> nodeUris; ///< the worker's: a publisher's address (empty: not found)
    static constexpr int kMaxLookupsPerPass = 10;
    static constexpr int kCallMs = 1000; ///< a lookup at the master, a publisherUpdate to this node
    std::atomic<quint64> askedAgain {0};
    std::atomic<quint64> madeAgain {0};
    static constexpr int kPassBudgetMs = 250; ///< a pass's calls, then the worker's other jobs
    static constexpr int kAsksBeforeSubscribing = 2; ///< asks (at 10, 30 s) before a new subscription (70 s)
    std::atomic<int> silentNow {0};
    HeadHub heads; ///< its own lock
    TapHub taps; ///< its own lock; a tapped topic is monitored while a tap of it is open

    void record(const QString& topic, const topic_tools::ShapeShifter::ConstPtr& msg)
    {
        const qint64 now = wallClockNs();
        QByteArray bytes = RosBytes::of(*msg);
        std::lock_guard<std::mutex> lock(mutex);
        auto it = topics.find(topic);
        if (it == topics.end())
            return; // unmonitored meanwhile
        TopicState& t = *it;
        ++t.stats.messages;
        t.stats.bytes += quint64(bytes.size());
        t.stats.lastSize = int(bytes.size());
        t.stats.lastNs = now;
        if (t.stats.type.isEmpty()) {
            t.stats.type = QString::fromStdString(msg->getDataType());
            t.stats.md5 = QString::fromStdString(msg->getMD5Sum());
            t.stats.definition = QString::fromStdString(msg->getMessageDefinition());
            learned.push_back({topic, t.stats.type, t.stats.definition});
            if (learned.size() > kMaxLearnedKept)
                learned.pop_front();
            ++typesLearned;
        }
        if (heads.active())
            heads.deliver(SourceHead::ofRos(SourceGraph::Ros1, topic, t.stats.type, now, bytes));
        taps.deliver({SourceGraph::Ros1, topic, {}, now, bytes}); // shares the bytes, no copy
        t.stats.lastMessage = std::move(bytes);
        t.rates.add(now, t.stats.lastSize);
    }

    // On the node's worker thread.
    void subscribe(ros::NodeHandle& node, const QString& topic, const std::weak_ptr<Private>& self,
                   QPointer<RosMonitor> owner)
    {
        subscribers.remove(topic);
        ++subscriptions;
        boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> cb
            = [self, topic](const topic_tools::ShapeShifter::ConstPtr& msg) {
                  if (auto p = self.lock())
                      p->record(topic, msg);
              };
        try {
            // TCP_NODELAY: what arrives is timed as it comes, not after Nagle's wait for the next
            // small message (up to 40 ms, which the observed hop latency would take for the bridge's).
            subscribers.insert(topic,
                               node.subscribe<topic_tools::ShapeShifter>(topic.toStdString(), 10, cb,
                                                                         ros::VoidConstPtr(),
                                                                         ros::TransportHints().tcpNoDelay()));
        } catch (const ros::Exception& e) {
            const QString why = QString::fromStdString(e.what());
            QMetaObject::invokeMethod(
                owner,
                [owner, topic, why] {
                    if (owner)
                        emit owner->monitorFailed(topic, why);
                },
                Qt::QueuedConnection);
        }
    }

    // On the node's worker thread: the publishers `graph` lists a topic of, this node not counted
    // (roscpp never connects a subscription to its own node's publisher through the master).
    void listPublished(const TopicGraph& graph)
    {
        const QString self = QString::fromStdString(ros::this_node::getName());
        publishersOf.clear();
        nodeUris.clear(); // a node started again has another address
        QSet<QString> listed;
        for (const TopicInfo& t : graph.topics) {
            QStringList others = t.publishers;
            others.removeAll(self);
            if (!others.isEmpty()) {
                listed.insert(t.name);
                publishersOf.insert(t.name, others);
            }
        }
        silence.setListed(std::move(listed));
    }

    // On the node's worker thread: the XML-RPC addresses of `topic`'s publishers, looked up at the
    // master (at most `*lookups` more calls, each within kCallMs; known ones kept until the graph
    // changes).
    QVariantList publisherUris(const QString& topic, const QString& caller, int* lookups)
    {
        QVariantList uris;
        for (const QString& node : publishersOf.value(topic)) {
            auto it = nodeUris.constFind(node);
            if (it == nodeUris.cend()) {
                if (*lookups <= 0)
                    continue;
                --*lookups;
                const RosMasterApi master(QString::fromStdString(ros::master::getURI()), caller);
                const Result<QVariant> uri = master.call(u"lookupNode"_s, {caller, node}, kCallMs);
                it = nodeUris.insert(node, uri ? uri->toString() : QString());
            }
            if (!it->isEmpty())
                uris.append(*it);
        }
        return uris;
    }

    // On the node's worker thread: asks again the publishers of what stayed silent (see
    // SilentSubscriptions) through this node's publisherUpdate, as the master does: roscpp starts a
    // request only to a publisher neither connected nor already asked, so a request still on its
    // way is not doubled, and nothing connected is dropped (only topics with none connected are
    // passed, with every publisher the master lists).
    void mendSilent(ros::NodeHandle& node, const std::weak_ptr<Private>& weakSelf, QPointer<RosMonitor> owner)
    {
        std::optional<TopicGraph> changed;
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (graphVersion != graphListed) {
                changed = graph;
                graphListed = graphVersion;
            }
        }
        if (changed)
            listPublished(*changed);
        const auto connected = [this](const QString& topic) {
            const auto it = subscribers.constFind(topic);
            return it == subscribers.cend() ? 0 : int(it->getNumPublishers());
        };
        // Candidates: subscribed topics that have heard nothing (one that heard is connected, and
        // roscpp tries a dropped connection again by itself).
        QList<QString> unheard;
        {
            std::lock_guard<std::mutex> lock(mutex);
            for (auto it = topics.cbegin(); it != topics.cend(); ++it) {
                if (it->stats.messages == 0 && subscribers.contains(it.key()))
                    unheard.append(it.key());
            }
        }
        const QList<QString> again = silence.pass(wallClockNs(), unheard, connected);
        int lookups = kMaxLookupsPerPass;
        const QString caller = QString::fromStdString(ros::this_node::getName());
        const QDeadlineTimer budget(kPassBudgetMs); // the worker subscribes for everyone else too
        for (const QString& topic : again) {
            if (budget.hasExpired())
                break; // the rest when next due
            if (silence.tries(topic) > kAsksBeforeSubscribing) {
                // Asked twice and still silent at 70 s: a request roscpp keeps waiting for that will
                // not come; only a new subscription forgets it.
                qCInfo(lcRos).noquote()
                    << u"subscribing again to %1: its publishers were asked and none connected"_s.arg(topic);
                subscribe(node, topic, weakSelf, owner);
                ++madeAgain;
                continue;
            }
            const QVariantList uris = publisherUris(topic, caller, &lookups);
            if (uris.isEmpty() || connected(topic) > 0)
                continue;
            qCInfo(lcRos).noquote()
                << u"asking the publishers of %1 again: the master lists them, none has connected"_s.arg(
                       topic);
            // This node's own publisherUpdate, as the master calls it (roscpp's is private).
            const RosMasterApi self(QString::fromStdString(ros::XMLRPCManager::instance()->getServerURI()),
                                    caller);
            if (self.call(u"publisherUpdate"_s, {caller, topic, uris}, kCallMs))
                ++askedAgain;
        }
        silentNow = silence.silent();
    }

    /// `unlessKnown`: not when the master knows this node (or knows it again once told).
    void subscribeAll(const std::shared_ptr<Private>& self, QPointer<RosMonitor> owner, bool unlessKnown)
    {
        std::weak_ptr<Private> weak = self;
        rosNode->post([weak, owner, unlessKnown](ros::NodeHandle& node) {
            auto p = weak.lock();
            if (!p)
                return;
            if (unlessKnown) {
                const RosReregistration::Result r = RosReregistration::check();
                if (r == RosReregistration::Result::Registered
                    || r == RosReregistration::Result::Reregistered)
                    return; // the master has every subscription, and the subscriptions their publishers
            }
            QList<QString> topics;
            {
                std::lock_guard<std::mutex> lock(p->mutex);
                topics = p->wanted.keys();
            }
            for (const QString& t : std::as_const(topics))
                p->subscribe(node, t, weak, owner);
        });
    }
};

RosMonitor::RosMonitor(QObject* parent)
    : QObject(parent)
    , d(std::make_shared<Private>(QPointer<RosMonitor>(this)))
{
    std::weak_ptr<Private> weak = d;
    QPointer<RosMonitor> self(this);
    d->hook = d->rosNode->addMasterChangedHook([weak, self] {
        if (auto p = weak.lock())
            p->subscribeAll(p, self, false); // another master
    });
}

RosMonitor::~RosMonitor()
{
    d->rosNode->removeHook(d->hook);
    // Subscribers die on the worker, before this object and its figures do (or, when the worker
    // is blocked in roscpp past RosNode::kWaitMs, whenever it is free: the job keeps them).
    d->rosNode->postAndWait([keep = d] { keep->subscribers.clear(); });
}

void RosMonitor::setMasterUri(const QString& uri)
{
    d->rosNode->setMasterUri(uri);
}

void RosMonitor::monitor(const QString& topic)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (d->wanted[topic]++ > 0)
            return; // subscribed for another user (the Links page, the Discover page's Mon)
        d->topics.insert(topic, TopicState());
    }
    std::weak_ptr<Private> weak = d;
    QPointer<RosMonitor> self(this);
    d->rosNode->post([weak, topic, self](ros::NodeHandle& node) {
        if (auto p = weak.lock())
            p->subscribe(node, topic, weak, self);
    });
}

void RosMonitor::unmonitor(const QString& topic)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        const auto it = d->wanted.find(topic);
        if (it == d->wanted.end() || --it.value() > 0)
            return; // not monitored, or still wanted by another user
        d->wanted.erase(it);
        d->topics.remove(topic);
    }
    std::weak_ptr<Private> weak = d;
    d->rosNode->post([weak, topic](ros::NodeHandle&) {
        if (auto p = weak.lock())
            p->subscribers.remove(topic);
    });
}

bool RosMonitor::isMonitored(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->wanted.contains(topic);
}

void RosMonitor::resubscribeAll()
{
    d->subscribeAll(d, this, true);
}

quint64 RosMonitor::subscriptions() const
{
    return d->subscriptions;
}

void RosMonitor::setGraph(const TopicGraph& graph)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->graph = graph;
        ++d->graphVersion;
    }
    if (m_mend)
        return;
    m_mend = new QTimer(this);
    connect(m_mend, &QTimer::timeout, this, [this] {
        {
            std::lock_guard<std::mutex> lock(d->mutex);
            if (d->wanted.isEmpty())
                return; // no node to start for it: looking registers nothing
        }
        std::weak_ptr<Private> weak = d;
        QPointer<RosMonitor> self(this);
        d->rosNode->post([weak, self](ros::NodeHandle& node) {
            if (auto p = weak.lock())
                p->mendSilent(node, weak, self);
        });
    });
    m_mend->start(kMendPeriodMs);
}

quint64 RosMonitor::publishersAskedAgain() const
{
    return d->askedAgain;
}

quint64 RosMonitor::subscriptionsMadeAgain() const
{
    return d->madeAgain;
}

int RosMonitor::silentSubscriptions() const
{
    return d->silentNow;
}

std::unique_ptr<HeadTap> RosMonitor::openHeadTap(std::size_t maxHeads)
{
    return d->heads.open(maxHeads);
}

std::unique_ptr<Tap> RosMonitor::openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    return d->taps.open(topic, maxMessages, maxBytes);
}

QHash<QString, TopicFigures> RosMonitor::figures(qint64 nowNs) const
{
    return topicFiguresOf(snapshot(nowNs));
}

quint64 RosMonitor::typesLearned() const
{
    return d->typesLearned;
}

std::vector<RosMonitor::LearnedType> RosMonitor::typesLearnedSince(quint64 from, bool* complete) const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    const quint64 total = d->typesLearned;
    const quint64 oldest = total - d->learned.size();
    *complete = from >= oldest;
    if (!*complete || from >= total)
        return {};
    return {d->learned.begin() + qsizetype(from - oldest), d->learned.end()};
}

QHash<QString, TopicStats> RosMonitor::snapshot(qint64 nowNs) const
{
    QHash<QString, TopicStats> out;
    std::lock_guard<std::mutex> lock(d->mutex);
    for (auto it = d->topics.cbegin(); it != d->topics.cend(); ++it) {
        TopicStats s = it->stats;
        std::tie(s.rateHz, s.bytesPerSecond) = it->rates.rates(nowNs);
        out.insert(it.key(), s);
    }
    return out;
}
