// SPDX-License-Identifier: MIT
// A ping through two ROS 2 reference bridges (`bridgescope bridge --ros 2`: DDS -> MQTT -> DDS),
// against two ROS 1 reference bridges (ROS -> MQTT -> ROS) and the broker alone, in one run and
// interleaved message by message, at 0.18 MB (and 1.08 MB with BENCH_LARGE=1).
//
// Latencies are this process's wall clock: the send time is written into the message before it is
// handed to the library; it is taken on arrival (ROS 1: roscpp's callback; ROS 2: when the DDS
// process of this bench's Ros2Participant took the sample; MQTT: Paho's callback). The ROS 2
// path's own ends go through a participant in a child process, so its sends pass one more pipe
// than an rclcpp node's would. BENCH_COUNT messages per path (default 100), at BENCH_RATE Hz
// (default 10).
//
//   build/bench/bench_ros2bridge
#include "app/cli/clioutput.h"
#include "base/wallclock.h"
#include "benchutil.h"
#include "mqtt/mqttlink.h"
#include "ros/rosendpoint.h"
#include "ros2/ros2participant.h"
#include "ros2peer.h"
#include "testservers.h"

#include <cstring>
#include <mutex>
#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTimer>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
const QString kBlobType = u"bridgescope_bench/Blob"_s;
const QString kBlob2Type = u"bridgescope_bench/msg/Blob"_s;
const QString kBlobDefinition = u"uint8[] data\n"_s;
const QString kBlobMd5 = u"f43a8e1b362b75baa741461b46adc7e0"_s; // md5("uint8[] data")

/// uint8[] of `size` bytes whose first 8 hold the send time: ROS 1 serialized, or CDR for ROS 2.
QByteArray blob(int size, qint64 sentNs, bool cdr)
{
    const int head = cdr ? 8 : 4;
    QByteArray b(head + size, '\x5a');
    if (cdr)
        std::memcpy(b.data(), "\x00\x01\x00\x00", 4);
    qToLittleEndian(quint32(size), b.data() + head - 4);
    std::memcpy(b.data() + head, &sentNs, 8);
    return b;
}

struct Collector
{
    std::mutex mutex;
    std::vector<double> ms;
    void add(const QByteArray& bytes, int at, qint64 receivedNs)
    {
        qint64 sent = 0;
        if (bytes.size() < at + 8)
            return;
        std::memcpy(&sent, bytes.constData() + at, 8);
        std::lock_guard<std::mutex> lock(mutex);
        ms.push_back(double(receivedNs - sent) / 1e6);
    }
    std::vector<double> take()
    {
        std::lock_guard<std::mutex> lock(mutex);
        return std::exchange(ms, {});
    }
};

