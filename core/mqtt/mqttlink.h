// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttprofile.h"

#include <functional>
#include <memory>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// The last will a client leaves with the broker.
struct MqttWill
{
    QString topic; ///< empty: none
    QByteArray message;
    int qos = 0;
    bool retained = false;
};

/// A broker connection for forwarding (the reference bridge): messages are handed to a callback
/// on Paho's thread the moment they arrive, and publish() may be called from any thread.
///
/// MqttConnection is the GUI's connection (buffered, drained on a timer); a bridge cannot wait
/// for a timer tick per message. Reconnects by itself; subscriptions are renewed on every
/// (re)connect, and onConnected lets the owner republish what must be retained.
class MqttLink
{
    Q_DECLARE_TR_FUNCTIONS(MqttLink)
public:
    using MessageHandler
        = std::function<void(const QString& topic, const QByteArray& payload, qint64 receivedNs)>;

    struct Options
    {
        MqttWill will;
        bool autoReconnect = true; ///< false: a lost connection stays lost (the probe reports it)
        int maxInflight = 0; ///< unacknowledged QoS 1/2 messages; 0: Paho's default
        /// The memory bound of send(), in bytes (0: send() is publish()). Paho keeps two copies of a
        /// message until it is written (QoS 0) or acknowledged: those count twice and may take a
        /// half; the messages waiting behind them the other half, the oldest dropped beyond it.
        qint64 maxQueuedBytes = 0;
    };

    /// What send() did with the messages it could not hand to Paho at once.
    struct QueueCounts
    {
        quint64 dropped = 0; ///< the oldest, at the memory bound
        quint64 failed = 0; ///< waited, then Paho refused them (disconnected)
        qint64 heldBytes = 0; ///< now: waiting, and handed to Paho (twice) and not yet done
    };

    MqttLink(const MqttProfile& profile, const MqttWill& will = {});
    MqttLink(const MqttProfile& profile, const Options& options);
    ~MqttLink();
    MqttLink(const MqttLink&) = delete;
    const QString& clientId() const;
    MqttLink& operator=(const MqttLink&) = delete;

    void setMessageHandler(MessageHandler handler);
    void setConnectedHandler(std::function<void(bool reconnect)> handler);
    void setLostHandler(std::function<void(const QString& why)> handler);
    /// Topic filters (and their QoS) to hold on every connection.
    void addSubscription(const QString& filter, int qos);

    /// Connects, waiting up to `timeoutMs` for the broker's answer.
    Status connect(int timeoutMs);
    /// Subscribes now and waits up to `timeoutMs` for the broker to confirm (also held on reconnects).
    Status subscribeAndWait(const QString& filter, int qos, int timeoutMs);
    bool publish(const QString& topic, const QByteArray& payload, int qos, bool retained);
    enum class Sent { Ok, Full, Failed };
    /// publish() that tells a full window (QoS 1/2 in flight, or messages not yet written: try
    /// again soon) from a failure.
    Sent tryPublish(const QString& topic, const char* data, qsizetype size, int qos, bool retained,
                    QString* error = nullptr);
    /// publish() within Options::maxQueuedBytes: hands the message to Paho now when Paho holds
    /// less than its share and nothing waits, else queues it behind the others (a thread of the
    /// link's own hands them on, in order), dropping the oldest waiting beyond the bound. False
    /// when it failed at once (not connected).
    bool send(const QString& topic, const QByteArray& payload, int qos, bool retained);
    QueueCounts queueCounts() const;
    /// Disconnects cleanly (the broker does not send the last will).
    void disconnect();
    bool isConnected() const;

private:
    struct Private;
    std::shared_ptr<Private> d;
};
