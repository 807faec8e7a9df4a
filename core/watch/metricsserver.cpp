// SPDX-License-Identifier: MIT
#include "metricsserver.h"

#include "watch/httphead.h"

#include <algorithm>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QTimer>
#include <sys/socket.h>

using namespace Qt::StringLiterals;

namespace {
constexpr int kAnswerLifetimeMs = 60'000; ///< a client that reads the answer slower than this is dropped

const char* reason(int status)
{
    switch (status) {
    case 200:
        return "OK";
    case 400:
        return "Bad Request";
    case 404:
        return "Not Found";
    case 405:
        return "Method Not Allowed";
    case 431:
        return "Request Header Fields Too Large";
    default:
        return "Error";
    }
}

bool isOpen(const QPointer<QTcpSocket>& socket)
{
    return socket && socket->state() != QAbstractSocket::UnconnectedState;
}

/// Whether the client has sent a byte: read by Qt, or still in the kernel's buffer.
bool hasSentSomething(QTcpSocket* socket)
{
    if (socket->bytesAvailable() > 0)
        return true;
    char c = 0;
    const qintptr fd = socket->socketDescriptor();
    return fd >= 0 && ::recv(int(fd), &c, 1, MSG_PEEK | MSG_DONTWAIT) > 0;
}
} // namespace

Result<MetricsServer::Endpoint> MetricsServer::parseHostPort(const QString& hostPort)
{
    const qsizetype colon = hostPort.lastIndexOf(u':');
    const LocatedError notHostPort {
        tr("'%1' is not HOST:PORT (for example 127.0.0.1:9464, [::1]:9464, or :9464 for every interface)")
            .arg(hostPort)};
    if (colon < 0)
        return notHostPort;
    QString host = hostPort.left(colon);
    const QString portText = hostPort.mid(colon + 1);
    // Digits only: toUInt() takes " 80" and "+80" as well.
    const bool digits = !portText.isEmpty() && portText.size() <= 5
        && std::all_of(portText.cbegin(), portText.cend(), [](QChar c) { return c >= u'0' && c <= u'9'; });
    bool ok = false;
    const uint p = portText.toUInt(&ok);
    if (!digits || !ok || p > 65535)
        return notHostPort;
    if (host.startsWith(u'[') && host.endsWith(u']'))
        host = host.mid(1, host.size() - 2);
    QHostAddress a;
    if (host.isEmpty() || host == u"*"_s)
        a = QHostAddress::Any;
    else if (host.compare(u"localhost"_s, Qt::CaseInsensitive) == 0)
        a = QHostAddress::LocalHost;
    else if (!a.setAddress(host))
        return notHostPort;
    return Endpoint {a, quint16(p)};
}

Result<std::unique_ptr<MetricsServer>> MetricsServer::listen(const QString& hostPort)
{
    const Result<Endpoint> endpoint = parseHostPort(hostPort);
    if (!endpoint)
        return endpoint.error();
    const QHostAddress address = endpoint->address;
    const quint16 port = endpoint->port;
    std::unique_ptr<MetricsServer> s(new MetricsServer);
    s->m_thread = std::make_unique<QThread>();
    s->m_thread->setObjectName(u"metrics http"_s);
    s->m_server = new QTcpServer;
    s->m_server->setMaxPendingConnections(kMaxClients);
    s->m_server->setListenBacklogSize(1024); // a burst waits in the kernel, not refused there
    s->m_server->moveToThread(s->m_thread.get());
    s->m_thread->start();
    QString why;
    MetricsServer* self = s.get();
    QMetaObject::invokeMethod(
        s->m_server,
        [self, address, port, &why] {
            if (!self->m_server->listen(address, port)) {
                why = self->m_server->errorString();
                return;
            }
            self->m_port = self->m_server->serverPort();
            QObject::connect(self->m_server, &QTcpServer::newConnection, self->m_server,
                             [self] { self->accept(); });
        },
        Qt::BlockingQueuedConnection);
    if (!why.isEmpty()) // the destructor stops the thread
        return LocatedError {tr("cannot serve metrics on %1: %2").arg(hostPort, why)};
    return s;
}

MetricsServer::~MetricsServer()
{
    if (!m_thread)
        return;
    if (m_server) {
        QTcpServer* server = m_server;
        QMetaObject::invokeMethod(
            server, [server] { delete server; }, Qt::BlockingQueuedConnection); // and its sockets
    }
    m_thread->quit();
    m_thread->wait();
}

void MetricsServer::publish(std::shared_ptr<const MetricsSnapshot> snapshot)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_snapshot = std::move(snapshot);
}

void MetricsServer::accept()
{
    while (QTcpSocket* socket = m_server->nextPendingConnection()) {
        m_clients.removeIf([](const QPointer<QTcpSocket>& c) { return !isOpen(c); });
        if (m_clients.size() >= kMaxClients && !makeRoom()) {
            ++m_rejected;
            socket->abort();
            socket->deleteLater();
            continue;
        }
        QObject::connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        QObject::connect(socket, &QTcpSocket::errorOccurred, socket, &QObject::deleteLater);
        // Peeked, never copied: the socket buffers no more than one request head may be long.
        socket->setReadBufferSize(kMaxRequestBytes + 1);
        QObject::connect(socket, &QTcpSocket::readyRead, socket, [this, socket] { read(socket); });
        QTimer::singleShot(kRequestTimeoutMs, socket, [this, socket] {
            if (!socket->property("answered").toBool()) {
                ++m_rejected;
                socket->abort();
                socket->deleteLater();
            }
        });
        m_clients.append(socket);
        read(socket); // what came with the connection
    }
}

