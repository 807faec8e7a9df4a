// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "experiment/experimentplan.h"

#include <atomic>
#include <memory>
#include <QCoreApplication>
#include <QString>

class QThread;
class QTcpServer;

/// A TCP relay in user space that gives one connection a link profile: every chunk of bytes waits
/// `delayMs` plus a normal jitter (one draw per burst of chunks, so a message keeps together),
/// queues behind the bandwidth, and a "lost" burst waits a retransmission timeout (TCP delivers it
/// later, it never vanishes), in each direction. Order is kept, as TCP keeps it. It listens on
/// 127.0.0.1 and forwards to the target; TLS passes through untouched. `tc netem` would need a
/// kernel module and privileges; this needs neither.
///
/// Memory is bounded per process: all relays together hold at most kMaxHeldBytes read and not yet
/// written to the kernel (waiting for delay and bandwidth, or for a peer that does not read), plus
/// kReadBufferBytes in each socket's own buffer. Beyond, reading pauses (TCP's window then closes
/// towards the sender) until the bytes held drain; readPauses() counts the pauses.
class LinkRelay
{
    Q_DECLARE_TR_FUNCTIONS(LinkRelay)
public:
    static constexpr int kMaxConnections = 64;
    static constexpr qint64 kMaxHeldBytes = 64 * 1024 * 1024; ///< per process; beyond, reading pauses
    static constexpr qint64 kReadBufferBytes = 256 * 1024; ///< each socket's own read buffer
    static constexpr double kRetransmissionMs = 200; ///< Linux's minimum RTO

    /// Listens on `listenAddress` (an IP literal; 127.0.0.1 unless a bridge on another host
    /// connects to it) on a free port, and relays to targetHost:targetPort.
    static Result<std::unique_ptr<LinkRelay>>
    start(const LinkProfile& profile, const QString& targetHost, quint16 targetPort, quint32 seed = 1,
          const QString& listenAddress = QStringLiteral("127.0.0.1"));
    ~LinkRelay();

    quint16 port() const { return m_port; }
    quint64 bytesRelayed() const { return m_bytes.load(); }
    quint64 burstsLost() const { return m_lost.load(); }
    /// How often a direction stopped reading because the process held kMaxHeldBytes.
    quint64 readPauses() const { return m_pauses.load(); }
    /// The bytes all relays of this process hold now (queued for the link, or not yet written).
    static qint64 heldBytes();

private:
    LinkRelay() = default;
    class Pipe;
    class Connection;

    std::unique_ptr<QThread> m_thread;
    QTcpServer* m_server = nullptr; ///< lives on m_thread, parent of the connections
    quint16 m_port = 0;
    std::atomic<quint64> m_bytes {0};
    std::atomic<quint64> m_lost {0};
    std::atomic<quint64> m_pauses {0};
};
