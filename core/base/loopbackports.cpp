// SPDX-License-Identifier: MIT
#include "loopbackports.h"

#include <memory>
#include <QDeadlineTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QUdpSocket>
#include <vector>

namespace LoopbackPorts {

quint16 freePort()
{
    QTcpServer server;
    return server.listen(QHostAddress::LocalHost, 0) ? server.serverPort() : 0;
}

quint16 freePort(const QList<quint16>& taken)
{
    // Every candidate stays bound until one is found: the kernel cannot hand the same one back.
    std::vector<std::unique_ptr<QTcpServer>> held;
    for (int tries = 0; tries < 64; ++tries) {
        auto server = std::make_unique<QTcpServer>();
        if (!server->listen(QHostAddress::LocalHost, 0))
            return 0;
        const quint16 port = server->serverPort();
        if (!taken.contains(port))
            return port;
        held.push_back(std::move(server));
    }
    return 0;
}

bool isUdpFree(quint16 port)
{
    QUdpSocket socket;
    return socket.bind(QHostAddress::LocalHost, port);
}

bool waitForListener(quint16 port, int timeoutMs, const std::function<bool()>& keepWaiting)
{
    const QDeadlineTimer deadline(timeoutMs);
    for (;;) {
        QTcpSocket socket;
        socket.connectToHost(QHostAddress::LocalHost, port);
        if (socket.waitForConnected(200)) {
            socket.disconnectFromHost();
            return true;
        }
        if (deadline.hasExpired() || (keepWaiting && !keepWaiting()))
            return false;
        QThread::msleep(50);
    }
}

} // namespace LoopbackPorts
