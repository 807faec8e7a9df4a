// SPDX-License-Identifier: MIT
#include "mqttlink.h"

#include "text/exactutf8.h"
#include "base/wallclock.h"
#include "mqtt/pahooptions.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mqtt/async_client.h>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

namespace {
/// A message send() keeps until Paho has room for it.
struct Outgoing
{
    QString topic;
    QByteArray payload;
    int qos = 0;
    bool retained = false;
};

/// The bytes of the messages handed to Paho and not yet done with (written, acknowledged, failed),
/// by the id each travels with as its user context. A reconnect forgets them: Paho frees what it
/// had not sent without telling, and a late answer then finds nothing to subtract.
class Handed : public mqtt::iaction_listener
{
public:
    /// Registers a message of `bytes` about to be handed; its id.
    std::uintptr_t add(qint64 bytes)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const std::uintptr_t id = ++m_lastId;
        m_bytesById.emplace(id, bytes);
        m_bytes += bytes;
        return id;
    }
    void remove(std::uintptr_t id)
    {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            const auto it = m_bytesById.find(id);
            if (it == m_bytesById.end())
                return;
            m_bytes -= it->second;
            m_bytesById.erase(it);
        }
        if (m_wake)
            m_wake->notify_all();
    }
    void forget()
    {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_bytesById.clear();
            m_bytes = 0;
        }
        if (m_wake)
            m_wake->notify_all();
    }
    qint64 bytes() const
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_bytes;
    }
    /// Notified (without its mutex: a waiter also looks again every few ms) when bytes are done.
    void setWake(std::condition_variable* wake) { m_wake = wake; }

    void on_success(const mqtt::token& t) override { remove(std::uintptr_t(t.get_user_context())); }
    void on_failure(const mqtt::token& t) override { remove(std::uintptr_t(t.get_user_context())); }

private:
    mutable std::mutex m_mutex; ///< never held while calling Paho
    std::condition_variable* m_wake = nullptr;
    std::unordered_map<std::uintptr_t, qint64> m_bytesById;
    std::uintptr_t m_lastId = 0;
    qint64 m_bytes = 0;
};
} // namespace

struct MqttLink::Private
{
    MqttProfile profile;
    Options options;
    QString clientId;
    Handed handed; ///< before `client`: it outlives Paho's callbacks
    std::unique_ptr<mqtt::async_client> client;
    std::mutex mutex; ///< guards the handlers and subscriptions
    MessageHandler onMessage;
    std::function<void(bool)> onConnected;
    std::function<void(const QString&)> onLost;
    std::vector<std::pair<std::string, int>> subscriptions;
    int connects = 0;
    bool closing = false; ///< disconnect() has begun: no reconnect from a late callback

    // send(): the messages waiting for room in Paho, and the thread that hands them on.
    std::mutex sendMutex; ///< guards the queue and orders hand-overs; taken before Paho's locks
    std::condition_variable sendWake;
    std::deque<Outgoing> waiting;
    qint64 waitingBytes = 0;
    std::atomic<quint64> dropped {0};
    std::atomic<quint64> failedLater {0};
    std::thread sender;
    std::atomic<bool> stopSender {false};

