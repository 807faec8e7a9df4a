// SPDX-License-Identifier: MIT
// A ROS node for tests: publishes benchmarking_suite/TimeStamped samples (through ShapeShifter,
// morphed with the type's md5, name and full definition, so the suite need not be installed) and
// std_msgs/Float64 latencies, on a deterministic schedule the tests can recompute.
//
//   stamp_publisher --samples N --rate HZ --stamp TOPIC:OFFSET_US [--stamp ...]
//                   [--latency TOPIC:SECONDS] [--first-sample SEC] [--jitter-us J --seed N]
//                   [--malformed TOPIC]   (TimeStamped's type, 10 bytes of it: no message)
//
// Sample s has header.stamp = first + s / rate; topic i stamps it at
// stamp + OFFSET_US_i + i * (s % 7) * 100 µs, or, with --jitter-us, at stamp + OFFSET_US_i plus
// the sum of i exponential delays of mean J µs (stages stay in order, values look measured). It waits (up to
// 30 s) until every topic has a subscriber, then publishes, and prints "done" when finished.
#include "ros/rosbytes.h"
#include "wire/stampcodec.h"

#include <cstdio>
#include <cstring>
#include <QCoreApplication>
#include <QStringList>
#include <random>
#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>

namespace {
struct Stream
{
    std::string topic;
    qint64 offsetNs = 0;
    ros::Publisher pub;
    bool malformed = false; ///< the right type, cut to 10 bytes
};

} // namespace

int main(int argc, char** argv)
{
    ros::init(argc, argv, "stamp_publisher", ros::init_options::AnonymousName | ros::init_options::NoRosout);
    QCoreApplication app(argc, argv);
    int samples = 10;
    double jitterUs = 0;
    unsigned seed = 1;
    double rate = 20;
    qint64 firstNs = 1'700'000'000LL * 1'000'000'000LL;
    std::vector<Stream> streams;
    std::vector<std::pair<std::string, double>> latencies;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); i += 2) {
        const QString& opt = args[i];
        const QString& val = args[i + 1];
        if (opt == QStringLiteral("--samples"))
            samples = val.toInt();
        else if (opt == QStringLiteral("--rate"))
            rate = val.toDouble();
        else if (opt == QStringLiteral("--jitter-us"))
            jitterUs = val.toDouble();
        else if (opt == QStringLiteral("--seed"))
            seed = val.toUInt();
        else if (opt == QStringLiteral("--first-sample"))
            firstNs = val.toLongLong() * 1'000'000'000LL;
        else if (opt == QStringLiteral("--stamp"))
            streams.push_back(
                {val.section(u':', 0, 0).toStdString(), val.section(u':', 1).toLongLong() * 1000, {}});
        else if (opt == QStringLiteral("--malformed"))
            streams.push_back({val.toStdString(), 0, {}, true});
        else if (opt == QStringLiteral("--latency"))
            latencies.emplace_back(val.section(u':', 0, 0).toStdString(), val.section(u':', 1).toDouble());
    }
    ros::NodeHandle node;
    const std::string md5 = StampCodec::md5();
    const std::string type = StampCodec::typeName();
    const std::string definition = StampCodec::definition().toStdString();
    for (Stream& s : streams) {
        topic_tools::ShapeShifter proto
            = RosBytes::shaped(md5, type, definition, StampCodec::encodeTimeStamped({}));
        s.pub = proto.advertise(node, s.topic, 1000);
    }
    std::vector<ros::Publisher> latencyPubs;
    for (const auto& [topic, seconds] : latencies) {
        QByteArray bytes(8, Qt::Uninitialized);
        std::memcpy(bytes.data(), &seconds, 8);
        topic_tools::ShapeShifter proto = RosBytes::shaped("fdb28210bfa9d7c91146260178d9a584",
                                                           "std_msgs/Float64", "float64 data\n", bytes);
        latencyPubs.push_back(proto.advertise(node, topic, 1000));
    }
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    const auto allSubscribed = [&] {
        for (const Stream& s : streams)
            if (s.pub.getNumSubscribers() == 0)
                return false;
        for (const ros::Publisher& p : latencyPubs)
            if (p.getNumSubscribers() == 0)
                return false;
        return true;
    };
    while (ros::ok() && !allSubscribed() && ros::WallTime::now() < deadline)
        ros::WallDuration(0.05).sleep();
    if (!allSubscribed()) {
        std::fprintf(stderr, "no subscriber within 30 s\n");
        return 1;
    }
    ros::WallDuration(0.3).sleep(); // let every connection finish its handshake
    std::mt19937 rng(seed);
    std::exponential_distribution<double> jitter(jitterUs > 0 ? 1.0 / jitterUs : 1.0);
    ros::WallRate pace(rate);
    for (int s = 0; s < samples && ros::ok(); ++s) {
        StampCodec::Decoded d;
        d.seq = quint32(s);
        d.sampleNs = firstNs + qint64(double(s) * 1e9 / rate);
        d.frameId = QStringLiteral("sample");
        qint64 extraNs = 0;
        for (std::size_t i = 0; i < streams.size(); ++i) {
            if (jitterUs > 0 && i > 0)
                extraNs += qint64(jitter(rng) * 1000.0);
            else if (jitterUs <= 0)
                extraNs = qint64(i) * (s % 7) * 100'000;
            d.timeNs = d.sampleNs + streams[i].offsetNs + extraNs;
            const QByteArray bytes = StampCodec::encodeTimeStamped(d);
            streams[i].pub.publish(
                RosBytes::shaped(md5, type, definition, streams[i].malformed ? bytes.left(10) : bytes));
        }
        for (std::size_t i = 0; i < latencyPubs.size(); ++i) {
            QByteArray bytes(8, Qt::Uninitialized);
            std::memcpy(bytes.data(), &latencies[i].second, 8);
            latencyPubs[i].publish(RosBytes::shaped("fdb28210bfa9d7c91146260178d9a584", "std_msgs/Float64",
                                                    "float64 data\n", bytes));
        }
        pace.sleep();
    }
    ros::WallDuration(0.5).sleep(); // let the last messages leave before the node goes
    std::printf("done\n");
    return 0;
}
