// SPDX-License-Identifier: MIT
// ROS -> MQTT -> ROS through two reference bridges (`bridgescope bridge`, separate processes)
// against the broker-only path of the same payload in the same run (publish to mosquitto and
// receive it back on the same client, as `probe` does), at 0.18 MB (a VelodyneScan) and 1.08 MB.
//
// Latencies are one process's clock: the bench stamps the send time into the message and takes
// the receive time in the subscriber's callback. Messages go at BENCH_RATE Hz (default 10, the
// paper's rate), BENCH_COUNT per size and path (default 200), alternating paths message by message
// so that both see the same machine load.
//
//   build-release/bench/bench_bridge
#include "app/cli/clioutput.h"
#include "base/wallclock.h"
#include "benchutil.h"
#include "mqtt/mqttlink.h"
#include "ros/rosendpoint.h"
#include "testservers.h"

#include <cstring>
#include <mutex>
#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtEndian>
#include <QTest>
#include <QThread>

using namespace Qt::StringLiterals;

namespace {
/// A raw sensor_msgs/PointCloud2-like payload: uint8[] of `size` bytes whose first 8 hold the send time.
/// Sent on ROS as std_msgs/UInt8MultiArray-free "bench/Blob" (uint8[] data), on MQTT as is.
const QString kBlobType = u"bridgescope_bench/Blob"_s;
const QString kBlobDefinition = u"uint8[] data\n"_s;
const QString kBlobMd5 = u"f43a8e1b362b75baa741461b46adc7e0"_s; // md5("uint8[] data")

QByteArray rosBlob(int size, qint64 sentNs)
{
    QByteArray b(4 + size, '\x5a');
    qToLittleEndian(quint32(size), b.data());
    std::memcpy(b.data() + 4, &sentNs, 8);
    return b;
}

struct Collector
{
    std::mutex mutex;
    std::vector<double> ms;
    void add(qint64 sentNs, qint64 receivedNs)
    {
        std::lock_guard<std::mutex> lock(mutex);
        ms.push_back(double(receivedNs - sentNs) / 1e6);
    }
    std::size_t size()
    {
        std::lock_guard<std::mutex> lock(mutex);
        return ms.size();
    }
};
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    CliOutput::keepFreedMemory(); // as the bridges do: both paths end in this process
    const int count = Bench::envInt("BENCH_COUNT", 200);
    const int rate = Bench::envInt("BENCH_RATE", 10);
    TestServers servers;
    if (!servers.startMosquitto() || !servers.startRosMaster()) {
        std::fprintf(stderr, "servers: %s\n", qPrintable(servers.errorString()));
        return 1;
    }
    QTemporaryDir dir;
    const auto write = [&dir](const QString& name, const QByteArray& text) {
        QFile f(dir.filePath(name));
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return f.fileName();
    };
    const QString vehicle = write(u"vehicle.yaml"_s,
                                  "bridge:\n  ros2mqtt:\n    - {ros_topic: /bench/in, mqtt_topic: "
                                  "bench/data, advanced: {ros: {queue_size: 100}}}\n");
    const QString cloud = write(u"cloud.yaml"_s,
                                "bridge:\n  mqtt2ros:\n    - {mqtt_topic: bench/data, ros_topic: /bench/out, "
                                "advanced: {ros: {queue_size: 100}}}\n");
    std::vector<std::unique_ptr<QProcess>> bridges;
    for (const auto& [config, name] : {std::pair {vehicle, u"bench_vehicle"_s}, {cloud, u"bench_cloud"_s}}) {
        auto p = std::make_unique<QProcess>();
        p->setProcessEnvironment(servers.rosEnvironment());
        p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p->start(QStringLiteral(BRIDGESCOPE_BINARY),
                 {u"bridge"_s, config, u"--broker"_s, servers.brokerUrl(), u"--name"_s, name});
        bridges.push_back(std::move(p));
    }