/// Runs the event loop until the wall clock reaches `wallNs` (the participant works on it).
void runUntil(qint64 wallNs)
{
    const qint64 ms = (wallNs - wallClockNs()) / 1'000'000;
    if (ms <= 0)
        return;
    QEventLoop loop;
    QTimer::singleShot(int(ms), Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
}

std::unique_ptr<QProcess> startBridge(const QStringList& args,
                                      const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment())
{
    auto p = std::make_unique<QProcess>();
    p->setProcessEnvironment(env);
    p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    p->start(QStringLiteral(BRIDGESCOPE_BINARY), QStringList {u"bridge"_s} + args);
    return p;
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    CliOutput::keepFreedMemory();
    const int count = Bench::envInt("BENCH_COUNT", 100);
    const int rate = Bench::envInt("BENCH_RATE", 10);
    TestServers servers;
    if (!servers.startMosquitto() || !servers.startRosMaster()) {
        std::fprintf(stderr, "servers: %s\n", qPrintable(servers.errorString()));
        return 1;
    }
    const int domain = Ros2Peer::freeDomain(200, 230);
    QTemporaryDir dir;
    const auto write = [&dir](const QString& name, const QByteArray& text) {
        QFile f(dir.filePath(name));
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return f.fileName();
    };
    const QString broker = servers.brokerUrl();
    const QStringList ros2 {u"--ros"_s, u"2"_s, u"--ros-domain"_s, QString::number(domain), u"--ros-localhost-only"_s,
                            u"--broker"_s, broker};
    std::vector<std::unique_ptr<QProcess>> bridges;
    QProcessEnvironment rosEnv = servers.rosEnvironment();
    for (const auto& [config, name] :
         {std::pair {write(u"v1.yaml"_s, "bridge:\n  ros2mqtt:\n    - {ros_topic: /bench/in, mqtt_topic: bench/data1, "
                                         "advanced: {ros: {queue_size: 100}}}\n"),
                     u"bench_vehicle"_s},
          {write(u"c1.yaml"_s, "bridge:\n  mqtt2ros:\n    - {mqtt_topic: bench/data1, ros_topic: /bench/out, "
                               "advanced: {ros: {queue_size: 100}}}\n"),
           u"bench_cloud"_s}}) {
        bridges.push_back(startBridge({config, u"--broker"_s, broker, u"--name"_s, name}, rosEnv));
    }
    bridges.push_back(startBridge(
        QStringList {write(u"v2.yaml"_s, "/**:\n  ros__parameters:\n    bridge:\n      ros2mqtt:\n        ros_topics: "
                                         "[/bench2/in]\n        /bench2/in: {mqtt_topic: bench/data2, advanced: {ros: "
                                         "{queue_size: 100}}}\n"),
                     u"--name"_s, u"bench_vehicle2"_s}
        + ros2));
    bridges.push_back(startBridge(
        QStringList {write(u"c2.yaml"_s, "/**:\n  ros__parameters:\n    bridge:\n      mqtt2ros:\n        mqtt_topics: "
                                         "[bench/data2]\n        bench/data2: {ros_topic: /bench2/out, advanced: {ros: "
                                         "{queue_size: 100}}}\n"),
                     u"--name"_s, u"bench_cloud2"_s}
        + ros2));

    Collector viaRos1, viaRos2, viaBroker;
    RosEndpoint ros;
    if (const Status started = ros.start(u"bench_ros2bridge"_s, servers.rosMasterUri(), {}); !started) {
        std::fprintf(stderr, "ros: %s\n", qPrintable(started.error().toString()));
        return 1;
    }
    static_cast<void>(ros.subscribe( // a failure shows as nothing arriving
        u"/bench/out"_s, 100, [&viaRos1](const RosRawMessage& m, qint64 t) { viaRos1.add(m.bytes, 4, t); }));
    const int pub
        = ros.advertise(u"/bench/in"_s, kBlobType, kBlobMd5, kBlobDefinition, 100, false).valueOr(-1);
    Ros2Participant dds;
    QObject::connect(&dds.node(), &Ros2EndpointLink::received,
                     [&viaRos2](const QString&, const Ros2Sample& s) { viaRos2.add(s.bytes, 8, s.receivedNs); });
    Ros2Qos qos;
    qos.depth = 100;
    dds.node().setNode(u"/"_s, u"bench_ros2bridge"_s);
    dds.node().advertise(u"/bench2/in"_s, kBlob2Type, qos);
    dds.node().subscribe(u"/bench2/out"_s, kBlob2Type, qos);
    if (const Status joined = dds.start({domain, true}); !joined) {
        std::fprintf(stderr, "dds: %s\n", qPrintable(joined.error().toString()));
        return 1;
    }
    MqttLink mqtt(MqttProfile::fromUrl(broker));
    mqtt.setMessageHandler([&viaBroker](const QString&, const QByteArray& p, qint64 t) { viaBroker.add(p, 0, t); });
    mqtt.addSubscription(u"bench/peer"_s, 0);
    if (const Status connected = mqtt.connect(5000); !connected) {
        std::fprintf(stderr, "mqtt: %s\n", qPrintable(connected.error().toString()));
        return 1;
    }
    const auto send = [&](int path, int size) {
        if (path == 1) {
            ros.publish(pub, blob(size, wallClockNs(), false));
        } else if (path == 2) {
            dds.node().publish(u"/bench2/in"_s, blob(size, wallClockNs(), true));
        } else {
            QByteArray payload(size, '\x5a');
            const qint64 now = wallClockNs();
            std::memcpy(payload.data(), &now, 8);
            mqtt.publish(u"bench/peer"_s, payload, 0, false);
        }
    };
    // Warm up: until a message makes it through each pair of bridges.
    for (int i = 0; i < 300 && (viaRos1.ms.empty() || viaRos2.ms.empty()); ++i) {
        send(1, 64);
        send(2, 64);
        runUntil(wallClockNs() + 50'000'000);
    }
    if (viaRos1.take().empty() || viaRos2.take().empty()) {
        std::fprintf(stderr, "nothing came through the bridges\n");
        return 1;
    }
    std::printf("A ping through two ROS 2 reference bridges, two ROS 1 ones and the broker alone, %d messages "
                "each at %d Hz, interleaved\n\n",
                count, rate);
    Bench::header("median ms");
    std::vector<int> sizes {180'000};
    if (Bench::envInt("BENCH_LARGE", 0, 0))
        sizes.push_back(1'080'000);
    for (const int size : sizes) {
        const qint64 period = 1'000'000'000LL / rate;
        qint64 next = wallClockNs();
        for (int i = 0; i < count; ++i) {
            for (int path : {2, 1, 3}) { // a third of a period apart
                send(path, size);
                runUntil(next + (path == 2 ? period / 3 : path == 1 ? 2 * period / 3 : period));
            }
            next += period;
        }
        runUntil(wallClockNs() + 1'000'000'000);
        const std::vector<double> r2 = viaRos2.take(), r1 = viaRos1.take(), b = viaBroker.take();
        const double mb = size / 1e6;
        const double m2 = Bench::percentile(r2, 0.5), m1 = Bench::percentile(r1, 0.5), mb0 = Bench::percentile(b, 0.5);
        const auto note = [count](const std::vector<double>& v) {
            return u"p99 %1 ms, %2 of %3 arrived"_s.arg(Bench::percentile(v, 0.99), 0, 'f', 2).arg(v.size()).arg(count);
        };
        Bench::row(u"%1 MB through two ROS 2 bridges (DDS->MQTT->DDS)"_s.arg(mb), m2, note(r2));
        Bench::row(u"%1 MB through two ROS 1 bridges (ROS->MQTT->ROS)"_s.arg(mb), m1, note(r1));
        Bench::row(u"%1 MB broker only (publish, receive back)"_s.arg(mb), mb0, note(b));
        Bench::row(u"%1 MB ratio ROS 2 bridges / ROS 1 bridges"_s.arg(mb), m1 > 0 ? m2 / m1 : 0,
                   u"ROS 2 adds %1 ms"_s.arg(m2 - m1, 0, 'f', 2));
        Bench::row(u"%1 MB ratio ROS 2 bridges / broker only"_s.arg(mb), mb0 > 0 ? m2 / mb0 : 0,
                   u"the bridges add %1 ms"_s.arg(m2 - mb0, 0, 'f', 2));
        // for scripts/bench.sh --gate, should bench/gate.txt name them
        Bench::gate(size == sizes.front() ? "ros2bridge_018mb_vs_ros1_bridges" : "ros2bridge_108mb_vs_ros1_bridges",
                    m1 > 0 ? m2 / m1 : 0);
    }
    mqtt.disconnect();
    ros.shutdown();
    for (auto& p : bridges) {
        p->terminate();
        p->waitForFinished(5000);
    }
    return 0;
}
