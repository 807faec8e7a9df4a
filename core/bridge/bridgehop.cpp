// SPDX-License-Identifier: MIT
#include "bridge/bridgehop.h"

#include "base/wallclock.h"
#include "mqtt/mqttlink.h"
#include "wire/ros2bridgewire.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

// The texts keep the contexts of the bridges they were written for, and so their translations.

QString BridgeCounters::text() const
{
    return u"to_mqtt=%1 to_ros=%2 failed=%3 too_large=%4 dropped_to_mqtt=%5 dropped_to_ros=%6 failed_waiting=%7"_s
        .arg(toMqtt.load())
        .arg(toRos.load())
        .arg(failed.load())
        .arg(tooLarge.load())
        .arg(droppedToMqtt.load())
        .arg(droppedToRos.load())
        .arg(failedWaiting.load());
}

BridgeHop::BridgeHop(const BridgeRoute& route, const BridgeOptions& options, BridgeCounters& counters,
                     Log log)
    : m_route(route)
    , m_options(options)
    , m_counters(counters)
    , m_log(std::move(log))
{ }

void BridgeHop::start(BridgeRosSide& ros, MqttLink& mqtt)
{
    m_ros = &ros;
    m_mqtt = &mqtt;
    if (!m_route.stampPrefix.isEmpty()) {
        m_stampIn = ros.advertiseStamps(m_route.stampPrefix + u"/in"_s);
        m_stampOut = ros.advertiseStamps(m_route.stampPrefix + u"/out"_s);
    }
    if (m_route.direction == Direction::Mqtt2Ros && !m_route.rosType.isEmpty()) {
        std::lock_guard<std::mutex> lock(m_mutex);
        advertise({QString(), m_route.rosType, QString(), false, ros.dialect()});
    }
}

qint64 BridgeHop::now() const
{
    return wallClockNs() + m_options.clockOffsetNs;
}

/// The sample a message is: its Header's stamp when it starts with one (the suite's messages all
/// do), else a hash of its bytes (the same at every component that carries it).
StampCodec::Decoded BridgeHop::sampleOf(const BridgeMessage& m)
{
    if (m.type.name != m_headerType || m.type.md5 != m_headerMd5) {
        m_headerType = m.type.name;
        m_headerMd5 = m.type.md5;
        m_headerFirst = m_ros->startsWithHeader(m.type);
    }
    if (m_headerFirst)
        if (std::optional<StampCodec::Decoded> header = m_ros->header(m.bytes))
            return *header;
    StampCodec::Decoded d;
    d.sampleNs
        = StampCodec::hashId(m.bytes) % 4'000'000'000'000'000'000LL; // fits the header's uint32 seconds
    return d;
}

void BridgeHop::publishStamp(int publisher, const StampCodec::Decoded& sample, qint64 timeNs)
{
    if (publisher < 0)
        return;
    StampCodec::Decoded d = sample;
    d.timeNs = timeNs;
    m_ros->publish(publisher, m_ros->timeStamped(d));
}

bool BridgeHop::tooLargeForJson(const QString& from, qsizetype bytes)
{
    if (bytes <= Ros2BridgeWire::kMaxJsonBytes)
        return false;
    // Counted, the first one logged: a peer can send them as fast as it likes.
    if (m_counters.tooLarge.fetch_add(1, std::memory_order_relaxed) == 0)
        m_log(QCoreApplication::translate("Ros2Bridge", "%1: %2 (further ones are counted)")
                  .arg(from, Ros2BridgeWire::tooLargeForJson(bytes)));
    return true;
}

void BridgeHop::fromRos(const BridgeMessage& message, qint64 receivedNs)
{
    StampCodec::Decoded sample;
    if (!m_route.stampPrefix.isEmpty()) {
        sample = sampleOf(message);
        publishStamp(m_stampIn, sample, receivedNs + m_options.clockOffsetNs);
    }
    qint64 outNs = now(); // the moment the message leaves: stamped before, so no receiver is earlier
    const bool ok = sendToMqtt(message, &outNs);
    (ok ? m_counters.toMqtt : m_counters.failed).fetch_add(1, std::memory_order_relaxed);
    if (ok && !m_route.stampPrefix.isEmpty())
        publishStamp(m_stampOut, sample, outNs);
}

