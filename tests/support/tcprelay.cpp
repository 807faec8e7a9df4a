// SPDX-License-Identifier: MIT
#include "tcprelay.h"

#include <atomic>
#include <QHostAddress>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>

/// The listening socket and its connection pairs; every call runs on the relay's thread.
class TcpRelay::Forwarder : public QObject
{
public:
    quint16 target = 0;
    std::atomic<int> accepted {0};

    bool listen(quint16 port)
    {
        m_server = std::make_unique<QTcpServer>();
        QObject::connect(m_server.get(), &QTcpServer::newConnection, this, [this] { acceptAll(); });
        return m_server->listen(QHostAddress::LocalHost, port);
    }
    quint16 port() const { return m_server ? m_server->serverPort() : 0; }

    void cut()
    {
        m_server.reset(); // refuses new connections
        const QList<QTcpSocket*> sockets = findChildren<QTcpSocket*>(Qt::FindDirectChildrenOnly);
        for (QTcpSocket* socket : sockets) {
            socket->disconnect(this);
            socket->abort(); // a reset, as a link that drops
        }
        qDeleteAll(sockets);
    }

private:
    void acceptAll()
    {
        while (QTcpSocket* in = m_server->nextPendingConnection()) {
            ++accepted;
            in->setParent(this);
            auto* out = new QTcpSocket(this);
            pipe(in, out);
            pipe(out, in);
            out->connectToHost(QHostAddress::LocalHost, target);
        }
    }

    /// Bytes from `from` go to `to` (once `to` is connected); either side closing closes both.
    void pipe(QTcpSocket* from, QTcpSocket* to)
    {
        const QPointer<QTcpSocket> src(from);
        const QPointer<QTcpSocket> dest(to);
        const auto forward = [src, dest] {
            if (src && dest && dest->state() == QAbstractSocket::ConnectedState && src->bytesAvailable() > 0)
                dest->write(src->readAll());
        };
        QObject::connect(from, &QTcpSocket::readyRead, this, forward);
        QObject::connect(to, &QTcpSocket::connected, this, forward);
        QObject::connect(from, &QTcpSocket::disconnected, this, [from, dest] {
            if (dest)
                dest->disconnectFromHost();
            from->deleteLater();
        });
        QObject::connect(from, &QTcpSocket::errorOccurred, this, [from, dest] {
            if (dest)
                dest->abort();
            from->deleteLater();
        });
    }

    std::unique_ptr<QTcpServer> m_server;
};

TcpRelay::TcpRelay() = default;

TcpRelay::~TcpRelay()
{
    if (!m_thread)
        return;
    QMetaObject::invokeMethod(
        m_forwarder,
        [this] {
            m_forwarder->cut();
            delete m_forwarder;
        },
        Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
}

bool TcpRelay::start(quint16 targetPort)
{
    m_thread = std::make_unique<QThread>();
    m_thread->start();
    m_forwarder = new Forwarder;
    m_forwarder->target = targetPort;
    m_forwarder->moveToThread(m_thread.get());
    bool ok = false;
    QMetaObject::invokeMethod(
        m_forwarder,
        [&] {
            ok = m_forwarder->listen(0);
            m_port = m_forwarder->port();
        },
        Qt::BlockingQueuedConnection);
    return ok;
}

void TcpRelay::cut()
{
    QMetaObject::invokeMethod(
        m_forwarder, [this] { m_forwarder->cut(); }, Qt::BlockingQueuedConnection);
}

bool TcpRelay::restore()
{
    bool ok = false;
    QMetaObject::invokeMethod(
        m_forwarder, [&] { ok = m_forwarder->listen(m_port); }, Qt::BlockingQueuedConnection);
    return ok;
}

int TcpRelay::connections() const
{
    return m_forwarder->accepted.load();
}
