// SPDX-License-Identifier: MIT
// Bridgescope's side of bench_ros2, in a process of its own so that its CPU time and memory are
// its own: a QCoreApplication with a Ros2Participant (localhostOnly), as the GUI's session uses it.
// The participant runs in this process's bridgescope-dds child (issue 31): CPU time is this
// process's and the child's together, peak memory the sum of both peaks.
//
//   bench_ros2_bridgescope discover DOMAIN TOPICS PREFIX GRAPH_INTERVAL_MS TIMEOUT_S
//       until the graph holds TOPICS topics named PREFIX... (/bench/t) with a publisher each and
//       every publisher's node named; prints one line `discovered ...` (times from just before
//       start(), taken when graphChanged delivers the graph).
//   bench_ros2_bridgescope subscribe DOMAIN TOPIC SIZE TIMEOUT_S
//       monitor(TOPIC) once the graph has it, the snapshot read every 33 ms as LiveSession's drain
//       does; prints `subscribed`, `matched`, and at a line on stdin (or the timeout) `received ...`.
#include "base/wallclock.h"
#include "benchutil.h"
#include "ddschild.h"
#include "ros2/ros2participant.h"

#include <cstdio>
#include <cstring>
#include <QFile>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSocketNotifier>
#include <QTimer>
#include <sys/resource.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {

/// This process's CPU seconds with its bridgescope-dds child's (found once, then kept).
double cpuSeconds()
{
    static qint64 child = 0;
    if (child <= 0)
        child = DdsChild::of();
    double childCpu = 0;
    QFile stat(u"/proc/%1/stat"_s.arg(child));
    if (child > 0 && stat.open(QIODevice::ReadOnly)) {
        const QByteArray line = stat.readAll();
        const QList<QByteArray> f = line.mid(line.lastIndexOf(')') + 2).split(' ');
        if (f.size() > 12) // utime and stime: fields 14 and 15 of stat, 12 and 13 after the name
            childCpu = double(f.at(11).toLongLong() + f.at(12).toLongLong()) / double(sysconf(_SC_CLK_TCK));
    }
    return Bench::cpuSeconds() + childCpu;
}

/// This process's VmRSS or VmHWM with its bridgescope-dds child's, in kB.
qint64 statusKb(const char* field)
{
    qint64 kb = Bench::statusKb(field);
    QFile status(u"/proc/%1/status"_s.arg(DdsChild::of()));
    if (status.open(QIODevice::ReadOnly))
        for (const QByteArray& line : status.readAll().split('\n'))
            if (line.startsWith(field))
                kb += line.mid(qsizetype(std::strlen(field))).trimmed().split(' ').first().toLongLong();
    return kb;
}

int discover(int domain, int topics, const QString& prefix, int intervalMs, int timeoutS)
{
    Ros2Participant participant;
    participant.setGraphInterval(intervalMs);
    const qint64 rss0 = statusKb("VmRSS:");
    const double cpu0 = cpuSeconds();
    QElapsedTimer clock;
    double topicsMs = -1, topicsCpu = 0;
    QObject::connect(&participant, &Ros2Participant::graphChanged, [&](const Ros2Graph& graph) {
        int found = 0, named = 0;
        for (const Ros2Topic& t : graph.topics) {
            if (!t.name.startsWith(prefix) || t.publishers.isEmpty())
                continue;
            ++found;
            named += std::all_of(t.publishers.cbegin(), t.publishers.cend(),
                                 [](const Ros2Endpoint& e) { return !e.node.isEmpty(); });
        }
        if (topicsMs < 0 && found >= topics) {
            topicsMs = double(clock.nsecsElapsed()) / 1e6;
            topicsCpu = cpuSeconds() - cpu0;
        }
        if (found >= topics && named >= topics)
            QCoreApplication::exit(0);
    });
    clock.start();
    if (const Status joined = participant.start({domain, true}); !joined) {
        std::fprintf(stderr, "bench_ros2_bridgescope: %s\n", qPrintable(joined.error().toString()));
        return 1;
    }
    QTimer::singleShot(timeoutS * 1000, [] { QCoreApplication::exit(1); });
    const int rc = QCoreApplication::exec();
    const double ms = double(clock.nsecsElapsed()) / 1e6;
    const double cpu = cpuSeconds() - cpu0;
    if (rc != 0) {
        std::printf("incomplete topics_ms=%.1f\n", topicsMs);
        return 1;
    }
    std::printf("discovered topics_ms=%.1f named_ms=%.1f topics_cpu_s=%.3f named_cpu_s=%.3f rss0_kb=%lld "
                "rss_kb=%lld hwm_kb=%lld\n",
                topicsMs, ms, topicsCpu, cpu, rss0, statusKb("VmRSS:"), statusKb("VmHWM:"));
    std::fflush(stdout);
    return 0;
}

