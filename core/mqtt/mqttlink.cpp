// SPDX-License-Identifier: MIT
#include "mqttlink.h"

#include "base/exactutf8.h"
#include "base/wallclock.h"
#include "mqtt/pahooptions.h"

#include <chrono>
#include <mqtt/async_client.h>
#include <mutex>
#include <vector>

struct MqttLink::Private
{
    MqttProfile profile;
    Options options;
    QString clientId;
    std::unique_ptr<mqtt::async_client> client;
    std::mutex mutex; ///< guards the handlers and subscriptions
    MessageHandler onMessage;
    std::function<void(bool)> onConnected;
    std::function<void(const QString&)> onLost;
    std::vector<std::pair<std::string, int>> subscriptions;
    int connects = 0;
    bool closing = false; ///< disconnect() has begun: no reconnect from a late callback

    void subscribeAll()
    {
        std::vector<std::pair<std::string, int>> subs;
        {
            std::lock_guard<std::mutex> lock(mutex);
            subs = subscriptions;
        }
        if (subs.empty())
            return;
        std::vector<std::string> filters;
        std::vector<int> qos;
        for (const auto& [filter, q] : subs) {
            filters.push_back(filter);
            qos.push_back(q);
        }
        auto topics = mqtt::string_collection::create(filters);
        try {
            client->subscribe(topics, qos);
        } catch (const mqtt::exception&) { }
    }
};

MqttLink::MqttLink(const MqttProfile& profile, const MqttWill& will)
    : MqttLink(profile, Options {will, true, 0})
{ }

MqttLink::MqttLink(const MqttProfile& profile, const Options& options)
    : d(std::make_shared<Private>())
{
    d->profile = profile;
    d->options = options;
    d->clientId = QString::fromStdString(PahoOptions::clientId(profile));
}

const QString& MqttLink::clientId() const
{
    return d->clientId;
}

MqttLink::~MqttLink()
{
    disconnect();
}

void MqttLink::setMessageHandler(MessageHandler handler)
{
    std::lock_guard<std::mutex> lock(d->mutex);
    d->onMessage = std::move(handler);
}

void MqttLink::setConnectedHandler(std::function<void(bool)> handler)
{
    std::lock_guard<std::mutex> lock(d->mutex);
    d->onConnected = std::move(handler);
}

void MqttLink::setLostHandler(std::function<void(const QString&)> handler)
{
    std::lock_guard<std::mutex> lock(d->mutex);
    d->onLost = std::move(handler);
}

void MqttLink::addSubscription(const QString& filter, int qos)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->subscriptions.emplace_back(filter.toStdString(), qos);
    }
    if (isConnected()) {
        try {
            d->client->subscribe(filter.toStdString(), qos);
        } catch (const mqtt::exception&) { }
    }
}

