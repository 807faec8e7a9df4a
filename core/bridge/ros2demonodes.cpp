// SPDX-License-Identifier: MIT
#include "ros2demonodes.h"

#include "base/wallclock.h"
#include "ros2/ros2participant.h"
#include "wire/ros2bridgewire.h"
#include "wire/ros2definitions.h"
#include "wire/rosmessageencoder.h"

#include <initializer_list>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QtEndian>
#include <QThread>
#include <QTimer>
#include <QVariantList>
#include <QVariantMap>
#include <random>

using namespace Qt::StringLiterals;

namespace {
const QString kStamps = DemoNodes::stampPrefix();
const QString kFrame = u"velodyne"_s; ///< of every scan, kept in the object list's header
const QString kPointCloud = u"sensor_msgs/msg/PointCloud2"_s;
const QString kPoseArray = u"geometry_msgs/msg/PoseArray"_s;

/// The bundled ROS 2 definitions (sensor_msgs, geometry_msgs).
const RosTypeRegistry& registry()
{
    static const RosTypeRegistry r = Ros2Definitions::registry();
    return r;
}

QVariantMap headerOf(qint64 stampNs)
{
    return {{u"stamp"_s,
             QVariantMap {{u"sec"_s, qint64(stampNs / 1'000'000'000LL)}, {u"nanosec"_s, qint64(stampNs % 1'000'000'000LL)}}},
            {u"frame_id"_s, kFrame}};
}

/// Publishes the stamps of one component on this host's (offset) clock.
struct Stamper
{
    Ros2Participant& dds;
    QString topic;
    qint64 offsetNs = 0;

    /// A stamp of the scan stamped `sampleNs` at `wallNs` (this host's clock, before its offset).
    void stamp(qint64 sampleNs, qint64 wallNs)
    {
        StampCodec::Decoded d;
        d.sampleNs = sampleNs;
        d.frameId = kFrame;
        d.timeNs = wallNs + offsetNs;
        dds.node().publish(topic, Ros2BridgeWire::encodeTimeStamped(d));
    }
};

/// Starts the participant as node `name` with the stamps' writers and waits (at most 15 s) until
/// it is on the domain.
Status setUp(Ros2Participant& dds, const Ros2DemoNodes::Options& o, const QString& name,
             std::initializer_list<const Stamper*> stampers)
{
    if (Status joined = dds.start(o.dds); !joined)
        return joined;
    dds.node().setNode(u"/"_s, name);
    for (const Stamper* s : stampers)
        dds.node().advertise(s->topic, QLatin1String(Ros2BridgeWire::kTimeStampedType));
    QEventLoop wait;
    bool ok = false;
    QObject::connect(&dds, &Ros2Participant::joined, &wait, [&](bool joined) {
        ok = joined;
        wait.quit();
    });
    QTimer::singleShot(15000, &wait, &QEventLoop::quit);
    wait.exec();
    if (!ok)
        return LocatedError {dds.lastError().isEmpty()
                                 ? Ros2DemoNodes::tr("the DDS process did not join the domain")
                                 : dds.lastError()};
    return {};
}

/// Runs the event loop until `stop` says so (asked every 50 ms).
void runUntil(const std::function<bool()>& stop)
{
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (stop())
            loop.quit();
    });
    poll.start(50);
    loop.exec();
}

/// Whether `topic` has a subscriber of another participant in the graph.
bool hasSubscriber(const Ros2Participant& dds, const QString& topic)
{
    const Ros2Topic* t = dds.graph().topic(topic);
    return t && !t->subscribers.isEmpty();
}

/// A VelodyneScan-sized PointCloud2 as CDR: 16-byte points (x, y, z, intensity), one row.
QByteArray pointCloud(int payloadBytes)
{
    const int width = std::max(1, payloadBytes / 16);
    QVariantList fields;
    for (const auto& [name, offset] : {std::pair {"x", 0}, {"y", 4}, {"z", 8}, {"intensity", 12}})
        fields << QVariantMap {{u"name"_s, QString::fromLatin1(name)},
                               {u"offset"_s, offset},
                               {u"datatype"_s, 7}, // FLOAT32
                               {u"count"_s, 1}};
    QByteArray data(qsizetype(width) * 16, Qt::Uninitialized);
    std::mt19937 rng(7);
    for (char& b : data)
        b = char(rng());
    const QVariantMap scan {{u"header"_s, QVariantMap {{u"frame_id"_s, u"velodyne"_s}}},
                            {u"height"_s, 1},
                            {u"width"_s, width},
                            {u"fields"_s, fields},
                            {u"point_step"_s, 16},
                            {u"row_step"_s, width * 16},
                            {u"data"_s, data},
                            {u"is_dense"_s, true}};
    return RosMessageEncoder::encodeCdr(registry(), kPointCloud, scan).valueOr(QByteArray());
}
} // namespace

