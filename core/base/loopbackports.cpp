// SPDX-License-Identifier: MIT
#include "loopbackports.h"

#include <QDeadlineTimer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QThread>
#include <QUdpSocket>

namespace LoopbackPorts {

quint16 freePort()
{
    QTcpServer server;
    return server.listen(QHostAddress::LocalHost, 0) ? server.serverPort() : 0;
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