int subscribe(int domain, const QString& topic, int size, int timeoutS)
{
    Ros2Participant participant;
    if (const Status joined = participant.start({domain, true}); !joined) {
        std::fprintf(stderr, "bench_ros2_bridgescope: %s\n", qPrintable(joined.error().toString()));
        return 1;
    }
    QObject::connect(&participant, &Ros2Participant::monitorFailed, [](const QString&, const QString& why) {
        std::fprintf(stderr, "bench_ros2_bridgescope: %s\n", qPrintable(why));
        QCoreApplication::exit(1);
    });
    QObject::connect(&participant, &Ros2Participant::graphChanged, [&](const Ros2Graph& graph) {
        if (!participant.isMonitored(topic) && graph.topic(topic)) {
            participant.monitor(topic);
            std::printf("subscribed\n");
            std::fflush(stdout);
        }
    });

    // LiveSession's drain: the figures every 33 ms
    bool matched = false;
    double matchCpu = 0;
    qint64 firstNs = 0; // the last sample's time at the first drain that saw one ...
    quint64 firstCount = 0; // ... and how many had come by then
    QTimer drain;
    drain.setTimerType(Qt::PreciseTimer);
    QObject::connect(&drain, &QTimer::timeout, [&] {
        const auto stats = participant.snapshot(wallClockNs());
        const auto it = stats.constFind(topic);
        if (it == stats.cend())
            return;
        if (!matched && it->matchedPublishers > 0) {
            matched = true;
            matchCpu = cpuSeconds();
            std::printf("matched\n");
            std::fflush(stdout);
        }
        if (firstNs == 0 && it->messages > 0) {
            firstNs = it->lastNs;
            firstCount = it->messages;
        }
    });
    drain.start(33);

    // as the Fast DDS example: run until told (a line on stdin), bounded by the timeout
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    QObject::connect(&input, &QSocketNotifier::activated, [] { QCoreApplication::exit(0); });
    QTimer::singleShot(timeoutS * 1000, [] { QCoreApplication::exit(0); });
    if (QCoreApplication::exec() != 0)
        return 1;
    const double cpu = cpuSeconds();
    const qint64 hwm = statusKb("VmHWM:");
    drain.stop();
    const Ros2MonitorStats last = participant.snapshot(wallClockNs()).value(topic);
    participant.stop();
    // the monitor keeps the last sample only: check that one
    const bool whole = last.lastSize == 0 || last.lastSize >= size;
    const double span = firstNs > 0 && last.lastNs > firstNs ? double(last.lastNs - firstNs) / 1e9 : 0.0;
    std::printf("received messages=%llu malformed=%d bytes=%llu rate_hz=%.2f ingest_cpu_s=%.3f cpu_s=%.3f "
                "hwm_kb=%lld\n",
                static_cast<unsigned long long>(last.messages), whole ? 0 : 1,
                static_cast<unsigned long long>(last.bytes),
                span > 0 ? double(last.messages - firstCount) / span : 0.0, matched ? cpu - matchCpu : 0.0,
                cpu, hwm);
    std::fflush(stdout);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const QString mode = args.value(1);
    if (mode == u"discover"_s && args.size() == 7)
        return discover(args[2].toInt(), args[3].toInt(), args[4], args[5].toInt(), args[6].toInt());
    if (mode == u"subscribe"_s && args.size() == 6)
        return subscribe(args[2].toInt(), args[3], args[4].toInt(), args[5].toInt());
    std::fprintf(stderr,
                 "usage: bench_ros2_bridgescope discover DOMAIN TOPICS PREFIX GRAPH_INTERVAL_MS TIMEOUT_S\n"
                 "       bench_ros2_bridgescope subscribe DOMAIN TOPIC SIZE TIMEOUT_S\n");
    return 2;
}
