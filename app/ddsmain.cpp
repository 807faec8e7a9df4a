// SPDX-License-Identifier: MIT
// bridgescope-dds: the DDS participant of Ros2Participant (core/ros2), in a process of its own.
// The DDS library (Cyclone DDS, core/dds) parses whatever any host of the domain sends: should a
// datagram crash it or make it allocate without end, that ends this process, under an
// address-space limit, and the parent starts it again. Reads Ros2Protocol frames on
// stdin, writes them on stdout; ends when stdin closes or the parent dies.
#include "base/logging.h"
#include "base/wallclock.h"
#include "dds/ros2engine.h"
#include "ros2/ddschildserver.h"
#include "ros2/ros2protocol.h"

#include <cerrno>
#include <cstdlib>
#include <csignal>
#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTimer>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/uio.h>
#include <unistd.h>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

namespace {

/// The most address space the participant may take: Cyclone DDS with a 4 MiB socket buffer, its
/// threads' stacks and pools reserves about 300 MiB on a quiet domain (VmPeak 304 MiB, Debug
/// build), as Fast DDS did; a datagram that made it allocate without end would stop here.
constexpr rlim_t kMaxAddressSpace = rlim_t(1536) << 20;

void limitMemory()
{
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    if (qEnvironmentVariableIsSet("BRIDGESCOPE_DDS_NO_LIMIT"))
        return;
    rlimit limit {kMaxAddressSpace, kMaxAddressSpace};
    setrlimit(RLIMIT_AS, &limit);
#endif
}

/// The pipe to the parent: stdout as it was given, before stdout became stderr (so that nothing a
/// library prints can end up in the frames).
int g_frames = STDOUT_FILENO;

/// Writes a frame of `kind` with `body` to the parent, its header and body in one writev() (no copy
/// of the body into a frame: a sample batch is megabytes); false when the parent is gone.
bool writeFrame(Kind kind, const QByteArray& body)
{
    const QByteArray header = Ros2Protocol::frameHeader(kind, body.size());
    iovec parts[2] = {{const_cast<char*>(header.constData()), std::size_t(header.size())},
                      {const_cast<char*>(body.constData()), std::size_t(body.size())}};
    int first = 0;
    while (first < 2) {
        const ssize_t n = ::writev(g_frames, parts + first, 2 - first);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        std::size_t done = std::size_t(n);
        while (first < 2 && done >= parts[first].iov_len)
            done -= parts[first++].iov_len;
        if (first < 2) {
            parts[first].iov_base = static_cast<char*>(parts[first].iov_base) + done;
            parts[first].iov_len -= done;
        }
    }
    return true;
}

/// The participant, with one hook for the tests of the parent's quarantine (tst_ros2bridge): with
/// BRIDGESCOPE_DDS_TEST_CRASH_TYPE set, a writer or reader of that type aborts this process, as
/// Cyclone DDS did on a type it could not take (issue 41); with BRIDGESCOPE_DDS_TEST_CRASH_UNLESS_LIMITED
/// set (milliseconds), this process aborts that long after it joined the domain unless its graph is
/// limited (a peer's discovery that kills every child: the parent's loop detection, issue 41).
class ChildEngine : public Ros2Engine
{
public:
    Status start(const Ros2Options& options) override
    {
        const int crashAfterMs = qEnvironmentVariableIntValue("BRIDGESCOPE_DDS_TEST_CRASH_UNLESS_LIMITED");
        if (crashAfterMs > 0 && !options.limitedGraph)
            QTimer::singleShot(crashAfterMs, [] { std::abort(); });
        return Ros2Engine::start(options);
    }
    Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        crashOn(type);
        return Ros2Engine::advertise(topic, type, qos);
    }
    Status subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        crashOn(type);
        return Ros2Engine::subscribeSamples(topic, type, qos);
    }

private:
    void crashOn(const QString& type) const
    {
        if (!m_crashType.isEmpty() && type == m_crashType)
            std::abort();
    }
    const QString m_crashType = qEnvironmentVariable("BRIDGESCOPE_DDS_TEST_CRASH_TYPE");
};

class Worker : public QObject
{
public:
    Worker()
        : m_input(STDIN_FILENO, QSocketNotifier::Read)
        , m_server(m_engine, [this](Kind kind, const QByteArray& body) { send(kind, body); })
    {
        connect(&m_input, &QSocketNotifier::activated, this, &Worker::readInput);
        connect(&m_engine, &Ros2Engine::graphChanged, this, [this](const Ros2Graph& graph) {
            send(Kind::Graph, Ros2Protocol::encodeGraph({graph, m_engine.badDiscoveryInfo()}));
        });
        connect(&m_engine, &Ros2Engine::monitorFailed, this, [this](const QString& topic, const QString& why) {
            send(Kind::MonitorFailed, Ros2Protocol::encodeStrings({topic, why}));
        });
        connect(&m_engine, &Ros2Engine::samplesReceived, this, &Worker::sendReceived);
        m_drain.setInterval(Ros2Engine::kPollMs);
        connect(&m_drain, &QTimer::timeout, this, &Worker::drain);
        m_drain.start();
        m_heartbeat.setInterval(1000);
        connect(&m_heartbeat, &QTimer::timeout, this, [this] { send(Kind::Heartbeat); });
        m_heartbeat.start();
    }

private:
    void send(Kind kind, const QByteArray& body = {})
    {
        if (!writeFrame(kind, body))
            QCoreApplication::exit(0); // the parent is gone
    }

