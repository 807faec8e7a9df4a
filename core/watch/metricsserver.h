// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
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
/// Every client is bounded: a request head of at most 8 KiB (CRLF or bare-LF lines, an origin or
/// absolute-URI target; see HttpHead) that must arrive within kRequestTimeoutMs, one request per
/// connection. At most kMaxClients at once: a newcomer beyond makes room by closing, oldest first, a
/// client that has sent nothing, else one whose head is incomplete, else one that has its answer, so
/// that bursts of idle connections churn among themselves and never push out a scrape that has asked.
/// Answers are made once per published snapshot and format (and shared), and the bytes queued to all
/// clients stay within kMaxQueuedBytes: a client that does not read is closed, oldest first, when a new
/// answer would pass it. Only GET and HEAD are served; other paths get 404, other methods 405, a
/// malformed head 400.
class MetricsServer
{
    Q_DECLARE_TR_FUNCTIONS(MetricsServer)
public:
    static constexpr int kMaxClients = 128; ///< a socket and at most one head (8 KiB) each: about 1.5 MiB in all
    static constexpr qsizetype kMaxRequestBytes = 8 * 1024;
    static constexpr int kRequestTimeoutMs = 5'000;
    /// The memory budget of unsent answers, over all clients (an answer is at most
    /// MetricsExposition::kMaxAnswerBytes).
    static constexpr qsizetype kMaxQueuedBytes = 64 * 1024 * 1024;

    /// Listens on `hostPort` ("127.0.0.1:9464", "[::1]:0" for a free port, "localhost:9464",
    /// ":9464" for every interface); an error when it cannot.
    static Result<std::unique_ptr<MetricsServer>> listen(const QString& hostPort);
    ~MetricsServer();

    quint16 port() const { return m_port; }
    /// What the next scrape answers (any thread).
    void publish(std::shared_ptr<const MetricsSnapshot> snapshot);
    /// Requests answered, and refused or malformed (for the tests and the log).
    quint64 served() const { return m_served.load(); }
    quint64 rejected() const { return m_rejected.load(); }
    /// Clients closed to make room for a newcomer or to keep within kMaxQueuedBytes.
    quint64 dropped() const { return m_dropped.load(); }

    /// Where to listen: the address and the port of a "host:port".
    struct Endpoint
    {
        QHostAddress address;
        quint16 port = 0;
    };
    /// Splits "host:port" / "[v6]:port"; an error when it is not one.
    static Result<Endpoint> parseHostPort(const QString& hostPort);

private:
    MetricsServer() = default;
    void accept(); // on the server's thread
    /// Closes one client to make room for a newcomer; false when none may go.
    bool makeRoom();
    void read(QTcpSocket* socket);
    void answer(QTcpSocket* socket, int status, const QByteArray& type, const QByteArray& body, bool head);
    /// The exposition of the latest snapshot in `format`, made once per snapshot.
    QByteArray exposition(MetricsFormat format);
    /// Closes clients with unsent answers, oldest first, until `more` bytes fit in kMaxQueuedBytes.
    void keepWithinBudget(qsizetype more);
    void drop(QTcpSocket* socket);

    std::unique_ptr<QThread> m_thread;
    QTcpServer* m_server = nullptr; ///< lives on m_thread
    quint16 m_port = 0;
    QList<QPointer<QTcpSocket>> m_clients; ///< on m_thread: open, oldest first
    std::shared_ptr<const MetricsSnapshot> m_answered; ///< on m_thread: the snapshot m_answers are of
    QByteArray m_answers[2]; ///< on m_thread: by MetricsFormat
    quint64 m_answeredDropped = 0; ///< on m_thread: the dropped clients m_answers say
    std::mutex m_mutex;
    std::shared_ptr<const MetricsSnapshot> m_snapshot;
    std::atomic<quint64> m_served {0};
    std::atomic<quint64> m_rejected {0};
    std::atomic<quint64> m_dropped {0};
};