    RosEndpoint ros;
    if (const Status started = ros.start(u"bench_bridge"_s, servers.rosMasterUri(), {}); !started) {
        std::fprintf(stderr, "ros: %s\n", qPrintable(started.error().toString()));
        return 1;
    }
    Collector viaBridges;
    Collector viaBroker;
    Collector viaOneBridge; ///< ROS -> vehicle bridge -> broker -> this client: where the time goes
    static_cast<void>(ros.subscribe( // a failure shows as nothing arriving
        u"/bench/out"_s, 100, [&viaBridges](const RosRawMessage& m, qint64 receivedNs) {
            qint64 sent = 0;
            if (m.bytes.size() >= 12) {
                std::memcpy(&sent, m.bytes.constData() + 4, 8);
                viaBridges.add(sent, receivedNs);
            }
        }));
    const int pub
        = ros.advertise(u"/bench/in"_s, kBlobType, kBlobMd5, kBlobDefinition, 100, false).valueOr(-1);
    MqttLink mqtt(MqttProfile::fromUrl(servers.brokerUrl()));
    mqtt.setMessageHandler([&](const QString& topic, const QByteArray& payload, qint64 receivedNs) {
        qint64 sent = 0;
        const bool peer = topic == u"bench/peer"_s;
        const int at = peer ? 0 : 4; // the bridge's payload is the ROS message: length, then data
        if (payload.size() >= at + 8) {
            std::memcpy(&sent, payload.constData() + at, 8);
            (peer ? viaBroker : viaOneBridge).add(sent, receivedNs);
        }
    });
    mqtt.addSubscription(u"bench/peer"_s, 0);
    mqtt.addSubscription(u"bench/data"_s, 0);
    if (const Status connected = mqtt.connect(5000); !connected) {
        std::fprintf(stderr, "mqtt: %s\n", qPrintable(connected.error().toString()));
        return 1;
    }
    // Warm up: until a message makes it through both bridges (they announce the type first).
    for (int i = 0; i < 200 && viaBridges.size() == 0; ++i) {
        ros.publish(pub, rosBlob(64, wallClockNs()));
        QThread::msleep(50);
    }
    if (viaBridges.size() == 0) {
        std::fprintf(stderr, "nothing came through the bridges\n");
        return 1;
    }