    void readInput()
    {
        static char buffer[1024 * 1024]; // samples to publish come this way
        const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            return;
        if (n <= 0) { // the parent closed its end, or is gone
            m_input.setEnabled(false);
            QCoreApplication::exit(0);
            return;
        }
        m_server.append(QByteArray(buffer, qsizetype(n)));
        handleTurn();
    }

    /// A turn of requests; while more wait, stdin is not read and the next turn comes after what
    /// else waits on the event loop (the heartbeat, the drain).
    void handleTurn()
    {
        switch (m_server.handlePending()) {
        case DdsChildServer::Turn::Failed:
            qCCritical(lcRos2).noquote() << "bridgescope-dds:" << m_server.error();
            QCoreApplication::exit(2);
            return;
        case DdsChildServer::Turn::More:
            m_input.setEnabled(false);
            QMetaObject::invokeMethod(this, &Worker::handleTurn, Qt::QueuedConnection);
            return;
        case DdsChildServer::Turn::Idle:
            m_input.setEnabled(true);
            return;
        }
    }

    /// Subscribed topics' samples, as soon as Cyclone passed them on: taken a batch at a time, each
    /// once the one before is in the pipe, so that what waits for a parent that does not read stays
    /// in the engine's bound (the rest dropped and counted there). After kTurnBytes the other
    /// requests get a turn and this goes on.
    void sendReceived()
    {
        constexpr qint64 kTurnBytes = 16 * Ros2Protocol::kBatchBytes;
        qint64 sent = 0;
        while (sent < kTurnBytes) {
            std::vector<Ros2Engine::Received> taken = m_engine.takeReceived(Ros2Protocol::kBatchBytes);
            if (taken.empty())
                return;
            for (Ros2Engine::Received& r : taken) {
                for (const Ros2Sample& s : r.samples)
                    sent += s.bytes.size() + 1; // an empty sample counts too
                sendSamples(Kind::Received, r.topic, r.dropped, std::move(r.samples));
            }
        }
        QMetaObject::invokeMethod(this, &Worker::sendReceived, Qt::QueuedConnection);
    }

    void drain()
    {
        Ros2TopicReaders& readers = m_engine.readers();
        for (const QString& topic : m_server.watched())
            sendSamples(Kind::Samples, topic, readers.droppedMessages(topic), readers.takeMessages(topic));
        std::vector<SourceHead> arrivals = readers.takeArrivals();
        if (!arrivals.empty())
            send(Kind::Arrivals,
                 Ros2Protocol::encodeArrivals({readers.droppedArrivals(), std::move(arrivals)}));
        if (++m_ticks * Ros2Engine::kPollMs >= Ros2Protocol::kStatsMs) {
            m_ticks = 0;
            sendStats();
        }
    }

    /// Samples in frames of about kBatchBytes (one sample is at most Ros2RawType's 64 MiB).
    void sendSamples(Kind kind, const QString& topic, quint64 dropped, std::vector<Ros2Sample> samples)
    {
        Ros2Protocol::SampleBatch batch {topic, dropped, {}};
        qsizetype bytes = 0;
        for (Ros2Sample& s : samples) {
            bytes += s.bytes.size();
            batch.samples.push_back(std::move(s));
            if (bytes >= Ros2Protocol::kBatchBytes) {
                send(kind, Ros2Protocol::encodeSamples(batch));
                batch.samples.clear();
                bytes = 0;
            }
        }
        if (!batch.samples.empty())
            send(kind, Ros2Protocol::encodeSamples(batch));
    }

    /// The monitored topics' figures; a topic's last message only when it changed.
    void sendStats()
    {
        const QHash<QString, Ros2MonitorStats> stats = m_engine.readers().snapshot(wallClockNs());
        if (stats.isEmpty())
            return;
        QList<Ros2Protocol::TopicStats> out;
        qsizetype bytes = 0;
        for (auto it = stats.cbegin(); it != stats.cend(); ++it) {
            quint64& sent = m_server.sentMessages()[it.key()];
            const bool with = sent != it->messages && bytes < Ros2Protocol::kBatchBytes;
            if (with) {
                sent = it->messages;
                bytes += it->lastMessage.size();
            }
            out.append({it.key(), *it, with});
        }
        send(Kind::Stats, Ros2Protocol::encodeStats(out));
    }

    ChildEngine m_engine;
    QSocketNotifier m_input;
    DdsChildServer m_server;
    QTimer m_drain;
    QTimer m_heartbeat;
    int m_ticks = 0;
};

} // namespace

int main(int argc, char** argv)
{
    limitMemory();
    prctl(PR_SET_PDEATHSIG, SIGKILL); // never outlive the parent
    if (getppid() == 1)
        return 0; // the parent died before the line above
    std::signal(SIGPIPE, SIG_IGN); // a write to a parent that is gone fails instead
    std::signal(SIGINT, SIG_IGN); // Ctrl+C in a terminal is the parent's to handle; it ends us
    // Frames go to a copy of stdout; what Cyclone DDS (or anything else) prints goes to stderr.
    g_frames = ::dup(STDOUT_FILENO);
    if (g_frames < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0)
        return 1;
    QCoreApplication app(argc, argv);
    if (argc > 1) {
        std::fprintf(stderr, "bridgescope-dds takes no arguments: Bridgescope starts it and talks to it on a pipe\n");
        return 2;
    }
    Worker worker;
    return app.exec();
}
