// SPDX-License-Identifier: MIT
#include "mqtt/mqttclockprober.h"

#include "mqtt/mqttclockserver.h"

#include <QRandomGenerator>

MqttClockProber::MqttClockProber(const QString& host, const MqttProfile& profile, QObject* parent)
    : ClockProber(host, parent)
    , m_profile(profile)
    , m_replyTopic(MqttClockServer::replyPrefix(host)
                   + QString::number(QRandomGenerator::global()->generate64(), 16))
{
    m_drain.setTimerType(Qt::CoarseTimer);
    m_drain.setInterval(kDrainIntervalMs);
    connect(&m_drain, &QTimer::timeout, this, &MqttClockProber::drain);
    connect(&m_connection, &MqttConnection::stateChanged, this, &MqttClockProber::onState);
}

MqttClockProber::~MqttClockProber() = default;

void MqttClockProber::start()
{
    if (!ClockProbe::isValidName(host())) {
        emit failed(
            tr("'%1' cannot name a host (1 to 64 bytes without spaces, '/', '+' or '#')").arg(host()));
        return;
    }
    m_profile.filters = {m_replyTopic};
    m_profile.brokerStatistics = false;
    m_started = false;
    m_connection.open(m_profile);
    m_drain.start();
}

void MqttClockProber::stop()
{
    ClockProber::stop();
    m_started = false;
}

void MqttClockProber::onState(MqttConnection::State state, const QString& detail)
{
    const bool connected = state == MqttConnection::State::Connected;
    // The last reason stays while it tries again ("no broker answers at ...; retrying in 2 s").
    if (connected)
        setTransportProblem(QString());
    else if (state == MqttConnection::State::Reconnecting || state == MqttConnection::State::Failed)
        setTransportProblem(detail.isEmpty() ? MqttConnection::stateText(state) : detail);
    if (connected && !m_started) {
        m_started = true;
        startProbing();
    } else if (state == MqttConnection::State::Failed) {
        emit failed(detail);
    }
}

Status MqttClockProber::send(const QByteArray& bytes)
{
    QString why;
    if (m_connection.publish(MqttClockServer::probeTopic(host()), bytes, 0, false, &why))
        return {};
    return LocatedError {why};
}

void MqttClockProber::prepare(ClockProbe& probe)
{
    probe.replyTopic = m_replyTopic;
}

void MqttClockProber::drain()
{
    for (const MqttMessage& m : m_connection.takeMessages()) {
        if (m.topic == m_replyTopic)
            received(m.payload, m.receivedNs);
        else
            countUnknown();
    }
}
