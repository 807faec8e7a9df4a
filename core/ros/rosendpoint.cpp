// SPDX-License-Identifier: MIT
#include "rosendpoint.h"

#include <map>
#include <mutex>
#include <ros/ros.h>
#include <thread>
#include <topic_tools/shape_shifter.h>
#include <vector>

using namespace Qt::StringLiterals;

namespace {
topic_tools::ShapeShifter shaped(const std::string& md5, const std::string& type,
                                 const std::string& definition, const QByteArray& bytes)
{
    topic_tools::ShapeShifter s;
    s.morph(md5, type, definition, "");
    // ShapeShifter::read copies from the stream; IStream wants a mutable pointer it never writes.
    ros::serialization::IStream in(reinterpret_cast<uint8_t*>(const_cast<char*>(bytes.constData())),
                                   uint32_t(bytes.size()));
    s.read(in);
    return s;
}
} // namespace

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

qint64 RosEndpoint::wallNs()
{
    const ros::WallTime t = ros::WallTime::now();
    return qint64(t.sec) * 1'000'000'000LL + t.nsec;
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
    boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> cb
        = [handler = std::move(handler)](const topic_tools::ShapeShifter::ConstPtr& msg) {
              const qint64 now = wallNs();
              RosRawMessage m;
              m.bytes = QByteArray(qsizetype(msg->size()), Qt::Uninitialized);
              ros::serialization::OStream out(reinterpret_cast<uint8_t*>(m.bytes.data()),
                                              uint32_t(m.bytes.size()));
              msg->write(out);
              m.type = QString::fromStdString(msg->getDataType());
              m.md5 = QString::fromStdString(msg->getMD5Sum());
              m.definition = QString::fromStdString(msg->getMessageDefinition());
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
        p.pub.publish(shaped(p.md5, p.type, p.definition, bytes));
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