bool BridgeHop::sendToMqtt(const BridgeMessage& m, qint64* outNs)
{
    const BridgeRoute& r = m_route;
    if (r.primitive) {
        const std::optional<QByteArray> text = m_ros->toText(m);
        return text && m_mqtt->send(r.mqttTopic, *text, r.qos, r.retained);
    }
    if (r.json) {
        if (tooLargeForJson(QCoreApplication::translate("Ros2Bridge", "ROS %1").arg(r.rosTopic),
                            m.bytes.size()))
            return false;
        const Result<QByteArray> json = m_ros->toJson(m);
        return json && m_mqtt->send(r.mqttTopic, *json, r.qos, r.retained);
    }
    // mqtt_client announces the type (retained) with every message; two small publishes back to
    // back then meet Nagle's algorithm and the broker's delayed ACK, 40 ms for the second. The
    // announcement is retained, so once per type and connection says the same.
    if (m_options.announceEveryMessage || !m_typeSent.exchange(true) || m_sentType.name != m.type.name
        || m_sentType.md5 != m.type.md5) {
        RosMsgTypeInfo type = m.type;
        type.stamped = r.stamped;
        m_sentType = m.type;
        if (!m_mqtt->send(MqttClientWire::typeTopicPrefix() + r.mqttTopic, MqttClientWire::encodeType(type),
                          r.qos, true)) {
            m_typeSent = false;
            return false;
        }
    }
    const QByteArray payload
        = r.stamped ? MqttClientWire::stamped(now(), m.bytes, m_ros->dialect()) : m.bytes;
    *outNs = now();
    return m_mqtt->send(r.mqttTopic, payload, r.qos, r.retained);
}

void BridgeHop::announce(const QByteArray& payload)
{
    const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(payload);
    if (!info) {
        m_log(
            QCoreApplication::translate("ReferenceBridge", "ignored a malformed type announcement for %1: %2")
                .arg(m_route.mqttTopic, info.error().toString()));
        return;
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    if (info->dialect != m_ros->dialect()) {
        if (!std::exchange(m_dialectSaid, true))
            m_log((m_ros->dialect() == RosTypeRegistry::Dialect::Ros1
                       ? QCoreApplication::translate(
                           "ReferenceBridge",
                           "ignored the ROS 2 type announcement for %1 (%2): this bridge speaks ROS 1")
                       : QCoreApplication::translate(
                           "Ros2Bridge",
                           "ignored the ROS 1 type announcement for %1 (%2): this bridge speaks ROS 2"))
                      .arg(m_route.mqttTopic, info->name));
        return;
    }
    // A fixed type: announcements change nothing (v2.5 says so when they differ).
    if (!m_route.rosType.isEmpty()) {
        if (info->name != m_route.rosType && !std::exchange(m_dialectSaid, true))
            m_log(QCoreApplication::translate("Ros2Bridge", "%1 announces %2, but the config fixes %3: kept")
                      .arg(m_route.mqttTopic, info->name, m_route.rosType));
        return;
    }
    const bool changed = !m_announced || m_announced->name != info->name || m_announced->md5 != info->md5;
    m_announced = *info;
    if (changed)
        advertise(*info);
}

/// The message a payload from the broker carries (and its injected send time); nullopt when it
/// does not read as the mapping's, or its type was not announced yet.
std::optional<BridgeMessage> BridgeHop::readMqtt(const QByteArray& payload, std::optional<qint64>* sentNs)
{
    const BridgeRoute& r = m_route;
    const RosTypeRegistry::Dialect dialect = m_ros->dialect();
    if (r.primitive)
        return m_ros->fromText(r, payload);
    if (r.json) {
        if (tooLargeForJson(QCoreApplication::translate("Ros2Bridge", "MQTT %1").arg(r.mqttTopic),
                            payload.size()))
            return std::nullopt;
        Result<QByteArray> bytes = m_ros->fromJson(r.rosType, payload);
        if (!bytes)
            return std::nullopt;
        return BridgeMessage {{QString(), r.rosType, QString(), false, dialect}, std::move(*bytes)};
    }
    if (!r.rosType.isEmpty()) // v2.5: a fixed type is never stamped
        return BridgeMessage {{QString(), r.rosType, QString(), false, dialect}, payload};
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_announced)
        return std::nullopt;
    BridgeMessage m {*m_announced, payload};
    if (m_announced->stamped) {
        Result<MqttClientWire::Stamped> s = MqttClientWire::splitStamped(payload, dialect);
        if (!s)
            return std::nullopt;
        *sentNs = s->stampNs;
        m.bytes = std::move(s->message);
    }
    return m;
}

