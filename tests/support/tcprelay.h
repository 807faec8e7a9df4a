// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QtGlobal>

class QThread;
class QTcpServer;

/// A plain TCP relay on 127.0.0.1 that a test can cut and restore, as a network link that goes
/// down and comes back: cut() drops every connection and stops listening (new connections are
/// refused), restore() listens again on the same port. It forwards on its own thread, so a test
/// that blocks on an HTTP request meanwhile does not stall it. (core's LinkRelay shapes a link
/// that stays up: delay, jitter, bandwidth; this one only breaks.)
class TcpRelay
{
public:
    TcpRelay();
    ~TcpRelay();
    TcpRelay(const TcpRelay&) = delete;
    TcpRelay& operator=(const TcpRelay&) = delete;

    /// Listens on a free port and forwards to 127.0.0.1:targetPort; false if it cannot listen.
    bool start(quint16 targetPort);
    quint16 port() const { return m_port; }
    void cut();
    bool restore();
    /// Connections accepted since start.
    int connections() const;

private:
    class Forwarder;
    std::unique_ptr<QThread> m_thread;
    Forwarder* m_forwarder = nullptr; ///< lives on m_thread
    quint16 m_port = 0;
};
