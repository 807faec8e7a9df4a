// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockprober.h"
#include "mqtt/mqttconnection.h"
#include "mqtt/mqttprofile.h"

#include <QTimer>

/// A ClockProber over MQTT: probes go to `bridgescope/clock/<host>/probe` with a reply topic of
/// its own under `bridgescope/clock/<host>/reply/`; t4 is when Paho handed the answer over.
/// Probing begins once the broker accepted the connection.
class MqttClockProber : public ClockProber
{
    Q_OBJECT
public:
    /// How often the answers are taken from the connection's buffer. Their t4 is stamped by Paho's
    /// thread on arrival, so this costs no accuracy; the window runs a prober per host on its GUI
    /// thread, where 100 wake-ups a second each showed in every page's CPU (bench_pages).
    static constexpr int kDrainIntervalMs = 100;

    MqttClockProber(const QString& host, const MqttProfile& profile, QObject* parent = nullptr);
    ~MqttClockProber() override;

    void start() override;
    void stop() override;
    const QString& replyTopic() const { return m_replyTopic; }
    const MqttConnection& connection() const { return m_connection; }

protected:
    Status send(const QByteArray& bytes) override;
    void prepare(ClockProbe& probe) override;

private:
    void onState(MqttConnection::State state, const QString& detail);
    void drain();

    MqttProfile m_profile;
    QString m_replyTopic;
    MqttConnection m_connection;
    QTimer m_drain;
    bool m_started = false;
};
