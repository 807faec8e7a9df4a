// SPDX-License-Identifier: MIT
#pragma once

#include "base/eventbuffer.h"
#include "mqtt/mqttprofile.h"

#include <memory>
#include <QByteArray>
#include <QObject>
#include <QString>
#include <vector>

/// One message as it came from the broker.
struct MqttMessage
{
    QString topic;
    QByteArray payload;
    qint64 receivedNs = 0; ///< wall clock, ns since the epoch
    quint8 qos = 0;
    bool retained = false;
};

/// A connection to a broker (the only code that talks to Paho).
///
/// Paho's threads only append messages to a bounded buffer and count them; the owner takes them
/// in batches on its own thread (the GUI drain timer). Connecting never blocks: states arrive as
/// the stateChanged signal. After a lost connection it reconnects by itself with backoff, and its
/// counters go on.
class MqttConnection : public QObject
{
    Q_OBJECT
public:
    enum class State { Disconnected, Connecting, Connected, Reconnecting, Failed };
    Q_ENUM(State)

    /// The Paho MQTT C++ library's version ("1.2.0"), for About.
    static QString pahoVersion();

    explicit MqttConnection(QObject* parent = nullptr);
    ~MqttConnection() override;

    void open(const MqttProfile& profile);
    void close();
    State state() const { return m_state; }
    QString stateDetail() const { return m_detail; }
    const MqttProfile& profile() const { return m_profile; }
    static QString stateText(State state);

    /// Messages received since the last call, oldest first.
    std::vector<MqttMessage> takeMessages();
    quint64 received() const;
    quint64 receivedBytes() const;
    quint64 dropped() const; ///< lost because the buffer was full
    int connects() const; ///< successful connects, reconnects included

    /// Publications Paho queues before it refuses more.
    static constexpr int kMaxQueuedPublications = 65535;
    /// Publishes without waiting (Paho's thread sends it); false, and why, when not connected or
    /// when Paho's queue is full.
    bool publish(const QString& topic, const QByteArray& payload, int qos = 0, bool retained = false,
                 QString* error = nullptr);

signals:
    void stateChanged(MqttConnection::State state, const QString& detail);

private:
    // Called on this object's thread by what Paho's threads post.
    Q_INVOKABLE void onConnected();
    Q_INVOKABLE void onConnectionLost(const QString& why);
    Q_INVOKABLE void onConnectFailed(const QString& why, bool authFailure);

    struct Private;
    void setState(State state, const QString& detail);
    void startClient();
    void scheduleRetry(const QString& why);
    void diagnoseTls(const QString& fallback);

    std::unique_ptr<Private> d;
    MqttProfile m_profile;
    State m_state = State::Disconnected;
    QString m_detail;
};
