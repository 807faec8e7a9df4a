// SPDX-License-Identifier: MIT
// ROS 2 on the wire (issue 16), against Fast DDS used directly as its own examples use it, in the
// same run, on loopback, with Cyclone DDS nodes (tests/ros2peer, as rmw_cyclonedds_cpp puts them on
// the wire) as the graph and the publisher:
//
// 1. Discovery of 1,000 topics: four nodes of 250 publishers of std_msgs/msg/String each
//    (/bench/t0000../bench/t0999, never publishing). In turn, each in a fresh process: Bridgescope's
//    Ros2Participant (graph rebuilt every 250 ms as shipped, and every 20 ms) until its graph holds
//    every topic with its node; and bench_ros2_fastdds, a DomainParticipantListener counting
//    on_publisher_discovery and reading ros_discovery_info, until it knows every writer and every
//    writer's node. Both join the domain the same way (UDPv4 on 127.0.0.1, unicast peers).
// 2. Ingest of sensor_msgs/msg/PointCloud2 of 184,320 bytes at 100 Hz, reliable, 2,000 samples from
//    a fresh Cyclone publisher for each subscriber, one subscriber at a time: Bridgescope's monitor()
//    with the snapshot read every 33 ms, and Fast DDS's example subscriber (generated type, listener,
//    take) reliable as the example and best effort as Bridgescope's monitor; and, to show what the
//    system's default UDP receive buffer costs, the best-effort one with a 4 MiB buffer. Messages
//    received against those sent after the subscriber matched, the rate, CPU seconds per 1,000
//    messages, and the datagrams the kernel dropped for a full receive buffer meanwhile.
//
//   scripts/bench.sh bench_ros2        (BENCH_TOPICS, BENCH_RUNS, BENCH_SECONDS, BENCH_INGEST_RUNS)
#include "benchutil.h"
#include "ros2peer.h"

#include <algorithm>
#include <memory>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QProcess>
#include <QTest>
#include <vector>

using namespace Qt::StringLiterals;

namespace {

/// A helper program of this benchmark; killed when it goes out of scope.
class Helper
{
public:
    Helper(const QString& program, const QStringList& args, const QStringList& environment = {})
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(u"BENCH_FASTDDS_RCVBUF"_s); // only where a side asks for it
        for (const QString& e : environment)
            env.insert(e.section(u'=', 0, 0), e.section(u'=', 1));
        m_process.setProcessEnvironment(env);
        m_process.setProcessChannelMode(QProcess::SeparateChannels);
        m_process.setReadChannel(QProcess::StandardOutput);
        m_process.start(QCoreApplication::applicationDirPath() + u'/' + program, args);
    }
    ~Helper()
    {
        if (m_process.state() != QProcess::NotRunning) {
            m_process.kill();
            m_process.waitForFinished(5000);
        }
    }
    Helper(const Helper&) = delete;
    Helper& operator=(const Helper&) = delete;

    /// The first line starting with `prefix` (earlier lines are dropped), or an empty string when
    /// none came within `timeoutMs` or the program ended.
    QString waitFor(const QString& prefix, int timeoutMs)
    {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < timeoutMs) {
            while (m_process.canReadLine()) {
                const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
                if (line.startsWith(prefix))
                    return line;
            }
            if (m_process.state() == QProcess::NotRunning)
                break;
            m_process.waitForReadyRead(50);
        }
        std::fprintf(stderr, "bench_ros2: no '%s' from %s within %d ms: %s\n", qPrintable(prefix),
                     qPrintable(m_process.program()), timeoutMs,
                     m_process.readAllStandardError().constData());
        return {};
    }
    void send(const QByteArray& line)
    {
        m_process.write(line);
        m_process.waitForBytesWritten(1000);
    }

private:
    QProcess m_process;
};

