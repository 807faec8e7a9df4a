// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockprober.h"

#include <QHostAddress>

class QUdpSocket;

/// A ClockProber over UDP: probes go to the clock service's address and port from an ephemeral
/// port of our own, answers are read from it (only from that address and port).
class UdpClockProber : public ClockProber
{
    Q_OBJECT
public:
    /// `host` may be empty: then whatever name the service answers with is taken.
    UdpClockProber(const QString& host, const QHostAddress& address, quint16 port, QObject* parent = nullptr);
    ~UdpClockProber() override;

    void start() override;

protected:
    Status send(const QByteArray& bytes) override;

private:
    void readAnswers();

    QHostAddress m_address;
    quint16 m_port;
    QUdpSocket* m_socket = nullptr;
};