bool MqttLink::connect(int timeoutMs, QString* error)
{
    const MqttProfile& p = d->profile;
    try {
        mqtt::create_options createOpts(p.mqttVersion == 5 ? MQTTVERSION_5 : MQTTVERSION_3_1_1);
        d->client = std::make_unique<mqtt::async_client>(p.pahoUri().toStdString(), d->clientId.toStdString(),
                                                         createOpts, nullptr);
        std::weak_ptr<Private> weak = d;
        d->client->set_message_callback([weak](mqtt::const_message_ptr msg) {
            const qint64 now = wallClockNs();
            auto self = weak.lock();
            if (!self)
                return;
            MessageHandler handler;
            {
                std::lock_guard<std::mutex> lock(self->mutex);
                handler = self->onMessage;
            }
            if (!handler)
                return;
            const mqtt::binary_ref& data = msg->get_payload_ref();
            handler(exactUtf8(msg->get_topic()), QByteArray(data.data(), qsizetype(data.size())),
                    now);
        });
        d->client->set_connected_handler([weak](const std::string&) {
            auto self = weak.lock();
            if (!self)
                return;
            self->subscribeAll(); // a clean session forgets them
            std::function<void(bool)> handler;
            bool reconnect = false;
            {
                std::lock_guard<std::mutex> lock(self->mutex);
                handler = self->onConnected;
                reconnect = self->connects++ > 0;
            }
            if (handler)
                handler(reconnect);
        });
        mqtt::async_client* client = d->client.get(); // outlives its callbacks
        d->client->set_connection_lost_handler([weak, client](const std::string& cause) {
            auto self = weak.lock();
            if (!self)
                return;
            std::function<void(const QString&)> handler;
            bool retry = false;
            {
                std::lock_guard<std::mutex> lock(self->mutex);
                handler = self->onLost;
                retry = self->options.autoReconnect && !self->closing;
            }
            if (retry)
                PahoOptions::reconnectNow(*client);
            if (handler)
                handler(QString::fromStdString(cause));
        });
        auto builder = PahoOptions::connectOptions(p);
        if (!d->options.autoReconnect)
            builder.automatic_reconnect(false);
        if (d->options.maxInflight > 0)
            builder.max_inflight(d->options.maxInflight);
        const MqttWill& will = d->options.will;
        if (!will.topic.isEmpty())
            builder.will(mqtt::message(will.topic.toStdString(), will.message.constData(),
                                       std::size_t(will.message.size()), will.qos, will.retained));
        mqtt::token_ptr token = d->client->connect(builder.finalize());
        if (!token->wait_for(std::chrono::milliseconds(timeoutMs))) {
            if (error)
                *error = tr("no answer from %1 within %2 s").arg(p.url).arg(timeoutMs / 1000.0);
            return false;
        }
    } catch (const mqtt::exception& e) {
        if (error)
            *error = e.get_return_code() == -1
                ? tr("no broker answers at %1").arg(p.url)
                : tr("cannot connect to %1: %2")
                      .arg(p.url,
                           QString::fromStdString(e.get_message().empty() ? e.what() : e.get_message()));
        return false;
    }
    return true;
}

bool MqttLink::subscribeAndWait(const QString& filter, int qos, int timeoutMs, QString* error)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->subscriptions.emplace_back(filter.toStdString(), qos); // held on reconnects too
    }
    try {
        if (d->client
            && d->client->subscribe(filter.toStdString(), qos)
                   ->wait_for(std::chrono::milliseconds(timeoutMs)))
            return true;
        if (error)
            *error
                = tr("the broker at %1 does not confirm the subscription to %2").arg(d->profile.url, filter);
    } catch (const mqtt::exception& e) {
        if (error)
            *error = tr("the broker at %1 refuses the subscription to %2: %3")
                         .arg(d->profile.url, filter, QString::fromStdString(e.what()));
    }
    return false;
}

bool MqttLink::publish(const QString& topic, const QByteArray& payload, int qos, bool retained)
{
    // Not connected (reconnecting) or too many in flight: the message is lost.
    return tryPublish(topic, payload.constData(), payload.size(), qos, retained) == Sent::Ok;
}

MqttLink::Sent MqttLink::tryPublish(const QString& topic, const char* data, qsizetype size, int qos,
                                    bool retained, QString* error)
{
    if (!d->client)
        return Sent::Failed;
    try {
        d->client->publish(topic.toStdString(), data, std::size_t(size), qos, retained);
    } catch (const mqtt::exception& e) {
        // The in-flight window (QoS 1/2) or the queue of messages not yet written is full.
        if (e.get_return_code() == MQTTASYNC_MAX_MESSAGES_INFLIGHT
            || e.get_return_code() == MQTTASYNC_MAX_BUFFERED_MESSAGES)
            return Sent::Full;
        if (error)
            *error = tr("cannot publish on %1: %2").arg(topic, QString::fromStdString(e.what()));
        return Sent::Failed;
    }
    return Sent::Ok;
}

void MqttLink::disconnect()
{
    if (!d->client)
        return;
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->onMessage = nullptr;
        d->onConnected = nullptr;
        d->onLost = nullptr;
        d->closing = true;
    }
    try {
        if (d->client->is_connected())
            d->client->disconnect(std::chrono::milliseconds(500))->wait_for(std::chrono::seconds(2));
    } catch (const mqtt::exception&) { }
    d->client.reset();
}

bool MqttLink::isConnected() const
{
    return d->client && d->client->is_connected();
}