/// "key=value" words of a result line.
QHash<QString, double> fieldsOf(const QString& line)
{
    QHash<QString, double> f;
    for (const QString& word : line.split(u' ', Qt::SkipEmptyParts)) {
        const qsizetype eq = word.indexOf(u'=');
        if (eq > 0)
            f.insert(word.left(eq), word.mid(eq + 1).toDouble());
    }
    return f;
}

/// Datagrams the kernel dropped because a UDP socket's receive buffer was full (all sockets of this
/// host: /proc/net/snmp, Udp RcvbufErrors), or -1.
double udpReceiveBufferErrors()
{
    QFile f(u"/proc/net/snmp"_s);
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QList<QByteArray> lines = f.readAll().split('\n');
    for (qsizetype i = 0; i + 1 < lines.size(); ++i)
        if (lines[i].startsWith("Udp:") && lines[i + 1].startsWith("Udp:")) {
            const QList<QByteArray> names = lines[i].simplified().split(' ');
            const QList<QByteArray> values = lines[i + 1].simplified().split(' ');
            const qsizetype k = names.indexOf("RcvbufErrors");
            return k > 0 && k < values.size() ? values[k].toDouble() : -1;
        }
    return -1;
}

/// How many of `v` are below `limit`.
int below(const std::vector<double>& v, double limit)
{
    return int(std::count_if(v.begin(), v.end(), [&](double x) { return x < limit; }));
}

QString range(const std::vector<double>& v, int decimals = 0)
{
    if (v.empty())
        return u"no run completed"_s;
    return u"median of %1, min %2, max %3"_s.arg(v.size())
        .arg(*std::min_element(v.begin(), v.end()), 0, 'f', decimals)
        .arg(*std::max_element(v.begin(), v.end()), 0, 'f', decimals);
}

double median(const std::vector<double>& v)
{
    return Bench::percentile(v, 0.5);
}

struct DiscoveryRuns
{
    std::vector<double> allMs, namedMs, namedCpu, hwmMiB, growthMiB;
};

struct DiscoverySide
{
    QString title;
    QString program;
    QStringList args;
    QString allKey; ///< the result's time to every topic (writer)
    DiscoveryRuns r;
};

