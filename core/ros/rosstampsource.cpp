// SPDX-License-Identifier: MIT
#include "rosstampsource.h"

#include "base/eventbuffer.h"
#include "base/wallclock.h"
#include "ros/rosbytes.h"
#include "ros/rosnode.h"
#include "wire/sourcemessage.h"

#include <atomic>
#include <mutex>
#include <QCoreApplication>
#include <QHash>
#include <QPointer>
#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>

struct RosStampSource::Private
{
    std::shared_ptr<RosNode> rosNode = RosNode::acquire();
    int hook = 0;
    EventBuffer<StampEvent> stamps {200000};
    EventBuffer<LatencyValue> latencies {200000};
    std::atomic<quint64> received {0};
    std::atomic<quint64> malformed {0};
    std::atomic<quint64> wrongType {0};
    mutable std::mutex mutex;
    QSet<QString> wantedStamps; ///< guarded by mutex
    QSet<QString> wantedLatencies;
    QHash<QString, quint64> malformedByTopic; ///< guarded by mutex
    QString lastError; ///< guarded by mutex
    QHash<QString, ros::Subscriber> subscribers; ///< the node's worker thread only
    std::atomic<bool> closing {false}; ///< the owner is going: subscribe nothing more

    // roscpp spinner thread; rare (bad messages only), so a lock is fine.
    void fail(const QString& topic, const QString& why)
    {
        std::lock_guard<std::mutex> lock(mutex);
        ++malformedByTopic[topic];
        lastError = topic + QStringLiteral(": ") + why;
    }

    // roscpp spinner thread: a stamp (`latency` false) or a latency, checked by its md5.
    void onMessage(const QString& topic, const topic_tools::ShapeShifter& msg, bool latency)
    {
        const qint64 now = wallClockNs();
        received.fetch_add(1, std::memory_order_relaxed);
        if (msg.getMD5Sum() != (latency ? float64Md5() : StampCodec::md5())) {
            wrongType.fetch_add(1, std::memory_order_relaxed);
            fail(topic, (latency ? QCoreApplication::translate("RosStampSource", "a %1, not a std_msgs/Float64")
                                 : QCoreApplication::translate("RosStampSource",
                                                               "a %1, not a benchmarking_suite/TimeStamped"))
                            .arg(QString::fromStdString(msg.getDataType())));
            return;
        }
        StampReading r = SourceMessage::readStamp(
            {SourceGraph::Ros1, topic, QString::fromStdString(msg.getDataType()), now, RosBytes::of(msg)}, latency);
        if (r.stamp)
            stamps.push(std::move(*r.stamp));
        else if (r.latency)
            latencies.push(std::move(*r.latency));
        else {
            malformed.fetch_add(1, std::memory_order_relaxed);
            fail(topic, r.error);
        }
    }

    // The node's worker thread: makes the subscriptions match what is wanted.
    void sync(ros::NodeHandle& node, const std::weak_ptr<Private>& self,
              const QPointer<RosStampSource>& owner, bool again)
    {
        QSet<QString> stampTopics;
        QSet<QString> latencyTopics;
        {
            std::lock_guard<std::mutex> lock(mutex);
            stampTopics = wantedStamps;
            latencyTopics = wantedLatencies;
        }
        for (auto it = subscribers.begin(); it != subscribers.end();) {
            if (again || (!stampTopics.contains(it.key()) && !latencyTopics.contains(it.key())))
                it = subscribers.erase(it);
            else
                ++it;
        }
        if (closing.load())
            return;
        const auto subscribe = [&](const QString& topic, bool stamp) {
            if (subscribers.contains(topic) || closing.load())
                return;
            boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> cb
                = [self, topic, stamp](const topic_tools::ShapeShifter::ConstPtr& msg) {
                      if (auto p = self.lock())
                          p->onMessage(topic, *msg, !stamp);
                  };
            try {
                // A deep queue: stamps come in bursts of one per component and must not be lost.
                subscribers.insert(topic,
                                   node.subscribe<topic_tools::ShapeShifter>(topic.toStdString(), 1000, cb));
            } catch (const ros::Exception& e) {
                const QString why = QString::fromStdString(e.what());
                QMetaObject::invokeMethod(
                    owner,
                    [owner, topic, why] {
                        if (owner)
                            emit owner->subscribeFailed(topic, why);
                    },
                    Qt::QueuedConnection);
            }
        };
        for (const QString& t : std::as_const(stampTopics))
            subscribe(t, true);
        for (const QString& t : std::as_const(latencyTopics))
            subscribe(t, false);
    }

    void post(const std::shared_ptr<Private>& self, const QPointer<RosStampSource>& owner, bool again)
    {
        std::weak_ptr<Private> weak = self;
        rosNode->post([weak, owner, again](ros::NodeHandle& node) {
            if (auto p = weak.lock())
                p->sync(node, weak, owner, again);
        });
    }
};

RosStampSource::RosStampSource(QObject* parent)
    : QObject(parent)
    , d(std::make_shared<Private>())
{
    std::weak_ptr<Private> weak = d;
    QPointer<RosStampSource> self(this);
    d->hook = d->rosNode->addMasterChangedHook([weak, self] {
        if (auto p = weak.lock())
            p->post(p, self, true);
    });
}

RosStampSource::~RosStampSource()
{
    d->rosNode->removeHook(d->hook);
    d->closing = true;
    // the job keeps what it clears: a worker blocked past RosNode::kWaitMs runs it later
    d->rosNode->postAndWait([keep = d] { keep->subscribers.clear(); });
}

void RosStampSource::setMasterUri(const QString& uri)
{
    d->rosNode->setMasterUri(uri);
}

void RosStampSource::setTopics(const QSet<QString>& stampTopics, const QSet<QString>& latencyTopics)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (d->wantedStamps == stampTopics && d->wantedLatencies == latencyTopics)
            return;
        d->wantedStamps = stampTopics;
        d->wantedLatencies = latencyTopics;
    }
    d->post(d, this, false);
}

QSet<QString> RosStampSource::stampTopics() const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->wantedStamps;
}

QSet<QString> RosStampSource::latencyTopics() const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->wantedLatencies;
}

void RosStampSource::resubscribeAll()
{
    d->post(d, this, true);
}

void RosStampSource::takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies)
{
    std::vector<StampEvent> s = d->stamps.take();
    stamps.insert(stamps.end(), std::make_move_iterator(s.begin()), std::make_move_iterator(s.end()));
    const std::vector<LatencyValue> l = d->latencies.take();
    latencies.insert(latencies.end(), l.begin(), l.end());
}

quint64 RosStampSource::received() const
{
    return d->received.load(std::memory_order_relaxed);
}

quint64 RosStampSource::malformed() const
{
    return d->malformed.load(std::memory_order_relaxed);
}

quint64 RosStampSource::wrongType() const
{
    return d->wrongType.load(std::memory_order_relaxed);
}

QHash<QString, quint64> RosStampSource::malformedByTopic() const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->malformedByTopic;
}

QString RosStampSource::lastError() const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->lastError;
}

quint64 RosStampSource::dropped() const
{
    return d->stamps.dropped() + d->latencies.dropped();
}