void BridgeHop::fromMqtt(const QByteArray& payload, qint64 receivedNs)
{
    std::optional<qint64> sentNs;
    const std::optional<BridgeMessage> m = readMqtt(payload, &sentNs);
    if (!m) {
        m_counters.failed.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    StampCodec::Decoded sample;
    if (!m_route.stampPrefix.isEmpty()) {
        sample = sampleOf(*m);
        publishStamp(m_stampIn, sample, receivedNs + m_options.clockOffsetNs);
    }
    int publisher = -1;
    {
        // A primitive's type follows its text ("42", then "hello"), an announced one the last
        // announcement: advertised anew when it changes.
        std::lock_guard<std::mutex> lock(m_mutex);
        if ((m->type.name != m_advertised.name || m->type.md5 != m_advertised.md5) && !advertise(m->type)) {
            m_counters.failed.fetch_add(1, std::memory_order_relaxed);
            return;
        }
        publisher = m_publisher;
    }
    const qint64 outNs = now(); // before it leaves, so no receiver stamps earlier
    const BridgeRosSide::Sent sent = m_ros->send(publisher, m->bytes);
    (sent == BridgeRosSide::Sent::Ok         ? m_counters.toRos
         : sent == BridgeRosSide::Sent::Full ? m_counters.droppedToRos
                                             : m_counters.failed)
        .fetch_add(1, std::memory_order_relaxed);
    if (sent == BridgeRosSide::Sent::Ok && !m_route.stampPrefix.isEmpty())
        publishStamp(m_stampOut, sample, outNs);
    if (sentNs)
        publishLatency(receivedNs, *sentNs);
}

/// The latency is mqtt_client's: from the injected send time to the arrival of the MQTT message
/// (v2.2.1 and v2.5 alike take `arrival_stamp` first thing in message_arrived(), before the
/// payload is read or anything published), the moment of the `<prefix>/in` stamp. So it does not
/// include this bridge's own work, on either ROS. Published after the message, which it would
/// otherwise delay; its publisher is made with the first stamped message, as mqtt_client does.
void BridgeHop::publishLatency(qint64 receivedNs, qint64 sentNs)
{
    if (m_latencyPublisher == -1) {
        const int id = m_ros->advertiseLatency(m_route.rosTopic);
        m_latencyPublisher = id >= 0 ? id : -2; // -2: refused, not asked again
    }
    if (m_latencyPublisher >= 0)
        m_ros->publish(m_latencyPublisher,
                       m_ros->float64(double(receivedNs + m_options.clockOffsetNs - sentNs) / 1e9));
}

/// Within the minute's limit of changes: false when a change is one too many (said once a minute).
bool BridgeHop::typeChangeAllowed()
{
    const qint64 nowNs = wallClockNs();
    if (nowNs - m_changeWindowNs >= 60'000'000'000LL) {
        m_changeWindowNs = nowNs;
        m_changesInWindow = 0;
    }
    if (++m_changesInWindow <= kMaxTypeChangesPerMinute)
        return true;
    if (m_changesInWindow == kMaxTypeChangesPerMinute + 1)
        m_log(
            QCoreApplication::translate("Ros2Bridge",
                                        "MQTT %1 -> ROS %2: refused: the announced type changed more than %3 "
                                        "times in a minute (kept %4; messages of other types dropped)")
                .arg(m_route.mqttTopic, m_route.rosTopic)
                .arg(kMaxTypeChangesPerMinute)
                .arg(m_advertised.name));
    return false;
}

/// (Re)advertises the mapping's ROS topic with `type`, retiring the publisher of the type before
/// (roscpp refuses a second type on one topic); false when that is refused: a type refused
/// before, a change past kMaxTypeChangesPerMinute, or one the ROS side refuses (said once a type).
/// Called with m_mutex held.
bool BridgeHop::advertise(const RosMsgTypeInfo& type)
{
    if (type.name == m_refusedType)
        return false;
    const bool change = !m_advertised.name.isEmpty();
    if (change && !typeChangeAllowed())
        return false;
    if (m_publisher >= 0)
        m_ros->retire(m_publisher);
    const Result<int> publisher = m_ros->advertise(m_route, type);
    m_publisher = publisher.valueOr(-1);
    if (!publisher) {
        refuse(type.name, publisher.error().toString());
        return false;
    }
    m_advertised = type;
    if (change && ++m_typeChanges > kLoggedChanges)
        return true; // counted, not logged
    if (!change)
        m_log(m_ros->publisherLine(m_route, type));
    else
        m_log(QCoreApplication::translate("ReferenceBridge", "MQTT %1 -> ROS %2: the type changed to %3%4")
                  .arg(m_route.mqttTopic, m_route.rosTopic, type.name,
                       m_typeChanges < kLoggedChanges
                           ? QString()
                           : QCoreApplication::translate("ReferenceBridge",
                                                         " (further changes are not logged)")));
    return true;
}

/// No publisher, `type` not asked for again: said once. Called with m_mutex held.
void BridgeHop::refuse(const QString& type, const QString& why)
{
    m_refusedType = type;
    m_log(QCoreApplication::translate("Ros2Bridge", "MQTT %1 -> ROS %2: refused: %3")
              .arg(m_route.mqttTopic, m_route.rosTopic, why));
    if (m_publisher >= 0)
        m_ros->retire(m_publisher);
    m_publisher = -1;
    m_advertised = {}; // the next type announced is asked for anew
}

void BridgeHop::refused(const QString& why)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const QString type = !m_advertised.name.isEmpty() ? m_advertised.name
        : m_announced                                 ? m_announced->name
                                                      : QString();
    if (type != m_refusedType)
        refuse(type, why);
}