bool runDiscovery(int domain, int topics, int runs)
{
    // the graph: four nodes (or BENCH_NODES) of publishers that never publish
    const int nodes = std::min(Bench::envInt("BENCH_NODES", 4), topics);
    std::vector<std::unique_ptr<Ros2Peer>> graph;
    for (int k = 0, first = 0; k < nodes; ++k) {
        const int n = topics / nodes + (k < topics % nodes ? 1 : 0);
        graph.push_back(std::make_unique<Ros2Peer>(
            domain,
            QStringList {u"--node"_s, u"/bench/node_%1"_s.arg(k), u"--many"_s,
                         u"%1@%2:/bench/t:std_msgs/msg/String:0"_s.arg(n).arg(first), u"--duration"_s,
                         u"600"_s}));
        first += n;
    }
    for (auto& peer : graph)
        if (!peer->waitFor(u"ready"_s, 30000)) {
            std::fprintf(stderr, "bench_ros2: a graph peer did not start: %s\n", qPrintable(peer->errors()));
            return false;
        }
    QTest::qWait(1000); // the peers have found each other

    const QString count = QString::number(topics);
    const QString timeout = u"60"_s;
    std::vector<DiscoverySide> sides {
        {u"peer: Fast DDS listener"_s,
         u"bench_ros2_fastdds"_s,
         {u"discover"_s, QString::number(domain), count, u"rt/bench/t"_s, timeout},
         u"writers_ms"_s,
         {}},
        {u"Bridgescope, graph 250 ms (shipped)"_s,
         u"bench_ros2_bridgescope"_s,
         {u"discover"_s, QString::number(domain), count, u"/bench/t"_s, u"250"_s, timeout},
         u"topics_ms"_s,
         {}},
        {u"Bridgescope, graph 20 ms"_s,
         u"bench_ros2_bridgescope"_s,
         {u"discover"_s, QString::number(domain), count, u"/bench/t"_s, u"20"_s, timeout},
         u"topics_ms"_s,
         {}},
    };
    for (int run = 0; run < runs; ++run) {
        for (size_t i = 0; i < sides.size(); ++i) {
            // each side in turn goes first
            DiscoverySide& side = sides[(i + size_t(run)) % sides.size()];
            Helper helper(side.program, side.args);
            const QString line = helper.waitFor(u"discovered"_s, 70000);
            if (line.isEmpty())
                return false;
            const auto f = fieldsOf(line);
            side.r.allMs.push_back(f.value(side.allKey));
            side.r.namedMs.push_back(f.value(u"named_ms"_s));
            side.r.namedCpu.push_back(f.value(u"named_cpu_s"_s));
            side.r.hwmMiB.push_back(f.value(u"hwm_kb"_s) / 1024);
            side.r.growthMiB.push_back((f.value(u"rss_kb"_s) - f.value(u"rss0_kb"_s)) / 1024);
            std::fprintf(stderr, "  run %d %-50s %s\n", run + 1, qPrintable(side.title), qPrintable(line));
            QTest::qWait(500); // the peers drop the participant that left
        }
    }

    std::printf(
        "\nDiscovery: %d topics in %d nodes (Cyclone DDS peers), %d runs of each side, each in a fresh "
        "process\n\n",
        topics, nodes, runs);
    Bench::header("median ms");
    const double peerNamed = median(sides[0].r.namedMs);
    const double peerAll = median(sides[0].r.allMs);
    for (const DiscoverySide& side : sides) {
        const bool peer = &side == &sides[0];
        Bench::row(
            side.title + (peer ? u": every writer"_s : u": every topic"_s), median(side.r.allMs),
            range(side.r.allMs)
                + (peer ? QString() : u"; %1x the peer"_s.arg(median(side.r.allMs) / peerAll, 0, 'f', 2)));
        // the wire makes some runs about a second slower than others, whoever listens (docs/BENCHMARKS.md)
        Bench::row(side.title + u": with node names"_s, median(side.r.namedMs),
                   range(side.r.namedMs) + u"; %1 under 500 ms"_s.arg(below(side.r.namedMs, 500))
                       + (peer ? QString()
                               : u"; %1x the peer"_s.arg(median(side.r.namedMs) / peerNamed, 0, 'f', 2)));
    }
    std::printf("\n");
    Bench::header("median");
    const double peerCpu = median(sides[0].r.namedCpu);
    for (const DiscoverySide& side : sides) {
        std::vector<double> cpuMs;
        for (double c : side.r.namedCpu)
            cpuMs.push_back(1000 * c);
        Bench::row(side.title + u": CPU to named graph (ms)"_s, median(cpuMs),
                   range(cpuMs)
                       + (&side == &sides[0]
                              ? QString()
                              : u"; %1x the peer"_s.arg(median(side.r.namedCpu) / peerCpu, 0, 'f', 2)));
        Bench::row(side.title + u": peak RSS (MiB)"_s, median(side.r.hwmMiB),
                   u"grew by %1 MiB while discovering"_s.arg(median(side.r.growthMiB), 0, 'f', 1));
    }
    return true;
}

struct IngestRuns
{
    std::vector<double> expected, received, rateHz, cpuPerK, cpuPerKOffered, publisherRateHz,
        publisherCpuPerK, hwmMiB, bufferDrops;
};

struct IngestSide
{
    QString title;
    QString program;
    QStringList extraArgs;
    QStringList environment;
    IngestRuns r;
};

