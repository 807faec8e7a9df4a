// SPDX-License-Identifier: MIT
#include "mqttlink.h"

#include "pahooptions.h"

#include <chrono>
#include <mqtt/async_client.h>
#include <mutex>
#include <vector>

namespace {
qint64 nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}
} // namespace

struct MqttLink::Private
{
    MqttProfile profile;
    MqttWill will;
    std::unique_ptr<mqtt::async_client> client;
    std::mutex mutex; ///< guards the handlers and subscriptions
    MessageHandler onMessage;
    std::function<void(bool)> onConnected;
    std::function<void(const QString&)> onLost;
    std::vector<std::pair<std::string, int>> subscriptions;
    int connects = 0;

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
    : d(std::make_shared<Private>())
{
    d->profile = profile;
    d->will = will;
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
        d->client = std::make_unique<mqtt::async_client>(p.pahoUri().toStdString(), PahoOptions::clientId(p),
                                                         createOpts, nullptr);
        std::weak_ptr<Private> weak = d;
        d->client->set_message_callback([weak](mqtt::const_message_ptr msg) {
            const qint64 now = nowNs();
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
            handler(QString::fromStdString(msg->get_topic()), QByteArray(data.data(), qsizetype(data.size())),
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
        d->client->set_connection_lost_handler([weak](const std::string& cause) {
            auto self = weak.lock();
            if (!self)
                return;
            std::function<void(const QString&)> handler;
            {
                std::lock_guard<std::mutex> lock(self->mutex);
                handler = self->onLost;
            }
            if (handler)
                handler(QString::fromStdString(cause));
        });
        auto builder = PahoOptions::connectOptions(p);
        if (!d->will.topic.isEmpty())
            builder.will(mqtt::message(d->will.topic.toStdString(), d->will.message.constData(),
                                       std::size_t(d->will.message.size()), d->will.qos, d->will.retained));
        mqtt::token_ptr token = d->client->connect(builder.finalize());
        if (!token->wait_for(std::chrono::milliseconds(timeoutMs))) {
            if (error)
                *error = tr("no answer from %1 within %2 s").arg(p.url).arg(timeoutMs / 1000.0);
            return false;
        }
    } catch (const mqtt::exception& e) {
        if (error)
            *error = tr("cannot connect to %1: %2")
                         .arg(p.url,
                              QString::fromStdString(e.get_message().empty() ? e.what() : e.get_message()));
        return false;
    }
    return true;
}

bool MqttLink::publish(const QString& topic, const QByteArray& payload, int qos, bool retained)
{
    if (!d->client)
        return false;
    try {
        d->client->publish(topic.toStdString(), payload.constData(), std::size_t(payload.size()), qos,
                           retained);
    } catch (const mqtt::exception&) {
        return false; // not connected (reconnecting) or too many in flight: the message is lost
    }
    return true;
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
