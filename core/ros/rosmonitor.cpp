// SPDX-License-Identifier: MIT
#include "rosmonitor.h"

#include <deque>
#include <mutex>
#include <QSet>
#include <QThread>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>

using namespace Qt::StringLiterals;

namespace ros::master {
// Exported by libroscpp but not declared in its headers: points master calls at another URI.
void init(const M_string& remappings);
} // namespace ros::master

namespace {
constexpr qint64 kRateWindowNs = 5'000'000'000LL;

qint64 wallNs()
{
    const ros::WallTime t = ros::WallTime::now();
    return qint64(t.sec) * 1000000000LL + t.nsec;
}

struct TopicState
{
    RosMonitorStats stats;
    std::deque<std::pair<qint64, int>> arrivals; ///< (time, size) within the rate window
};
} // namespace

struct RosMonitor::Private
{
    mutable std::mutex mutex;
    QHash<QString, TopicState> topics;
    QSet<QString> wanted;
    QThread thread;
    QObject* worker = nullptr; ///< lives in `thread`; roscpp calls that may block run there
    ros::CallbackQueue queue; ///< our own, so that other spinners in the process do not interfere
    std::unique_ptr<ros::NodeHandle> node;
    std::unique_ptr<ros::AsyncSpinner> spinner;
    QHash<QString, ros::Subscriber> subscribers; ///< touched on the worker thread only
    QString masterUri;

    void record(const QString& topic, const topic_tools::ShapeShifter::ConstPtr& msg)
    {
        const qint64 now = wallNs();
        QByteArray bytes(qsizetype(msg->size()), Qt::Uninitialized);
        ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(bytes.data()), uint32_t(bytes.size()));
        msg->write(stream);
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
        }
        t.stats.lastMessage = std::move(bytes);
        t.arrivals.emplace_back(now, t.stats.lastSize);
        while (t.arrivals.size() > 20000
               || (!t.arrivals.empty() && now - t.arrivals.front().first > kRateWindowNs))
            t.arrivals.pop_front();
    }

    // On the worker thread.
    void ensureNode()
    {
        if (node)
            return;
        ros::M_string remappings;
        remappings["__master"] = masterUri.toStdString();
        if (!ros::isInitialized())
            ros::init(remappings, "bridgescope",
                      ros::init_options::AnonymousName | ros::init_options::NoSigintHandler
                          | ros::init_options::NoRosout);
        // A dead master must not hold a subscription forever.
        ros::master::setRetryTimeout(ros::WallDuration(2.0));
        node = std::make_unique<ros::NodeHandle>();
        node->setCallbackQueue(&queue);
        spinner = std::make_unique<ros::AsyncSpinner>(1, &queue);
        spinner->start();
    }

    void subscribe(const QString& topic, const std::weak_ptr<Private>& self, RosMonitor* owner)
    {
        ensureNode();
        subscribers.remove(topic);
        const std::string name = topic.toStdString();
        boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> cb
            = [self, topic](const topic_tools::ShapeShifter::ConstPtr& msg) {
                  if (auto p = self.lock())
                      p->record(topic, msg);
              };
        try {
            ros::Subscriber sub = node->subscribe<topic_tools::ShapeShifter>(name, 10, cb);
            subscribers.insert(topic, sub);
        } catch (const ros::Exception& e) {
            const QString why = QString::fromStdString(e.what());
            QMetaObject::invokeMethod(
                owner, [owner, topic, why] { emit owner->monitorFailed(topic, why); }, Qt::QueuedConnection);
        }
    }
};

RosMonitor::RosMonitor(QObject* parent)
    : QObject(parent)
    , d(std::make_shared<Private>())
{
    d->worker = new QObject;
    d->worker->moveToThread(&d->thread);
    connect(&d->thread, &QThread::finished, d->worker, &QObject::deleteLater);
    d->thread.setObjectName(u"ros-monitor"_s);
    d->thread.start();
    d->masterUri = qEnvironmentVariable("ROS_MASTER_URI", u"http://localhost:11311/"_s);
}

RosMonitor::~RosMonitor()
{
    std::shared_ptr<Private> p = d;
    QMetaObject::invokeMethod(
        p->worker,
        [p] {
            p->subscribers.clear();
            if (p->spinner)
                p->spinner->stop();
            p->spinner.reset();
            p->node.reset();
        },
        Qt::BlockingQueuedConnection);
    d->thread.quit();
    d->thread.wait();
}

void RosMonitor::setMasterUri(const QString& uri)
{
    std::shared_ptr<Private> p = d;
    QMetaObject::invokeMethod(p->worker, [p, uri, this] {
        if (uri == p->masterUri && p->node)
            return;
        p->masterUri = uri;
        if (!p->node)
            return; // used when the node starts
        ros::M_string remappings;
        remappings["__master"] = uri.toStdString();
        ros::master::init(remappings);
        const QList<QString> topics = p->subscribers.keys();
        for (const QString& t : topics)
            p->subscribe(t, p, this);
    });
}

void RosMonitor::monitor(const QString& topic)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (d->wanted.contains(topic))
            return;
        d->wanted.insert(topic);
        d->topics.insert(topic, TopicState());
    }
    std::shared_ptr<Private> p = d;
    QMetaObject::invokeMethod(p->worker, [p, topic, this] { p->subscribe(topic, p, this); });
}

void RosMonitor::unmonitor(const QString& topic)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->wanted.remove(topic);
        d->topics.remove(topic);
    }
    std::shared_ptr<Private> p = d;
    QMetaObject::invokeMethod(p->worker, [p, topic] { p->subscribers.remove(topic); });
}

bool RosMonitor::isMonitored(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->wanted.contains(topic);
}

void RosMonitor::resubscribeAll()
{
    std::shared_ptr<Private> p = d;
    QMetaObject::invokeMethod(p->worker, [p, this] {
        QList<QString> topics;
        {
            std::lock_guard<std::mutex> lock(p->mutex);
            topics = p->wanted.values();
        }
        for (const QString& t : std::as_const(topics))
            p->subscribe(t, p, this);
    });
}

QHash<QString, RosMonitorStats> RosMonitor::snapshot(qint64 nowNs) const
{
    QHash<QString, RosMonitorStats> out;
    std::lock_guard<std::mutex> lock(d->mutex);
    for (auto it = d->topics.cbegin(); it != d->topics.cend(); ++it) {
        RosMonitorStats s = it->stats;
        // Rate as rostopic hz computes it: intervals between the arrivals still in the window.
        qsizetype n = 0;
        qint64 first = 0;
        qint64 bytes = 0;
        for (const auto& [t, size] : it->arrivals) {
            if (nowNs - t > kRateWindowNs)
                continue;
            if (n == 0)
                first = t;
            ++n;
            bytes += size;
        }
        const qint64 span = nowNs - first;
        s.rateHz = n >= 2 && s.lastNs > first ? double(n - 1) / (double(s.lastNs - first) / 1e9) : 0;
        s.bytesPerSecond
            = n >= 1 && span > 0 ? double(bytes) / (double(std::max<qint64>(span, 1000000000LL)) / 1e9) : 0;
        out.insert(it.key(), s);
    }
    return out;
}