    qint64 shareBytes() const { return options.maxQueuedBytes / 2; }
    /// Whether Paho may take `bytes` more (counted twice: its two copies); one message always.
    bool pahoHasRoom(qint64 handedBytes, qint64 bytes) const
    {
        return handedBytes <= 0 || handedBytes + 2 * bytes <= shareBytes();
    }
    Sent hand(const Outgoing& o);
    void sendLoop();

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

namespace {
bool isFull(const mqtt::exception& e)
{
    // The in-flight window (QoS 1/2) or the queue of messages not yet written is full.
    return e.get_return_code() == MQTTASYNC_MAX_MESSAGES_INFLIGHT
        || e.get_return_code() == MQTTASYNC_MAX_BUFFERED_MESSAGES;
}
} // namespace

MqttLink::Sent MqttLink::Private::hand(const Outgoing& o)
{
    if (!client)
        return Sent::Failed;
    const std::uintptr_t id = handed.add(2 * qint64(o.payload.size()));
    try {
        client->publish(o.topic.toStdString(), o.payload.constData(), std::size_t(o.payload.size()), o.qos,
                        o.retained, reinterpret_cast<void*>(id), handed);
    } catch (const mqtt::exception& e) {
        handed.remove(id);
        return isFull(e) ? Sent::Full : Sent::Failed;
    }
    return Sent::Ok;
}

void MqttLink::Private::sendLoop()
{
    std::unique_lock<std::mutex> lock(sendMutex);
    const auto ready
        = [this] { return !waiting.empty() && pahoHasRoom(handed.bytes(), waiting.front().payload.size()); };
    while (!stopSender) {
        // Paho's answers notify without our lock: a missed one costs at most these 10 ms.
        sendWake.wait_for(lock, std::chrono::milliseconds(10), [&] { return stopSender || ready(); });
        if (stopSender || !ready())
            continue;
        Outgoing o = std::move(waiting.front());
        waiting.pop_front();
        const Sent sent = hand(o);
        if (sent == Sent::Full) { // Paho's own count of messages not yet written: soon again
            waiting.push_front(std::move(o));
            sendWake.wait_for(lock, std::chrono::milliseconds(2));
            continue;
        }
        waitingBytes -= o.payload.size();
        if (sent == Sent::Failed)
            ++failedLater;
    }
}

MqttLink::MqttLink(const MqttProfile& profile, const MqttWill& will)
    : MqttLink(profile, Options {will, true, 0})
{ }

MqttLink::MqttLink(const MqttProfile& profile, const Options& options)
    : d(std::make_shared<Private>())
{
    d->profile = profile;
    d->options = options;
    d->clientId = QString::fromStdString(PahoOptions::clientId(profile));
    d->handed.setWake(&d->sendWake);
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

Status MqttLink::connect(int timeoutMs)
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
            if (reconnect)
                self->handed.forget();
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
        if (d->options.maxQueuedBytes > 0 && !d->sender.joinable()) {
            d->stopSender = false;
            d->sender = std::thread([p = d.get()] { p->sendLoop(); });
        }
        mqtt::token_ptr token = d->client->connect(builder.finalize());
        if (!token->wait_for(std::chrono::milliseconds(timeoutMs)))
            return LocatedError {tr("no answer from %1 within %2 s").arg(p.url).arg(timeoutMs / 1000.0)};
    } catch (const mqtt::exception& e) {
        return LocatedError {
            e.get_return_code() == -1
                ? tr("no broker answers at %1").arg(p.url)
                : tr("cannot connect to %1: %2")
                      .arg(p.url,
                           QString::fromStdString(e.get_message().empty() ? e.what() : e.get_message()))};
    }
    return {};
}

Status MqttLink::subscribeAndWait(const QString& filter, int qos, int timeoutMs)
{
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->subscriptions.emplace_back(filter.toStdString(), qos); // held on reconnects too
    }
    try {
        if (d->client
            && d->client->subscribe(filter.toStdString(), qos)
                   ->wait_for(std::chrono::milliseconds(timeoutMs)))
            return {};
        return LocatedError {
            tr("the broker at %1 does not confirm the subscription to %2").arg(d->profile.url, filter)};
    } catch (const mqtt::exception& e) {
        return LocatedError {tr("the broker at %1 refuses the subscription to %2: %3")
                                 .arg(d->profile.url, filter, QString::fromStdString(e.what()))};
    }
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
        if (isFull(e))
            return Sent::Full;
        if (error)
            *error = tr("cannot publish on %1: %2").arg(topic, QString::fromStdString(e.what()));
        return Sent::Failed;
    }
    return Sent::Ok;
}

bool MqttLink::send(const QString& topic, const QByteArray& payload, int qos, bool retained)
{
    if (d->options.maxQueuedBytes <= 0)
        return publish(topic, payload, qos, retained);
    std::lock_guard<std::mutex> lock(d->sendMutex);
    Outgoing o {topic, payload, qos, retained};
    if (d->waiting.empty() && d->pahoHasRoom(d->handed.bytes(), payload.size())) {
        const Sent sent = d->hand(o);
        if (sent != Sent::Full)
            return sent == Sent::Ok;
    }
    d->waitingBytes += payload.size();
    d->waiting.push_back(std::move(o));
    while (d->waitingBytes > d->shareBytes() && d->waiting.size() > 1) {
        d->waitingBytes -= d->waiting.front().payload.size();
        d->waiting.pop_front();
        ++d->dropped;
    }
    d->sendWake.notify_one();
    return true;
}

MqttLink::QueueCounts MqttLink::queueCounts() const
{
    QueueCounts c;
    c.dropped = d->dropped.load();
    c.failed = d->failedLater.load();
    std::lock_guard<std::mutex> lock(d->sendMutex);
    c.heldBytes = d->waitingBytes + d->handed.bytes();
    return c;
}

void MqttLink::disconnect()
{
    if (d->sender.joinable()) {
        {
            std::lock_guard<std::mutex> lock(d->sendMutex);
            d->stopSender = true;
        }
        d->sendWake.notify_all();
        d->sender.join();
    }
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
    std::lock_guard<std::mutex> lock(d->sendMutex); // send() hands on under it
    d->client.reset();
}

bool MqttLink::isConnected() const
{
    return d->client && d->client->is_connected();
}