    std::printf(
        "ROS -> MQTT -> ROS through two reference bridges vs the broker alone, %d messages each at %d Hz\n\n",
        count, rate);
    // One message of `size` bytes with its send time, through the bridges or to the broker alone.
    const auto send = [&](bool bridges, int size) {
        if (bridges) {
            ros.publish(pub, rosBlob(size, wallClockNs()));
            return;
        }
        QByteArray payload(size, '\x5a');
        const qint64 now = wallClockNs(); // after making the payload, as the bridged path's time
        std::memcpy(payload.data(), &now, 8);
        mqtt.publish(u"bench/peer"_s, payload, 0, false);
    };
    const auto sleepUntil = [](qint64 wallNs) {
        const qint64 wait = wallNs - wallClockNs();
        if (wait > 0)
            QThread::usleep(quint64(wait / 1000));
    };
    Bench::header("median ms");
    for (const int size : {180'000, 1'080'000}) {
        viaBridges.ms.clear();
        viaBroker.ms.clear();
        viaOneBridge.ms.clear();
        const qint64 period = 1'000'000'000LL / rate;
        qint64 next = wallClockNs();
        for (int i = 0; i < count; ++i) {
            // Alternate the two paths, half a period apart.
            send(true, size);
            QThread::usleep(quint64(period / 2000));
            send(false, size);
            next += period;
            sleepUntil(next);
        }
        QThread::msleep(1000);
        const std::vector<double> b = viaBridges.ms;
        const std::vector<double> p = viaBroker.ms;
        const double mb = size / 1e6;
        const double bMed = Bench::percentile(b, 0.5);
        const double pMed = Bench::percentile(p, 0.5);
        Bench::row(u"%1 MB through two bridges (ROS->MQTT->ROS)"_s.arg(mb), bMed,
                   u"p99 %1 ms, %2 of %3 arrived"_s.arg(Bench::percentile(b, 0.99), 0, 'f', 2)
                       .arg(b.size())
                       .arg(count));
        Bench::row(u"%1 MB broker only (publish, receive back)"_s.arg(mb), pMed,
                   u"p99 %1 ms, %2 of %3 arrived"_s.arg(Bench::percentile(p, 0.99), 0, 'f', 2)
                       .arg(p.size())
                       .arg(count));
        Bench::row(u"%1 MB ROS -> one bridge -> MQTT (part of the above)"_s.arg(mb),
                   Bench::percentile(viaOneBridge.ms, 0.5),
                   u"p99 %1 ms"_s.arg(Bench::percentile(viaOneBridge.ms, 0.99), 0, 'f', 2));
        // The literal peer of the issue: `bridgescope probe` in its own process, same size and rate.
        QProcess probe;
        probe.start(QStringLiteral(BRIDGESCOPE_BINARY),
                    {u"probe"_s, u"--broker"_s, servers.brokerUrl(), u"--size"_s, QString::number(size),
                     u"--rate"_s, QString::number(rate), u"--count"_s, QString::number(std::min(count, 100)),
                     u"--json"_s});
        probe.waitForFinished(120000);
        const double probeMed = QJsonDocument::fromJson(probe.readAllStandardOutput())
                                    .object()
                                    .value(u"rtt"_s)
                                    .toObject()
                                    .value(u"median_ms"_s)
                                    .toDouble();
        Bench::row(u"%1 MB bridgescope probe round trip (own process)"_s.arg(mb), probeMed,
                   u"ratio bridges / probe %1"_s.arg(probeMed > 0 ? bMed / probeMed : 0, 0, 'f', 2));
        Bench::row(u"%1 MB ratio bridges / broker only (median)"_s.arg(mb), pMed > 0 ? bMed / pMed : 0,
                   u"bridges add %1 ms"_s.arg(bMed - pMed, 0, 'f', 2));
        if (size == 180'000)
            Bench::gate("bridge_018mb_vs_broker_only", pMed > 0 ? bMed / pMed : 0);
    }
    // BENCH_SWEEP=0: the gate's short run, the latencies only
    if (Bench::envInt("BENCH_SWEEP", 1, 0) != 0) {
        // Throughput at 0.18 MB: raise the rate by 1.5x per one-second step, on each path alone, until
        // more than 1 % is lost or the median exceeds 10x the first step's (at least 10 ms).
        std::printf("\nHighest sustainable rate at 0.18 MB (1 s steps, x1.5 from 50 Hz, <= 1 %% lost, median <= "
                    "10x)\n\n");
        Bench::header("MB/s");
        const int size = 180'000;
        const auto sweep = [&](bool bridges) {
            Collector& c = bridges ? viaBridges : viaBroker;
            double best = 0;
            double first = 0;
            for (double hz = 50; hz <= 5000; hz *= 1.5) {
                {
                    std::lock_guard<std::mutex> lock(c.mutex);
                    c.ms.clear();
                }
                const int n = int(hz);
                const qint64 period = qint64(1e9 / hz);
                qint64 next = wallClockNs();
                for (int i = 0; i < n; ++i) {
                    send(bridges, size);
                    next += period;
                    sleepUntil(next);
                }
                QThread::msleep(500);
                std::vector<double> got;
                {
                    std::lock_guard<std::mutex> lock(c.mutex);
                    got = c.ms;
                }
                const double median = Bench::percentile(got, 0.5);
                if (first == 0)
                    first = std::max(median, 1.0);
                const bool ok = double(got.size()) >= 0.99 * n && median <= std::max(10 * first, 10.0);
                if (!ok)
                    break;
                best = hz;
            }
            return best;
        };
        const double bridgeHz = sweep(true);
        QThread::msleep(1000);
        const double brokerHz = sweep(false);
        Bench::row(u"0.18 MB through two bridges (ROS->MQTT->ROS)"_s, bridgeHz * size / 1e6,
                   u"%1 Hz"_s.arg(bridgeHz, 0, 'f', 0));
        Bench::row(u"0.18 MB broker only (publish, receive back)"_s, brokerHz * size / 1e6,
                   u"%1 Hz"_s.arg(brokerHz, 0, 'f', 0));
        Bench::row(u"ratio bridges / broker only"_s, brokerHz > 0 ? bridgeHz / brokerHz : 0);
    }

    mqtt.disconnect();
    ros.shutdown();
    for (auto& p : bridges) {
        p->terminate();
        p->waitForFinished(5000);
    }
    return 0;
}
