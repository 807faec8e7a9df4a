// SPDX-License-Identifier: MIT
#include "clock/clockserver.h"

#include "base/wallclock.h"

#include <cmath>
#include <QNetworkDatagram>
#include <QUdpSocket>

ClockServer::ClockServer(ClockServerOptions options, QObject* parent)
    : QObject(parent)
    , m_options(std::move(options))
    , m_offsetNs(qint64(std::llround(m_options.clockOffsetMs * 1e6)))
{ }

ClockServer::~ClockServer() = default;

Status ClockServer::listen()
{
    if (!ClockProbe::isValidName(m_options.name))
        return LocatedError {tr("'%1' cannot name a host (1 to 64 bytes without spaces, '/', '+' or '#')")
                                 .arg(m_options.name)};
    if (m_options.udpPort < 0)
        return {};
    m_udp = new QUdpSocket(this);
    if (!m_udp->bind(m_options.udpAddress, quint16(m_options.udpPort))) {
        const QString why = m_udp->errorString();
        delete m_udp;
        m_udp = nullptr;
        return LocatedError {tr("cannot listen for clock probes on UDP %1:%2: %3")
                                 .arg(m_options.udpAddress.toString())
                                 .arg(m_options.udpPort)
                                 .arg(why)};
    }
    connect(m_udp, &QUdpSocket::readyRead, this, &ClockServer::readDatagrams);
    return {};
}

quint16 ClockServer::udpPort() const
{
    return m_udp ? m_udp->localPort() : 0;
}

qint64 ClockServer::serverClockNs(qint64 wallNs) const
{
    return wallNs + m_offsetNs;
}

std::optional<ClockProbe> ClockServer::accept(const QByteArray& bytes, const QString& peer,
                                              const QString& replyPrefix)
{
    changed();
    Result<ClockProbe> probe = ClockProbe::decode(bytes);
    if (!probe.ok()) {
        ++m_counters.malformed;
        return std::nullopt;
    }
    const QString& reply = probe->replyTopic;
    const bool replyOk = replyPrefix.isEmpty()
        ? reply.isEmpty()
        : reply.startsWith(replyPrefix) && reply.size() > replyPrefix.size();
    if (probe->kind != ClockProbe::Kind::Probe || !replyOk
        || (!probe->name.isEmpty() && probe->name != m_options.name)) {
        ++m_counters.refused;
        return std::nullopt;
    }
    if (!m_budget.allow(peer.isEmpty() ? reply : peer, wallClockNs())) {
        ++m_counters.overBudget;
        return std::nullopt;
    }
    return std::move(*probe);
}

QByteArray ClockServer::answerBytes(const ClockProbe& probe, qint64 arrivedWallNs) const
{
    ClockProbe answer = probe.answer(m_options.name, serverClockNs(arrivedWallNs), 0, m_sync);
    // t3 last, into the encoded bytes: what follows is the send itself.
    answer.t3 = std::max(answer.t2, serverClockNs(wallClockNs()));
    return answer.encode();
}

void ClockServer::countAnswered(bool sent)
{
    changed();
    if (sent)
        ++m_counters.answered;
    else
        ++m_counters.sendFailed;
}

void ClockServer::changed()
{
    if (m_changePosted)
        return;
    m_changePosted = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_changePosted = false;
            emit countersChanged();
        },
        Qt::QueuedConnection);
}

void ClockServer::readDatagrams()
{
    for (int i = 0; i < kMaxDatagramsPerTurn && m_udp->hasPendingDatagrams(); ++i) {
        // One byte more than a probe: a longer datagram is cut there, and refused for its size.
        const QNetworkDatagram datagram = m_udp->receiveDatagram(ClockProbe::kSize + 1);
        const qint64 arrived = wallClockNs();
        if (!datagram.isValid())
            continue;
        // The budget charges the address, whatever port a flood comes from.
        const std::optional<ClockProbe> probe
            = accept(datagram.data(), datagram.senderAddress().toString(), QString());
        if (!probe)
            continue;
        const QByteArray answer = answerBytes(*probe, arrived);
        const qint64 written
            = m_udp->writeDatagram(answer, datagram.senderAddress(), quint16(datagram.senderPort()));
        countAnswered(written == answer.size());
    }
    if (m_udp->hasPendingDatagrams())
        QMetaObject::invokeMethod(this, &ClockServer::readDatagrams, Qt::QueuedConnection);
}
