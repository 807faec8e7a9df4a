// SPDX-License-Identifier: MIT
#include "rosendpoint.h"

#include "base/wallclock.h"
#include "ros/rosbytes.h"
#include "ros/rosreregistration.h"

#include <atomic>
#include <condition_variable>
#include <cstring>
#include <map>
#include <mutex>
#include <ros/ros.h>
#include <thread>
#include <topic_tools/shape_shifter.h>
#include <utility>
#include <vector>

using namespace Qt::StringLiterals;

namespace {
/// Bytes to publish as they are, with their type by name (as ShapeShifter carries them, but copied
/// once, not twice); the serialized buffer tells `held` when roscpp lets go of it.
struct CountedBytes
{
    const std::string& md5;
    const std::string& type;
    const std::string& definition;
    const QByteArray& bytes;
    std::shared_ptr<std::atomic<qint64>> held;
};
} // namespace

namespace ros {
namespace message_traits {
template<> struct IsMessage<CountedBytes> : TrueType
{
};
template<> struct MD5Sum<CountedBytes>
{
    static const char* value() { return "*"; }
    static const char* value(const CountedBytes& m) { return m.md5.c_str(); }
};
template<> struct DataType<CountedBytes>
{
    static const char* value() { return "*"; }
    static const char* value(const CountedBytes& m) { return m.type.c_str(); }
};
template<> struct Definition<CountedBytes>
{
    static const char* value() { return ""; }
    static const char* value(const CountedBytes& m) { return m.definition.c_str(); }
};
} // namespace message_traits

namespace serialization {
/// Called by roscpp only when someone subscribes (or the topic is latched).
template<> inline SerializedMessage serializeMessage<CountedBytes>(const CountedBytes& m)
{
    const uint32_t length = uint32_t(m.bytes.size());
    const std::size_t total = std::size_t(length) + 4;
    std::shared_ptr<std::atomic<qint64>> held = m.held;
    *held += qint64(total);
    boost::shared_array<uint8_t> buf(new uint8_t[total], [held, total](uint8_t* p) {
        delete[] p;
        *held -= qint64(total);
    });
    OStream out(buf.get(), uint32_t(total));
    serialize(out, length);
    SerializedMessage serialized(buf, total);
    serialized.message_start = out.getData();
    std::memcpy(out.getData(), m.bytes.constData(), length);
    return serialized;
}
} // namespace serialization
} // namespace ros

struct RosEndpoint::Private
{
    std::unique_ptr<ros::NodeHandle> node;
    std::unique_ptr<ros::AsyncSpinner> spinner;
    std::vector<ros::Subscriber> subscribers;
    mutable std::mutex mutex; ///< guards publishers
    struct Publisher
    {
        ros::Publisher pub;
        std::string type, md5, definition;
        bool latched = false;
        qint64 lastBytes = 0; ///< latched: the message roscpp keeps for late subscribers
    };
    std::vector<Publisher> publishers; ///< retired ones have an empty `pub`
    std::vector<int> freeIds; ///< retired slots, reused so that type changes do not grow the table
    /// What roscpp holds of our messages: shared with their buffers, which may outlive us.
    std::shared_ptr<std::atomic<qint64>> held = std::make_shared<std::atomic<qint64>>(0);
    std::atomic<qint64> maxHeld {0};
    qint64 latchedBytes = 0; ///< of `held`, the latched topics' last messages (not a queue: never refused)

    // Watches the master: a restarted one is told about our topics again.
    std::thread watch;
    std::mutex watchMutex;
    std::condition_variable watchWake;
    bool watchStop = false;
    std::function<void(const QString&)> notice; ///< set before start()