bool MetricsServer::makeRoom()
{
    // Oldest first: one that has sent nothing (0), else one whose head is incomplete (1), else one
    // that has its answer (2). A scrape is answered as soon as its head is read, and a head that
    // came is read before the client goes (the kernel is asked, not only what Qt has read).
    QTcpSocket* victim = nullptr;
    int rank = 3;
    for (const QPointer<QTcpSocket>& c : std::as_const(m_clients)) {
        if (!isOpen(c))
            continue;
        const int r = c->property("answered").toBool() ? 2 : hasSentSomething(c) ? 1 : 0;
        if (r < rank) {
            rank = r;
            victim = c;
            if (r == 0)
                break;
        }
    }
    if (!victim)
        return false;
    if (rank < 2)
        ++m_rejected;
    drop(victim);
    return true;
}

void MetricsServer::drop(QTcpSocket* socket)
{
    ++m_dropped;
    socket->abort();
    socket->deleteLater();
}

void MetricsServer::read(QTcpSocket* socket)
{
    if (socket->property("answered").toBool())
        return; // one request per connection; the rest is ignored
    HttpHead::Request request;
    switch (HttpHead::parse(socket->peek(kMaxRequestBytes + 1), kMaxRequestBytes, &request)) {
    case HttpHead::Status::Incomplete:
        return; // more to come
    case HttpHead::Status::TooLarge:
        answer(socket, 431, "text/plain; charset=utf-8", "request head too large\n", false);
        return;
    case HttpHead::Status::Malformed:
        answer(socket, 400, "text/plain; charset=utf-8", "not an HTTP/1 request\n", false);
        return;
    case HttpHead::Status::Complete:
        break;
    }
    const bool isHead = request.method == "HEAD";
    if (request.method != "GET" && !isHead) {
        answer(socket, 405, "text/plain; charset=utf-8", "only GET and HEAD\n", false);
        return;
    }
    if (request.path == "/") {
        answer(socket, 200, "text/html; charset=utf-8",
               "<html><head><title>Bridgescope</title></head><body><p>Bridgescope watch: the links' figures "
               "are at <a href=\"/metrics\">/metrics</a>.</p></body></html>\n",
               isHead);
        return;
    }
    if (request.path != "/metrics") {
        answer(socket, 404, "text/plain; charset=utf-8", "not found: the metrics are at /metrics\n", isHead);
        return;
    }
    const MetricsFormat format = MetricsExposition::negotiate(request.accept);
    answer(socket, 200, MetricsExposition::contentType(format), exposition(format), isHead);
    ++m_served;
}

QByteArray MetricsServer::exposition(MetricsFormat format)
{
    std::shared_ptr<const MetricsSnapshot> snapshot;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        snapshot = m_snapshot;
    }
    // An answer holds the snapshot and the server's own count of clients it dropped: either new
    // makes it anew (the watch publishes only when its figures move).
    const quint64 dropped = m_dropped.load();
    if (snapshot != m_answered || !m_answered || dropped != m_answeredDropped) {
        m_answered = snapshot;
        m_answeredDropped = dropped;
        for (QByteArray& a : m_answers)
            a.clear();
    }
    QByteArray& a = m_answers[format == MetricsFormat::OpenMetrics ? 1 : 0];
    if (a.isEmpty())
        a = MetricsExposition::write(snapshot ? *snapshot : MetricsSnapshot {}, format, dropped);
    return a;
}

void MetricsServer::keepWithinBudget(qsizetype more)
{
    qsizetype queued = 0;
    for (const QPointer<QTcpSocket>& c : std::as_const(m_clients))
        if (isOpen(c))
            queued += c->bytesToWrite();
    for (const QPointer<QTcpSocket>& c : std::as_const(m_clients)) {
        if (queued + more <= kMaxQueuedBytes)
            return;
        if (isOpen(c) && c->bytesToWrite() > 0) {
            queued -= c->bytesToWrite();
            drop(c);
        }
    }
}

void MetricsServer::answer(QTcpSocket* socket, int status, const QByteArray& type, const QByteArray& body,
                           bool head)
{
    if (status != 200)
        ++m_rejected;
    socket->setProperty("answered", true);
    const QByteArray top = "HTTP/1.1 " + QByteArray::number(status) + ' ' + reason(status)
        + "\r\nContent-Type: " + type + "\r\nContent-Length: " + QByteArray::number(body.size())
        + "\r\nConnection: close\r\n\r\n";
    keepWithinBudget(top.size() + (head ? 0 : body.size()));
    socket->write(top);
    if (!head)
        socket->write(body); // shared with the other answers of this snapshot, not copied
    socket->disconnectFromHost(); // once written
    QTimer::singleShot(kAnswerLifetimeMs, socket, [socket] { socket->abort(); });
}
