// SPDX-License-Identifier: MIT
#include "linkrelay.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <QElapsedTimer>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QTimer>
#include <random>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kBurstGapNs = 1'000'000; ///< chunks closer than this belong to one burst (one message)
constexpr int kResumePollMs = 5; ///< a paused direction looks again this often (another may have drained)

/// What all pipes of the process hold: read, and not yet written to the kernel.
std::atomic<qint64> g_heldBytes {0};

qint64 nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

/// One direction of a connection: bytes read from `from` are written to `to` at their release time.
class LinkRelay::Pipe : public QObject
{
public:
    Pipe(QTcpSocket* from, QTcpSocket* to, const LinkProfile& profile, quint32 seed, LinkRelay* relay,
         QObject* parent)
        : QObject(parent)
        , m_from(from)
        , m_to(to)
        , m_profile(profile)
        , m_random(seed)
        , m_relay(relay)
    {
        m_timer.setSingleShot(true);
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, &Pipe::release);
        connect(&m_resume, &QTimer::timeout, this, &Pipe::take);
        connect(from, &QTcpSocket::readyRead, this, &Pipe::take);
        connect(to, &QTcpSocket::bytesWritten, this, [this] {
            account();
            if (m_paused)
                take();
        });
    }

    ~Pipe() override { g_heldBytes -= m_held; }

    void take()
    {
        // Qt reads at most kReadBufferBytes into `from` while we do not: the rest waits in the
        // kernel, and TCP's window closes towards the sender.
        const qint64 room = kMaxHeldBytes - g_heldBytes.load();
        if (room <= 0) {
            pause();
            return;
        }
        if (m_paused) {
            m_paused = false;
            m_resume.stop();
        }
        // Ask for what is there, never for the room left: QIODevice::read(maxSize) first resizes
        // its result to maxSize (64 MiB here, a 128 MiB block once QByteArray rounds it up), reads
        // into it, and only then shrinks the size, not the block. Each chunk, even an empty read,
        // cost an mmap and a munmap (0.4 ms a hop in a normal build) and, under ASan, the poisoning
        // of 16 MiB of shadow at allocation and at free (50-200 ms each): ~0.15 s a hop, ~1 s late
        // across a bridge's hops. A queued chunk also kept its 128 MiB block alive.
        const qint64 available = std::min(m_from->bytesAvailable(), room);
        if (available <= 0)
            return;
        const QByteArray bytes = m_from->read(available);
        if (bytes.isEmpty())
            return;
        const qint64 now = nowNs();
        if (now - m_lastArrivalNs > kBurstGapNs) { // a new burst: its own delay, and maybe lost
            m_burstDelayNs = qint64(
                (m_profile.delayMs + (m_profile.jitterMs > 0 ? m_normal(m_random) * m_profile.jitterMs : 0))
                * 1e6);
            m_burstDelayNs = std::max<qint64>(m_burstDelayNs, 0);
            if (m_profile.lossPercent > 0 && m_uniform(m_random) * 100 < m_profile.lossPercent) {
                m_burstDelayNs += qint64(kRetransmissionMs * 1e6);
                ++m_relay->m_lost;
            }
        }
        m_lastArrivalNs = now;
        qint64 sent = now; // when the last byte is on the wire
        if (m_profile.bandwidthMbit > 0) {
            m_wireFreeNs = std::max(m_wireFreeNs, now)
                + qint64(double(bytes.size()) * 8 / m_profile.bandwidthMbit * 1e3);
            sent = m_wireFreeNs;
        }
        const qint64 at = std::max(sent + m_burstDelayNs, m_lastReleaseNs); // in order, as TCP
        m_lastReleaseNs = at;
        m_queue.push_back({at, bytes});
        m_queued += bytes.size();
        account();
        schedule();
    }

    void release()
    {
        const qint64 now = nowNs();
        while (!m_queue.empty() && m_queue.front().first <= now + 50'000) { // within 50 µs: now
            const QByteArray& b = m_queue.front().second;
            if (m_to->state() != QAbstractSocket::UnconnectedState) // while connecting, Qt keeps it
                m_to->write(b);
            m_relay->m_bytes += quint64(b.size());
            m_queued -= b.size();
            m_queue.pop_front();
        }
        account(); // written bytes stay held until the kernel has them (bytesWritten)
        if (m_from->bytesAvailable() > 0 || m_paused)
            take();
        schedule();
        if (m_queue.empty() && m_closing)
            m_to->disconnectFromHost();
    }

    /// The source closed: the rest is delivered, then the other side is closed.
    void close()
    {
        m_closing = true;
        take();
        if (m_queue.empty())
            m_to->disconnectFromHost();
    }

