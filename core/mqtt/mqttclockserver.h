// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"
#include "mqtt/mqttprofile.h"

#include <QObject>
#include <QString>
#include <QTimer>

class ClockServer;

/// The clock service's MQTT side: answers the probes on `bridgescope/clock/<name>/probe` on the
/// reply topic each carries, which must lie under `bridgescope/clock/<name>/reply/`. Decoding,
/// the budget (per reply topic and in total) and the counts are the ClockServer's; t2 is when
/// Paho handed the probe over, t3 just before the answer is published.
class MqttClockServer : public QObject
{
    Q_OBJECT
public:
    /// How often the received probes are taken from the connection's buffer. The wait costs no
    /// accuracy: Paho's thread stamps arrivals (t2, t4), and t3 − t2 is not part of the round trip.
    /// 50 ms: a lab host runs it for days beside its bridges, and the demo lab runs two of them.
    static constexpr int kDrainIntervalMs = 50;

    static QString probeTopic(const QString& name);
    static QString replyPrefix(const QString& name);

    explicit MqttClockServer(ClockServer* server, QObject* parent = nullptr);
    ~MqttClockServer() override;

    /// Connects to the broker of `profile` (its filters are replaced by the probe topic).
    void open(const MqttProfile& profile);
    const MqttConnection& connection() const { return m_connection; }

signals:
    void stateChanged(MqttConnection::State state, const QString& detail);

private:
    void drain();

    ClockServer* m_server;
    MqttConnection m_connection;
    QTimer m_drain;
};