    void watchMaster()
    {
        std::unique_lock<std::mutex> lock(watchMutex);
        bool wasAway = false;
        while (!watchWake.wait_for(lock, std::chrono::seconds(1), [this] { return watchStop; })) {
            lock.unlock();
            QString detail;
            const RosReregistration::Result r = RosReregistration::check(&detail);
            if (notice) {
                if (r == RosReregistration::Result::MasterUnreachable && !wasAway)
                    notice(RosEndpoint::tr("the ROS master does not answer; waiting for it"));
                else if (r == RosReregistration::Result::Reregistered)
                    notice(RosEndpoint::tr("the ROS master was restarted: %1").arg(detail));
                else if (r == RosReregistration::Result::Failed)
                    notice(RosEndpoint::tr("cannot register with the ROS master again: %1").arg(detail));
                else if (r == RosReregistration::Result::Registered && wasAway)
                    notice(RosEndpoint::tr("the ROS master answers again"));
            }
            wasAway = r == RosReregistration::Result::MasterUnreachable;
            lock.lock();
        }
    }
};

RosEndpoint::RosEndpoint()
    : d(std::make_unique<Private>())
{ }

RosEndpoint::~RosEndpoint()
{
    shutdown();
}

Status RosEndpoint::start(const QString& name, const QString& masterUri,
                          const std::function<bool()>& keepWaiting)
{
    std::map<std::string, std::string> remappings;
    if (!masterUri.isEmpty())
        remappings["__master"] = masterUri.toStdString();
    try {
        ros::init(remappings, name.toStdString(), ros::init_options::NoSigintHandler);
        ros::master::setRetryTimeout(ros::WallDuration(1.0));
        // Not ros::master::check(): it waits without end for a master that does not answer.
        while (!RosReregistration::masterAnswers()) {
            if (!keepWaiting || !keepWaiting())
                return LocatedError {
                    tr("no ROS master answers at %1").arg(QString::fromStdString(ros::master::getURI()))};
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        }
        d->node = std::make_unique<ros::NodeHandle>();
        // Two spinner threads: a big message being forwarded does not hold up the small ones.
        d->spinner = std::make_unique<ros::AsyncSpinner>(2);
        d->spinner->start();
        d->watchStop = false;
        d->watch = std::thread([p = d.get()] { p->watchMaster(); });
    } catch (const ros::Exception& e) {
        return LocatedError {QString::fromStdString(e.what())};
    }
    return {};
}

void RosEndpoint::shutdown()
{
    if (!d->node)
        return;
    if (d->watch.joinable()) {
        {
            std::lock_guard<std::mutex> lock(d->watchMutex);
            d->watchStop = true;
        }
        d->watchWake.notify_all();
        d->watch.join();
    }
    if (d->spinner)
        d->spinner->stop();
    d->subscribers.clear();
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->publishers.clear();
        d->freeIds.clear();
        d->latchedBytes = 0;
    }
    d->node.reset();
    ros::shutdown();
}

void RosEndpoint::setNoticeHandler(std::function<void(const QString&)> notice)
{
    d->notice = std::move(notice);
}

QString RosEndpoint::nodeName() const
{
    return QString::fromStdString(ros::this_node::getName());
}

QString RosEndpoint::resolve(const QString& name) const
{
    try {
        return QString::fromStdString(ros::names::resolve(name.toStdString()));
    } catch (const ros::Exception&) {
        return name;
    }
}

Status RosEndpoint::subscribe(const QString& topic, int queueSize, Handler handler)
{
    if (!d->node)
        return LocatedError {};
    // The type's texts are converted once per type, not per message (a definition is kilobytes);
    // roscpp never runs one subscription's callbacks concurrently.
    struct TypeCache
    {
        std::string md5;
        RosRawMessage texts;
    };
    auto type = std::make_shared<TypeCache>();
    boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> cb
        = [handler = std::move(handler), type](const topic_tools::ShapeShifter::ConstPtr& msg) {
              const qint64 now = wallClockNs();
              if (type->md5 != msg->getMD5Sum()) {
                  type->md5 = msg->getMD5Sum();
                  type->texts.type = QString::fromStdString(msg->getDataType());
                  type->texts.md5 = QString::fromStdString(type->md5);
                  type->texts.definition = QString::fromStdString(msg->getMessageDefinition());
              }
              RosRawMessage m = type->texts;
              m.bytes = RosBytes::of(*msg);
              handler(m, now);
          };
    try {
        ros::SubscribeOptions options;
        options.init<topic_tools::ShapeShifter>(topic.toStdString(), uint32_t(std::max(1, queueSize)), cb);
        options.transport_hints = ros::TransportHints().tcpNoDelay();
        d->subscribers.push_back(d->node->subscribe(options));
    } catch (const ros::Exception& e) {
        return LocatedError {QString::fromStdString(e.what())};
    }
    return {};
}

