// SPDX-License-Identifier: MIT
#include "rosendpoint.h"

#include "common/wallclock.h"
#include "rosbytes.h"

#include <map>
#include <mutex>
#include <ros/ros.h>
#include <thread>
#include <topic_tools/shape_shifter.h>
#include <vector>

using namespace Qt::StringLiterals;

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
    };
    std::vector<Publisher> publishers;
};

RosEndpoint::RosEndpoint()
    : d(std::make_unique<Private>())
{ }

RosEndpoint::~RosEndpoint()
{
    shutdown();
}

bool RosEndpoint::start(const QString& name, const QString& masterUri,
                        const std::function<bool()>& keepWaiting, QString* error)
{
    std::map<std::string, std::string> remappings;
    if (!masterUri.isEmpty())
        remappings["__master"] = masterUri.toStdString();
    try {
        ros::init(remappings, name.toStdString(), ros::init_options::NoSigintHandler);
        ros::master::setRetryTimeout(ros::WallDuration(1.0));
        while (!ros::master::check()) {
            if (!keepWaiting || !keepWaiting()) {
                if (error)
                    *error = tr("no ROS master answers at %1")
                                 .arg(QString::fromStdString(ros::master::getURI()));
                return false;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        }
        d->node = std::make_unique<ros::NodeHandle>();
        // Two spinner threads: a big message being forwarded does not hold up the small ones.
        d->spinner = std::make_unique<ros::AsyncSpinner>(2);
        d->spinner->start();
    } catch (const ros::Exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

void RosEndpoint::shutdown()
{
    if (!d->node)
        return;
    if (d->spinner)
        d->spinner->stop();
    d->subscribers.clear();
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->publishers.clear();
    }
    d->node.reset();
    ros::shutdown();
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

bool RosEndpoint::subscribe(const QString& topic, int queueSize, Handler handler, QString* error)
{
    if (!d->node)
        return false;
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
        if (error)
            *error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

int RosEndpoint::advertise(const QString& topic, const QString& type, const QString& md5,
                           const QString& definition, int queueSize, bool latched, QString* error)
{
    if (!d->node)
        return -1;
    Private::Publisher p {{}, type.toStdString(), md5.toStdString(), definition.toStdString()};
    try {
        ros::AdvertiseOptions options(topic.toStdString(), uint32_t(std::max(1, queueSize)), p.md5, p.type,
                                      p.definition);
        options.latch = latched;
        p.pub = d->node->advertise(options);
    } catch (const ros::Exception& e) {
        if (error)
            *error = QString::fromStdString(e.what());
        return -1;
    }
    std::lock_guard<std::mutex> lock(d->mutex);
    d->publishers.push_back(std::move(p));
    return int(d->publishers.size()) - 1;
}

bool RosEndpoint::publish(int publisher, const QByteArray& bytes)
{
    std::lock_guard<std::mutex> lock(d->mutex);
    if (publisher < 0 || std::size_t(publisher) >= d->publishers.size())
        return false;
    const Private::Publisher& p = d->publishers[std::size_t(publisher)];
    try {
        p.pub.publish(RosBytes::shaped(p.md5, p.type, p.definition, bytes));
    } catch (const ros::Exception&) {
        return false;
    }
    return true;
}

int RosEndpoint::subscriberCount(int publisher) const
{
    std::lock_guard<std::mutex> lock(d->mutex);
    if (publisher < 0 || std::size_t(publisher) >= d->publishers.size())
        return 0;
    return int(d->publishers[std::size_t(publisher)].pub.getNumSubscribers());
}
