// SPDX-License-Identifier: MIT
#include "metricsserver.h"

#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QTimer>

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
} // namespace

bool MetricsServer::parseHostPort(const QString& hostPort, QHostAddress* address, quint16* port,
                                  QString* error)
{
    const qsizetype colon = hostPort.lastIndexOf(u':');
    const auto fail = [&] {
        if (error)
            *error = tr("'%1' is not HOST:PORT (for example 127.0.0.1:9464, [::1]:9464, or :9464 for every "
                        "interface)")
                         .arg(hostPort);
        return false;
    };
    if (colon < 0)
        return fail();
    QString host = hostPort.left(colon);
    bool ok = false;
    const uint p = hostPort.mid(colon + 1).toUInt(&ok);
    if (!ok || p > 65535)
        return fail();
    if (host.startsWith(u'[') && host.endsWith(u']'))
        host = host.mid(1, host.size() - 2);
    QHostAddress a;
    if (host.isEmpty() || host == u"*"_s)
        a = QHostAddress::Any;
    else if (host.compare(u"localhost"_s, Qt::CaseInsensitive) == 0)
        a = QHostAddress::LocalHost;
    else if (!a.setAddress(host))
        return fail();
    *address = a;
    *port = quint16(p);
    return true;
}

std::unique_ptr<MetricsServer> MetricsServer::listen(const QString& hostPort, QString* error)
{
    QHostAddress address;
    quint16 port = 0;
    if (!parseHostPort(hostPort, &address, &port, error))
        return nullptr;
    std::unique_ptr<MetricsServer> s(new MetricsServer);
    s->m_thread = std::make_unique<QThread>();
    s->m_thread->setObjectName(u"metrics http"_s);
    s->m_server = new QTcpServer;
    s->m_server->setMaxPendingConnections(kMaxClients);
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
    if (!why.isEmpty()) {
        if (error)
            *error = tr("cannot serve metrics on %1: %2").arg(hostPort, why);
        return nullptr; // the destructor stops the thread
    }
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
        if (m_clients >= kMaxClients) {
            // Full: the client that has waited longest without sending a request makes room, so
            // idle connections cannot lock Prometheus out; if all are being answered, the new one goes.
            ++m_rejected;
            QTcpSocket* idle = nullptr;
            while (!m_waiting.isEmpty() && !idle) {
                QPointer<QTcpSocket> oldest = m_waiting.takeFirst();
                if (oldest && !oldest->property("answered").toBool())
                    idle = oldest;
            }
            QTcpSocket* drop = idle ? idle : socket;
            drop->abort();
            drop->deleteLater();
            if (!idle)
                continue;
        }
        ++m_clients;
        QObject::connect(socket, &QObject::destroyed, m_server, [this] { --m_clients; });
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
        m_waiting.removeIf(
            [](const QPointer<QTcpSocket>& w) { return !w || w->property("answered").toBool(); });
        m_waiting.append(socket);
        read(socket); // what came with the connection
    }
}

void MetricsServer::read(QTcpSocket* socket)
{
    if (socket->property("answered").toBool())
        return; // one request per connection; the rest is ignored
    const QByteArray head = socket->peek(kMaxRequestBytes + 1);
    const qsizetype end = head.indexOf("\r\n\r\n");
    if (end < 0) {
        if (head.size() > kMaxRequestBytes)
            answer(socket, 431, "text/plain; charset=utf-8", "request head too large\n", false);
        return; // more to come
    }
    const QList<QByteArray> lines = head.left(end).split('\n');
    const QList<QByteArray> request = lines.front().trimmed().split(' ');
    if (request.size() != 3 || !request[2].startsWith("HTTP/1.")) {
        answer(socket, 400, "text/plain; charset=utf-8", "not an HTTP/1 request\n", false);
        return;
    }
    const QByteArray& method = request[0];
    const bool isHead = method == "HEAD";
    if (method != "GET" && !isHead) {
        answer(socket, 405, "text/plain; charset=utf-8", "only GET and HEAD\n", false);
        return;
    }
    QByteArray path = request[1];
    if (const qsizetype q = path.indexOf('?'); q >= 0)
        path.truncate(q);
    if (path == "/") {
        answer(socket, 200, "text/html; charset=utf-8",
               "<html><head><title>Bridgescope</title></head><body><p>Bridgescope watch: the links' figures "
               "are at <a href=\"/metrics\">/metrics</a>.</p></body></html>\n",
               isHead);
        return;
    }
    if (path != "/metrics") {
        answer(socket, 404, "text/plain; charset=utf-8", "not found: the metrics are at /metrics\n", isHead);
        return;
    }
    QByteArray accept;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QByteArray line = lines[i].trimmed();
        if (line.size() > 7 && qstrnicmp(line.constData(), "accept:", 7) == 0)
            accept = line.mid(7).trimmed();
    }
    std::shared_ptr<const MetricsSnapshot> snapshot;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        snapshot = m_snapshot;
    }
    const MetricsFormat format = MetricsExposition::negotiate(accept);
    answer(socket, 200, MetricsExposition::contentType(format),
           MetricsExposition::write(snapshot ? *snapshot : MetricsSnapshot {}, format), isHead);
    ++m_served;
}

void MetricsServer::answer(QTcpSocket* socket, int status, const QByteArray& type, const QByteArray& body,
                           bool head)
{
    if (status != 200)
        ++m_rejected;
    socket->setProperty("answered", true);
    QByteArray out = "HTTP/1.1 " + QByteArray::number(status) + ' ' + reason(status) + "\r\nContent-Type: "
        + type + "\r\nContent-Length: " + QByteArray::number(body.size()) + "\r\nConnection: close\r\n\r\n";
    if (!head)
        out += body;
    socket->write(out);
    socket->disconnectFromHost(); // once written
    QTimer::singleShot(kAnswerLifetimeMs, socket, [socket] { socket->abort(); });
}
