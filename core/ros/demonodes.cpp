// SPDX-License-Identifier: MIT
#include "demonodes.h"

#include "base/wallclock.h"
#include "ros/rosbytes.h"
#include "ros/rosendpoint.h"
#include "wire/stampcodec.h"

#include <geometry_msgs/PoseArray.h>
#include <random>
#include <sensor_msgs/PointCloud2.h>
#include <thread>

using namespace Qt::StringLiterals;

namespace {
template<typename M> Result<int> advertiseAs(RosEndpoint& ros, const QString& topic, int queue)
{
    return ros.advertise(topic, QString::fromLatin1(ros::message_traits::DataType<M>::value()),
                         QString::fromLatin1(ros::message_traits::MD5Sum<M>::value()),
                         QString::fromLatin1(ros::message_traits::Definition<M>::value()), queue, false);
}

/// The demo's stamp publisher: TimeStamped for a header, on this host's (offset) clock.
struct Stamper
{
    RosEndpoint& ros;
    int publisher = -1;
    qint64 offsetNs = 0;

    Status init(const QString& component)
    {
        const Result<int> advertised
            = ros.advertise(DemoNodes::stampPrefix() + component, QString::fromLatin1(StampCodec::typeName()),
                            QString::fromLatin1(StampCodec::md5()), StampCodec::definition(), 100, false);
        if (!advertised)
            return advertised.error();
        publisher = *advertised;
        return {};
    }
    void stamp(const std_msgs::Header& h, qint64 wallNs)
    {
        StampCodec::Decoded d;
        d.seq = h.seq;
        d.sampleNs = qint64(h.stamp.sec) * 1'000'000'000LL + h.stamp.nsec;
        d.frameId = QString::fromStdString(h.frame_id);
        d.timeNs = wallNs + offsetNs;
        ros.publish(publisher, StampCodec::encodeTimeStamped(d));
    }
};

bool waitUntil(const std::function<bool()>& stop, double seconds)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (stop())
            return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(std::min<int>(
            50,
            int(std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now())
                    .count())
                + 1)));
    }
    return true;
}
} // namespace

Status DemoNodes::runVehicle(const Options& o, const std::function<bool()>& stop)
{
    RosEndpoint ros;
    if (Status started = ros.start(u"demo_vehicle"_s, o.masterUri, [&stop] { return !stop(); }); !started)
        return started;
    Stamper sent {ros, -1, o.clockOffsetNs};
    Stamper back {ros, -1, o.clockOffsetNs};
    const Result<int> cloud = advertiseAs<sensor_msgs::PointCloud2>(ros, u"/vehicle/pointcloud"_s, 10);
    if (!cloud)
        return cloud.error();
    const int cloudPub = *cloud;
    for (auto [stamper, component] :
         {std::pair {&sent, u"pointcloud"_s}, std::pair {&back, u"object_list"_s}})
        if (Status advertised = stamper->init(component); !advertised)
            return advertised;
    if (Status subscribed
        = ros.subscribe(u"/vehicle/object_list"_s, 10,
                        [&back](const RosRawMessage& m, qint64 receivedNs) {
                            back.stamp(RosBytes::read<geometry_msgs::PoseArray>(m.bytes).header, receivedNs);
                        });
        !subscribed)
        return subscribed;

    // A VelodyneScan-sized cloud: 16-byte points (x, y, z, intensity), one row.
    sensor_msgs::PointCloud2 scan;
    scan.header.frame_id = "velodyne";
    scan.height = 1;
    scan.width = uint32_t(std::max(1, o.payloadBytes / 16));
    scan.point_step = 16;
    scan.row_step = scan.width * scan.point_step;
    scan.is_dense = true;
    for (const auto& [name, offset] : {std::pair {"x", 0}, {"y", 4}, {"z", 8}, {"intensity", 12}}) {
        sensor_msgs::PointField f;
        f.name = name;
        f.offset = uint32_t(offset);
        f.datatype = sensor_msgs::PointField::FLOAT32;
        f.count = 1;
        scan.fields.push_back(f);
    }
    scan.data.resize(std::size_t(scan.row_step));
    std::mt19937 rng(7);
    for (auto& b : scan.data)
        b = uint8_t(rng());

    // Start when the bridge and a measuring Bridgescope listen (at most 15 s): samples sent
    // before would count as dropped, though nothing was lost.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
    while (!stop() && std::chrono::steady_clock::now() < deadline
           && (ros.subscriberCount(cloudPub) == 0 || ros.subscriberCount(sent.publisher) == 0))
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (!waitUntil(stop, 0.5)) // the other components' stamp subscriptions settle
        return {};

    const double period = 1.0 / std::max(0.1, o.rateHz);
    auto next = std::chrono::steady_clock::now();
    quint32 seq = 0;
    while (!stop()) {
        const qint64 now = wallClockNs() + o.clockOffsetNs;
        scan.header.seq = ++seq;
        scan.header.stamp.sec = uint32_t(now / 1'000'000'000LL);
        scan.header.stamp.nsec = uint32_t(now % 1'000'000'000LL);
        const QByteArray bytes = RosBytes::of(scan);
        sent.stamp(scan.header, wallClockNs());
        ros.publish(cloudPub, bytes);
        next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(period));
        const double wait = std::chrono::duration<double>(next - std::chrono::steady_clock::now()).count();
        if (wait > 0 && !waitUntil(stop, wait))
            break;
    }
    ros.shutdown();
    return {};
}

Status DemoNodes::runCloud(const Options& o, const std::function<bool()>& stop)
{
    RosEndpoint ros;
    if (Status started = ros.start(u"demo_object_detection"_s, o.masterUri, [&stop] { return !stop(); });
        !started)
        return started;
    Stamper in {ros, -1, o.clockOffsetNs};
    Stamper out {ros, -1, o.clockOffsetNs};
    const Result<int> list = advertiseAs<geometry_msgs::PoseArray>(ros, u"/cloud/object_list"_s, 10);
    if (!list)
        return list.error();
    const int listPub = *list;
    for (auto [stamper, component] : {std::pair {&in, u"object_detection/pointcloud"_s},
                                      std::pair {&out, u"object_detection/object_list"_s}})
        if (Status advertised = stamper->init(component); !advertised)
            return advertised;
    auto rng = std::make_shared<std::mt19937>(11);
    const double meanMs = o.detectionMs;
    if (Status subscribed = ros.subscribe(
            u"/cloud/pointcloud"_s, 2,
            [&, rng, meanMs](const RosRawMessage& m, qint64 receivedNs) {
                const sensor_msgs::PointCloud2 scan = RosBytes::read<sensor_msgs::PointCloud2>(m.bytes);
                in.stamp(scan.header, receivedNs);
                // "Inference": about the mean, varying like a real network's run time.
                std::gamma_distribution<double> work(16.0, meanMs / 16.0);
                std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(work(*rng)));
                geometry_msgs::PoseArray objects;
                objects.header = scan.header;
                std::uniform_int_distribution<int> count(3, 12);
                objects.poses.resize(std::size_t(count(*rng)));
                for (std::size_t i = 0; i < objects.poses.size(); ++i) {
                    objects.poses[i].position.x = double(i) * 2.5;
                    objects.poses[i].orientation.w = 1;
                }
                out.stamp(objects.header, wallClockNs());
                ros.publish(listPub, RosBytes::of(objects));
            });
        !subscribed)
        return subscribed;
    while (!stop())
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ros.shutdown();
    return {};
}
