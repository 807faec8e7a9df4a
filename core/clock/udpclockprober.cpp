// SPDX-License-Identifier: MIT
#include "clock/udpclockprober.h"

#include "base/wallclock.h"

#include <QNetworkDatagram>
#include <QUdpSocket>

UdpClockProber::UdpClockProber(const QString& host, const QHostAddress& address, quint16 port,
                               QObject* parent)
    : ClockProber(host, parent)
    , m_address(address)
    , m_port(port)
{ }

UdpClockProber::~UdpClockProber() = default;

void UdpClockProber::start()
{
    if (!m_socket) {
        m_socket = new QUdpSocket(this);
        const bool v6 = m_address.protocol() == QAbstractSocket::IPv6Protocol;
        if (!m_socket->bind(v6 ? QHostAddress::AnyIPv6 : QHostAddress::AnyIPv4, 0)) {
            emit failed(tr("cannot open a UDP socket: %1").arg(m_socket->errorString()));
            return;
        }
        connect(m_socket, &QUdpSocket::readyRead, this, &UdpClockProber::readAnswers);
    }
    startProbing();
}

Status UdpClockProber::send(const QByteArray& bytes)
{
    if (m_socket->writeDatagram(bytes, m_address, m_port) == bytes.size())
        return {};
    return LocatedError {m_socket->errorString()};
}

void UdpClockProber::readAnswers()
{
    // Bounded per turn like the service; the rest waits for the next turn.
    for (int i = 0; i < ClockProberOptions::kMaxPending && m_socket->hasPendingDatagrams(); ++i) {
        const QNetworkDatagram datagram = m_socket->receiveDatagram(ClockProbe::kSize + 1);
        const qint64 t4 = wallClockNs();
        if (!datagram.isValid())
            continue;
        if (datagram.senderAddress().isEqual(m_address, QHostAddress::TolerantConversion)
            && datagram.senderPort() == m_port)
            received(datagram.data(), t4);
        else
            countUnknown();
    }
    if (m_socket->hasPendingDatagrams())
        QMetaObject::invokeMethod(this, &UdpClockProber::readAnswers, Qt::QueuedConnection);
}