Status Ros2DemoNodes::runVehicle(const Options& o, const std::function<bool()>& stop)
{
    Ros2Participant dds;
    Stamper sent {dds, kStamps + u"pointcloud"_s, o.clockOffsetNs};
    Stamper back {dds, kStamps + u"object_list"_s, o.clockOffsetNs};
    if (Status joined = setUp(dds, o, u"demo_vehicle"_s, {&sent, &back}); !joined)
        return joined;
    dds.node().advertise(u"/vehicle/pointcloud"_s, kPointCloud);
    dds.node().subscribe(u"/vehicle/object_list"_s, kPoseArray);
    QObject::connect(&dds.node(), &Ros2EndpointLink::received, &dds, [&back](const QString& topic, const Ros2Sample& s) {
        if (topic != u"/vehicle/object_list"_s)
            return;
        if (const std::optional<qint64> stamp = Ros2BridgeWire::headerStampNs(s.bytes))
            back.stamp(*stamp, s.receivedNs);
    });
    QByteArray scan = pointCloud(o.payloadBytes);
    if (scan.size() < 16)
        return LocatedError {tr("cannot encode the point cloud")};

    // Start when the bridge and a measuring Bridgescope listen (at most 15 s): samples sent
    // before would count as dropped, though nothing was lost.
    QElapsedTimer waited;
    waited.start();
    runUntil([&] {
        return stop() || waited.elapsed() > 15000
            || (hasSubscriber(dds, u"/vehicle/pointcloud"_s) && hasSubscriber(dds, sent.topic));
    });
    QElapsedTimer settle; // the other components' stamp subscriptions settle
    settle.start();
    runUntil([&] { return stop() || settle.elapsed() > 500; });

    // As on ROS 1: each scan at its time on a fixed schedule (a late one goes at once), so that the
    // mean rate is the one asked for whatever the timer's granularity.
    const double periodNs = 1e9 / std::max(0.1, o.rateHz);
    QElapsedTimer clock;
    clock.start();
    qint64 scans = 0;
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    tick.setSingleShot(true);
    QObject::connect(&tick, &QTimer::timeout, &dds, [&] {
        // the scan's header.stamp, right after the encapsulation header: the bytes once encoded stay
        const qint64 now = wallClockNs() + o.clockOffsetNs;
        auto* p = reinterpret_cast<uchar*>(scan.data());
        qToLittleEndian<qint32>(qint32(now / 1'000'000'000LL), p + 4);
        qToLittleEndian<quint32>(quint32(now % 1'000'000'000LL), p + 8);
        sent.stamp(now, wallClockNs());
        dds.node().publish(u"/vehicle/pointcloud"_s, scan);
        const qint64 waitNs = qint64(double(++scans) * periodNs) - clock.nsecsElapsed();
        tick.start(int(std::max<qint64>(0, waitNs / 1'000'000)));
    });
    tick.start(0);
    runUntil(stop);
    dds.stop();
    return {};
}

Status Ros2DemoNodes::runCloud(const Options& o, const std::function<bool()>& stop)
{
    Ros2Participant dds;
    Stamper in {dds, kStamps + u"object_detection/pointcloud"_s, o.clockOffsetNs};
    Stamper out {dds, kStamps + u"object_detection/object_list"_s, o.clockOffsetNs};
    if (Status joined = setUp(dds, o, u"demo_object_detection"_s, {&in, &out}); !joined)
        return joined;
    dds.node().advertise(u"/cloud/object_list"_s, kPoseArray);
    dds.node().subscribe(u"/cloud/pointcloud"_s, kPointCloud);
    std::mt19937 rng(11);
    QObject::connect(&dds.node(), &Ros2EndpointLink::received, &dds, [&](const QString& topic, const Ros2Sample& s) {
        if (topic != u"/cloud/pointcloud"_s)
            return;
        const std::optional<qint64> stamp = Ros2BridgeWire::headerStampNs(s.bytes);
        if (!stamp)
            return;
        in.stamp(*stamp, s.receivedNs);
        // "Inference": about the mean, varying like a real network's run time.
        std::gamma_distribution<double> work(16.0, o.detectionMs / 16.0);
        QThread::usleep(quint64(work(rng) * 1000));
        std::uniform_int_distribution<int> count(3, 12);
        QVariantList poses;
        for (int i = count(rng); i > 0; --i)
            poses << QVariantMap {{u"position"_s, QVariantMap {{u"x"_s, double(poses.size()) * 2.5}}},
                                  {u"orientation"_s, QVariantMap {{u"w"_s, 1.0}}}};
        const QVariantMap objects {{u"header"_s, headerOf(*stamp)}, {u"poses"_s, poses}};
        out.stamp(*stamp, wallClockNs());
        dds.node().publish(u"/cloud/object_list"_s,
                    RosMessageEncoder::encodeCdr(registry(), kPoseArray, objects).valueOr(QByteArray()));
    });
    runUntil(stop);
    dds.stop();
    return {};
}
