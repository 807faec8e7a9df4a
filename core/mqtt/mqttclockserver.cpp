// SPDX-License-Identifier: MIT
#include "mqtt/mqttclockserver.h"

#include "clock/clockserver.h"

using namespace Qt::StringLiterals;

QString MqttClockServer::probeTopic(const QString& name)
{
    return u"bridgescope/clock/"_s + name + u"/probe"_s;
}

QString MqttClockServer::replyPrefix(const QString& name)
{
    return u"bridgescope/clock/"_s + name + u"/reply/"_s;
}

MqttClockServer::MqttClockServer(ClockServer* server, QObject* parent)
    : QObject(parent)
    , m_server(server)
{
    m_drain.setTimerType(Qt::CoarseTimer);
    m_drain.setInterval(kDrainIntervalMs);
    connect(&m_drain, &QTimer::timeout, this, &MqttClockServer::drain);
    connect(&m_connection, &MqttConnection::stateChanged, this, &MqttClockServer::stateChanged);
}

MqttClockServer::~MqttClockServer() = default;

void MqttClockServer::open(const MqttProfile& profile)
{
    MqttProfile p = profile;
    p.filters = {probeTopic(m_server->options().name)};
    p.brokerStatistics = false;
    m_connection.open(p);
    m_drain.start();
}

void MqttClockServer::drain()
{
    const QString prefix = replyPrefix(m_server->options().name);
    for (const MqttMessage& m : m_connection.takeMessages()) {
        // Charged to its reply topic: a prober's own, under the prefix.
        const std::optional<ClockProbe> probe = m_server->accept(m.payload, QString(), prefix);
        if (!probe)
            continue;
        const QByteArray answer = m_server->answerBytes(*probe, m.receivedNs);
        m_server->countAnswered(m_connection.publish(probe->replyTopic, answer));
    }
}