private:
    /// Brings the process's count up to date with what this direction holds now.
    void account()
    {
        const qint64 held = m_queued + m_to->bytesToWrite();
        g_heldBytes += held - m_held;
        m_held = held;
    }

    void pause()
    {
        if (!m_paused) {
            m_paused = true;
            ++m_relay->m_pauses;
        }
        if (!m_resume.isActive())
            m_resume.start(kResumePollMs); // another pipe (or relay) may be the one that drains
    }

    void schedule()
    {
        if (m_queue.empty()) {
            m_timer.stop();
            return;
        }
        const qint64 waitNs = std::max<qint64>(m_queue.front().first - nowNs(), 0);
        // Whole milliseconds rounded down, then zero-timers for the rest: a QTimer fires at the
        // earliest on its millisecond, so rounding up (or to nearest) would add half a ms a hop.
        m_timer.start(int(waitNs / 1'000'000));
    }

    QTcpSocket* m_from;
    QTcpSocket* m_to;
    LinkProfile m_profile;
    std::mt19937 m_random;
    std::normal_distribution<double> m_normal {0, 1};
    std::uniform_real_distribution<double> m_uniform {0, 1};
    LinkRelay* m_relay;
    QTimer m_timer;
    QTimer m_resume; ///< while paused
    std::deque<std::pair<qint64, QByteArray>> m_queue; ///< (release time, bytes)
    qint64 m_queued = 0;
    qint64 m_held = 0; ///< m_queued plus what `to` has not yet written, as g_heldBytes counts it
    bool m_paused = false;
    qint64 m_lastArrivalNs = 0;
    qint64 m_burstDelayNs = 0;
    qint64 m_wireFreeNs = 0;
    qint64 m_lastReleaseNs = 0;
    bool m_closing = false;
};

/// A client and its connection to the target, with a pipe each way.
class LinkRelay::Connection : public QObject
{
public:
    Connection(QTcpSocket* client, const QString& host, quint16 port, const LinkProfile& profile,
               quint32 seed, LinkRelay* relay, QObject* parent)
        : QObject(parent)
        , m_client(client)
        , m_upstream(new QTcpSocket(this))
    {
        client->setParent(this);
        client->setReadBufferSize(kReadBufferBytes);
        m_upstream->setReadBufferSize(kReadBufferBytes);
        client->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        m_upstream->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        // The way there is longer by thereExtraMs: towards the broker, on the relay the vehicle uses.
        LinkProfile up = profile;
        up.delayMs += profile.thereExtraMs;
        m_up = new Pipe(client, m_upstream, up, seed, relay, this);
        m_down = new Pipe(m_upstream, client, profile, seed * 7919u + 1, relay, this);
        connect(client, &QTcpSocket::disconnected, this, [this] {
            m_up->close();
            finishIfDone();
        });
        connect(m_upstream, &QTcpSocket::disconnected, this, [this] {
            m_down->close();
            finishIfDone();
        });
        connect(m_upstream, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
            if (e != QAbstractSocket::RemoteHostClosedError)
                m_client->abort(); // the target is not there: neither is the relay
            finishIfDone();
        });
        m_upstream->connectToHost(host, port);
    }

    ~Connection() override
    {
        delete m_up; // before the sockets (children made earlier): a pipe never sees a deleted one
        delete m_down;
    }

private:
    void finishIfDone()
    {
        if (m_client->state() == QAbstractSocket::UnconnectedState
            && m_upstream->state() == QAbstractSocket::UnconnectedState)
            deleteLater();
    }

    QTcpSocket* m_client;
    QTcpSocket* m_upstream;
    Pipe* m_up = nullptr;
    Pipe* m_down = nullptr;
};

Result<std::unique_ptr<LinkRelay>> LinkRelay::start(const LinkProfile& profile, const QString& targetHost,
                                                    quint16 targetPort, quint32 seed,
                                                    const QString& listenAddress)
{
    const QHostAddress address(listenAddress);
    if (address.isNull())
        return LocatedError {
            tr("the link relay cannot listen on '%1': not an IP address").arg(listenAddress)};
    std::unique_ptr<LinkRelay> r(new LinkRelay);
    r->m_thread = std::make_unique<QThread>();
    r->m_thread->setObjectName(u"link relay"_s);
    r->m_server = new QTcpServer;
    r->m_server->moveToThread(r->m_thread.get());
    r->m_thread->start();
    QString why;
    LinkRelay* self = r.get();
    QMetaObject::invokeMethod(
        r->m_server,
        [self, profile, targetHost, targetPort, seed, address, &why] {
            if (!self->m_server->listen(address, 0)) {
                why = self->m_server->errorString();
                return;
            }
            self->m_port = self->m_server->serverPort();
            auto connections = std::make_shared<quint32>(0);
            QObject::connect(self->m_server, &QTcpServer::newConnection, self->m_server,
                             [self, profile, targetHost, targetPort, seed, connections] {
                                 while (QTcpSocket* client = self->m_server->nextPendingConnection()) {
                                     if (self->m_server->children().size() > kMaxConnections) {
                                         client->abort();
                                         client->deleteLater();
                                         continue;
                                     }
                                     new Connection(client, targetHost, targetPort, profile,
                                                    seed + 104729u * ++*connections, self, self->m_server);
                                 }
                             });
        },
        Qt::BlockingQueuedConnection);
    if (!why.isEmpty())
        return LocatedError {tr("the link relay cannot listen: %1").arg(why)};
    return r;
}

qint64 LinkRelay::heldBytes()
{
    return g_heldBytes.load();
}

LinkRelay::~LinkRelay()
{
    if (!m_thread)
        return;
    QTcpServer* server = m_server;
    QMetaObject::invokeMethod(
        server, [server] { delete server; }, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
}