bool runIngest(int domain, int seconds, int runs)
{
    constexpr int kRate = 100;
    constexpr int kSize = 184320;
    const int count = kRate * seconds;
    const QString topic = u"/bench/cloud"_s;
    std::vector<IngestSide> sides {
        {u"Bridgescope monitor() (best effort)"_s, u"bench_ros2_bridgescope"_s, {}, {}, {}},
        {u"peer: Fast DDS example sub, reliable"_s, u"bench_ros2_fastdds"_s, {}, {}, {}},
        {u"peer: Fast DDS example sub, best effort"_s, u"bench_ros2_fastdds"_s, {u"best_effort"_s}, {}, {}},
        // not a peer: what a larger UDP receive buffer than the system's default would change
        {u"best-effort sub, 4 MiB UDP receive buffer"_s,
         u"bench_ros2_fastdds"_s,
         {u"best_effort"_s},
         {u"BENCH_FASTDDS_RCVBUF=4194304"_s},
         {}},
    };
    for (int run = 0; run < runs; ++run) {
        for (size_t i = 0; i < sides.size(); ++i) {
            IngestSide& side = sides[(i + size_t(run)) % sides.size()];
            const double drops0 = udpReceiveBufferErrors();
            Helper sub(side.program,
                       QStringList {u"subscribe"_s, QString::number(domain), topic, QString::number(kSize),
                                    QString::number(seconds + 60)}
                           + side.extraArgs,
                       side.environment);
            Ros2Peer publisher(domain,
                               {u"--node"_s, u"/bench/lidar"_s, u"--size"_s, QString::number(kSize),
                                u"--pub"_s, u"%1:sensor_msgs/msg/PointCloud2:%2"_s.arg(topic).arg(kRate),
                                u"--count"_s, QString::number(count), u"--duration"_s,
                                QString::number(seconds + 40)});
            if (sub.waitFor(u"matched"_s, 20000).isEmpty()
                || !publisher.waitFor(u"matched %1 1"_s.arg(topic), 20000)) {
                std::fprintf(stderr, "bench_ros2: the subscriber did not match: %s\n",
                             qPrintable(publisher.errors()));
                return false;
            }
            QElapsedTimer sending;
            sending.start();
            if (!publisher.waitFor(u"sent %1 %2"_s.arg(topic).arg(count), (seconds + 30) * 1000)) {
                std::fprintf(stderr, "bench_ros2: the publisher did not finish: %s\n",
                             qPrintable(publisher.errors()));
                return false;
            }
            const double sendingS = double(sending.elapsed()) / 1000;
            const double publisherCpu = Bench::processCpuSeconds(publisher.pid());
            QTest::qWait(1000); // what is in flight arrives
            sub.send("stop\n");
            const QString line = sub.waitFor(u"received"_s, 10000);
            if (line.isEmpty())
                return false;
            // sent after the match: what a subscriber can get (earlier samples went to nobody)
            const QStringList lines = publisher.lines();
            const auto matchedAt = std::find(lines.begin(), lines.end(), u"matched %1 1"_s.arg(topic));
            const double expected = double(std::count_if(matchedAt, lines.end(), [&](const QString& l) {
                return l.startsWith(u"sent %1 "_s.arg(topic));
            }));
            const auto f = fieldsOf(line);
            side.r.bufferDrops.push_back(udpReceiveBufferErrors() - drops0);
            side.r.expected.push_back(expected);
            side.r.received.push_back(f.value(u"messages"_s));
            side.r.rateHz.push_back(f.value(u"rate_hz"_s));
            // CPU ms per 1,000 messages received, and per 1,000 offered (sent after the match): a
            // sample lost to a full socket buffer still costs the fragments that did arrive
            side.r.cpuPerK.push_back(1e6 * f.value(u"ingest_cpu_s"_s)
                                     / std::max(1.0, f.value(u"messages"_s)));
            side.r.cpuPerKOffered.push_back(1e6 * f.value(u"ingest_cpu_s"_s) / std::max(1.0, expected));
            side.r.publisherRateHz.push_back(expected / std::max(0.001, sendingS));
            side.r.publisherCpuPerK.push_back(1e6 * publisherCpu / count);
            side.r.hwmMiB.push_back(f.value(u"hwm_kb"_s) / 1024);
            std::fprintf(stderr, "  run %d %-50s sent after match %.0f, %s\n", run + 1,
                         qPrintable(side.title), expected, qPrintable(line));
            if (f.value(u"malformed"_s) > 0)
                std::fprintf(stderr, "bench_ros2: %s received malformed samples\n", qPrintable(side.title));
        }
    }

    std::printf(
        "\nIngest: sensor_msgs/msg/PointCloud2, %d bytes of data, %d Hz, %d samples (reliable, keep last "
        "10) from a fresh Cyclone DDS publisher per run; %d run(s) of each subscriber, one at a time\n\n",
        kSize, kRate, count, runs);
    Bench::header("median");
    auto ratios = [&](const std::vector<double> IngestRuns::*figure) {
        const double ours = median(sides[0].r.*figure);
        return u"; %1x the reliable peer, %2x the best-effort peer"_s
            .arg(ours / median(sides[1].r.*figure), 0, 'f', 2)
            .arg(ours / median(sides[2].r.*figure), 0, 'f', 2);
    };
    for (const IngestSide& side : sides) {
        std::vector<double> lost;
        for (size_t k = 0; k < side.r.expected.size(); ++k)
            lost.push_back(std::max(0.0, side.r.expected[k] - side.r.received[k]));
        Bench::row(side.title + u": received"_s, median(side.r.received),
                   u"of %1 sent after it matched; lost %2 (%3 %)"_s.arg(median(side.r.expected))
                       .arg(median(lost))
                       .arg(100 * median(lost) / std::max(1.0, median(side.r.expected)), 0, 'f', 2));
        Bench::row(side.title + u": rate (Hz)"_s, median(side.r.rateHz),
                   u"publisher sent at %1 Hz"_s.arg(median(side.r.publisherRateHz), 0, 'f', 1));
        const bool bridgescope = &side == &sides[0];
        Bench::row(side.title + u": CPU ms / 1000 received"_s, median(side.r.cpuPerK),
                   range(side.r.cpuPerK) + (bridgescope ? ratios(&IngestRuns::cpuPerK) : QString()));
        Bench::row(side.title + u": CPU ms / 1000 offered"_s, median(side.r.cpuPerKOffered),
                   range(side.r.cpuPerKOffered)
                       + (bridgescope ? ratios(&IngestRuns::cpuPerKOffered) : QString()));
        Bench::row(side.title + u": peak RSS (MiB)"_s, median(side.r.hwmMiB));
        Bench::row(side.title + u": UDP datagrams dropped"_s, median(side.r.bufferDrops),
                   u"receive buffer full (host-wide RcvbufErrors during the run)"_s);
    }
    std::vector<double> publisherCpu;
    for (const IngestSide& side : sides)
        publisherCpu.insert(publisherCpu.end(), side.r.publisherCpuPerK.begin(),
                            side.r.publisherCpuPerK.end());
    Bench::row(u"Cyclone DDS publisher: CPU ms / 1000 sent"_s, median(publisherCpu),
               u"for reference, all runs"_s);
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int topics = Bench::envInt("BENCH_TOPICS", 1000);
    const int runs = Bench::envInt("BENCH_RUNS", 9);
    const int seconds = Bench::envInt("BENCH_SECONDS", 20);
    const int ingestRuns = Bench::envInt("BENCH_INGEST_RUNS", 3);
    // the tests use domains 1..60 and 100..199; every port of 200..230 fits in 16 bits
    const int domain = Ros2Peer::freeDomain(200, 230);
    std::printf("bench_ros2: ROS 2 domain %d on loopback, %d topics, %d discovery runs, ingest %d s x %d\n",
                domain, topics, runs, seconds, ingestRuns);
    if (!runDiscovery(domain, topics, runs))
        return 1;
    if (!runIngest(domain, seconds, ingestRuns))
        return 1;
    return 0;
}