Result<int> RosEndpoint::advertise(const QString& topic, const QString& type, const QString& md5,
                                   const QString& definition, int queueSize, bool latched)
{
    if (!d->node)
        return LocatedError {};
    Private::Publisher p {{}, type.toStdString(), md5.toStdString(), definition.toStdString(), latched, 0};
    try {
        ros::AdvertiseOptions options(topic.toStdString(), uint32_t(std::max(1, queueSize)), p.md5, p.type,
                                      p.definition);
        options.latch = latched;
        p.pub = d->node->advertise(options);
    } catch (const ros::Exception& e) {
        return LocatedError {QString::fromStdString(e.what())};
    }
    // roscpp answers a second advertisement of a topic with another type by an invalid publisher
    // (and a log line); publishing on it aborts a Debug build.
    if (!p.pub)
        return LocatedError {tr("this node already publishes %1 with another type").arg(topic)};
    std::lock_guard<std::mutex> lock(d->mutex);
    if (!d->freeIds.empty()) {
        const int id = d->freeIds.back();
        d->freeIds.pop_back();
        d->publishers[std::size_t(id)] = std::move(p);
        return id;
    }
    d->publishers.push_back(std::move(p));
    return int(d->publishers.size()) - 1;
}

void RosEndpoint::retire(int publisher)
{
    ros::Publisher old;
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (publisher < 0 || std::size_t(publisher) >= d->publishers.size()
            || !d->publishers[std::size_t(publisher)].pub)
            return;
        old = std::move(d->publishers[std::size_t(publisher)].pub);
        d->publishers[std::size_t(publisher)].pub = ros::Publisher();
        d->latchedBytes -= std::exchange(d->publishers[std::size_t(publisher)].lastBytes, 0);
        d->freeIds.push_back(publisher);
    }
    old.shutdown(); // unregisters from the master: outside our lock
}

bool RosEndpoint::publish(int publisher, const QByteArray& bytes)
{
    return send(publisher, bytes) == Sent::Ok;
}

RosEndpoint::Sent RosEndpoint::send(int publisher, const QByteArray& bytes)
{
    std::lock_guard<std::mutex> lock(d->mutex);
    if (publisher < 0 || std::size_t(publisher) >= d->publishers.size())
        return Sent::Failed;
    Private::Publisher& p = d->publishers[std::size_t(publisher)];
    if (!p.pub)
        return Sent::Failed;
    // What roscpp queues: a latched topic's last message would otherwise stop all that follow.
    const qint64 queued = d->held->load() - d->latchedBytes;
    const qint64 max = d->maxHeld.load();
    if (max > 0 && queued > 0 && queued + bytes.size() + 4 > max)
        return Sent::Full;
    try {
        p.pub.publish(CountedBytes {p.md5, p.type, p.definition, bytes, d->held});
    } catch (const ros::Exception&) {
        return Sent::Failed;
    }
    if (p.latched)
        d->latchedBytes += bytes.size() + 4 - std::exchange(p.lastBytes, bytes.size() + 4);
    return Sent::Ok;
}

void RosEndpoint::setMaxHeldBytes(qint64 bytes)
{
    d->maxHeld = bytes;
}

qint64 RosEndpoint::heldBytes() const
{
    return d->held->load();
}

int RosEndpoint::subscriberCount(int publisher) const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    if (publisher < 0 || std::size_t(publisher) >= d->publishers.size()
        || !d->publishers[std::size_t(publisher)].pub)
        return 0;
    return int(d->publishers[std::size_t(publisher)].pub.getNumSubscribers());
}
