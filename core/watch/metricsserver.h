// SPDX-License-Identifier: MIT
#pragma once

#include "watch/metricsexposition.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <QCoreApplication>
#include <QHostAddress>
#include <QList>
#include <QPointer>
#include <QString>

class QThread;
class QTcpServer;
class QTcpSocket;

/// A small HTTP/1.1 server for Prometheus' pull: GET /metrics answers the latest published
/// snapshot, in OpenMetrics or the text format as the Accept header asks. It runs on a thread of
/// its own, so a scrape (or a slow or hostile client) never holds up the thread that publishes.
///
/// Every client is bounded: at most kMaxClients at once (beyond, the longest idle one is closed), a request
/// head of at most 8 KiB that must arrive within 10 s, one request per connection. Only GET and HEAD are
/// served; other paths get 404, other methods 405, a malformed head 400.
class MetricsServer
{
    Q_DECLARE_TR_FUNCTIONS(MetricsServer)
public:
    static constexpr int kMaxClients = 32;
    static constexpr qsizetype kMaxRequestBytes = 8 * 1024;
    static constexpr int kRequestTimeoutMs = 10'000;

    /// Listens on `hostPort` ("127.0.0.1:9464", "[::1]:0" for a free port, "localhost:9464",
    /// ":9464" for every interface); nullptr with `error` when it cannot.
    static std::unique_ptr<MetricsServer> listen(const QString& hostPort, QString* error);
    ~MetricsServer();

    quint16 port() const { return m_port; }
    /// What the next scrape answers (any thread).
    void publish(std::shared_ptr<const MetricsSnapshot> snapshot);
    /// Requests answered, and refused or malformed (for the tests and the log).
    quint64 served() const { return m_served.load(); }
    quint64 rejected() const { return m_rejected.load(); }

    /// Splits "host:port" / "[v6]:port"; false with `error` when it is not one.
    static bool parseHostPort(const QString& hostPort, QHostAddress* address, quint16* port, QString* error);

private:
    MetricsServer() = default;
    void accept(); // on the server's thread
    void read(QTcpSocket* socket);
    void answer(QTcpSocket* socket, int status, const QByteArray& type, const QByteArray& body, bool head);

    std::unique_ptr<QThread> m_thread;
    QTcpServer* m_server = nullptr; ///< lives on m_thread
    quint16 m_port = 0;
    int m_clients = 0; ///< on m_thread
    QList<QPointer<QTcpSocket>>
        m_waiting; ///< on m_thread: accepted, oldest first (answered ones are skipped)
    std::mutex m_mutex;
    std::shared_ptr<const MetricsSnapshot> m_snapshot;
    std::atomic<quint64> m_served {0};
    std::atomic<quint64> m_rejected {0};
};
