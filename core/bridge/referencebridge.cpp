// SPDX-License-Identifier: MIT
#include "referencebridge.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "bridge/bridgespec.h"
#include "mqtt/mqttlink.h"
#include "ros/rosendpoint.h"
#include "wire/mqttclientwire.h"
#include "wire/stampcodec.h"

#include <cmath>
#include <cstring>
#include <mutex>
#include <QCryptographicHash>
#include <QRegularExpression>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace PrimitiveText {
namespace {
QString md5Of(const QString& simpleDefinition)
{
    // For a message without dependencies ROS hashes its definition's field lines.
    return QString::fromLatin1(
        QCryptographicHash::hash(simpleDefinition.trimmed().toUtf8(), QCryptographicHash::Md5).toHex());
}

RosRawMessage make(const QString& field, const QByteArray& bytes)
{
    const QString name = field.front().toUpper() + field.mid(1);
    const QString definition = field + u" data\n"_s;
    return {bytes, u"std_msgs/"_s + (field == u"string"_s ? u"String"_s : name), md5Of(definition),
            definition};
}

template<typename T> T read(const QByteArray& bytes)
{
    T v {};
    std::memcpy(&v, bytes.constData(), sizeof(T));
    return v;
}

/// std::to_string's text, as mqtt_client writes numbers.
QByteArray floatText(double v)
{
    return QByteArray::number(v, 'f', 6);
}
} // namespace

std::optional<QByteArray> toText(const QString& type, const QByteArray& b)
{
    const QString t = type.startsWith(u"std_msgs/"_s) ? type.mid(9) : QString();
    const auto fits = [&b](qsizetype n) { return b.size() == n; };
    if (t == u"String"_s && b.size() >= 4) {
        const quint32 n = qFromLittleEndian<quint32>(b.constData());
        if (qsizetype(n) == b.size() - 4)
            return b.mid(4);
    } else if (t == u"Bool"_s && fits(1)) {
        return b[0] ? QByteArray("true") : QByteArray("false");
    } else if ((t == u"Int8"_s || t == u"Byte"_s) && fits(1)) {
        return QByteArray::number(int(read<qint8>(b)));
    } else if ((t == u"UInt8"_s || t == u"Char"_s) && fits(1)) {
        return QByteArray::number(uint(read<quint8>(b)));
    } else if (t == u"Int16"_s && fits(2)) {
        return QByteArray::number(int(read<qint16>(b)));
    } else if (t == u"UInt16"_s && fits(2)) {
        return QByteArray::number(uint(read<quint16>(b)));
    } else if (t == u"Int32"_s && fits(4)) {
        return QByteArray::number(read<qint32>(b));
    } else if (t == u"UInt32"_s && fits(4)) {
        return QByteArray::number(read<quint32>(b));
    } else if (t == u"Int64"_s && fits(8)) {
        return QByteArray::number(read<qint64>(b));
    } else if (t == u"UInt64"_s && fits(8)) {
        return QByteArray::number(read<quint64>(b));
    } else if (t == u"Float32"_s && fits(4)) {
        return floatText(double(read<float>(b)));
    } else if (t == u"Float64"_s && fits(8)) {
        return floatText(read<double>(b));
    }
    return std::nullopt;
}

RosRawMessage fromText(const QByteArray& text)
{
    if (text == "true" || text == "false")
        return make(u"bool"_s, QByteArray(1, text == "true" ? '\1' : '\0'));
    bool ok = false;
    const qint32 i = text.toInt(&ok);
    if (ok) {
        QByteArray b(4, Qt::Uninitialized);
        qToLittleEndian(i, b.data());
        return make(u"int32"_s, b);
    }
    const double d = text.toDouble(&ok);
    if (ok && std::isfinite(d)) {
        QByteArray b(8, Qt::Uninitialized);
        std::memcpy(b.data(), &d, 8);
        return make(u"float64"_s, b);
    }
    QByteArray b(4, Qt::Uninitialized);
    qToLittleEndian(quint32(text.size()), b.data());
    return make(u"string"_s, b + text);
}
} // namespace PrimitiveText

namespace {
constexpr const char* kFloat64Md5 = "fdb28210bfa9d7c91146260178d9a584";

/// Whether a message definition starts with a Header field (checked once per type).
bool startsWithHeader(const QString& definition)
{
    static const QRegularExpression headerFirst(u"^\\s*(#[^\\n]*\\n\\s*)*(std_msgs/)?Header\\s+\\w+"_s);
    return headerFirst.match(definition).hasMatch();
}

/// A mapping as the config says it, and its runtime state.
struct Route : BridgeRoute
{
    // Runtime state (mqtt2ros: the announced type and its publisher; stamp publishers).
    std::mutex mutex;
    RosMsgTypeInfo announced;
    bool haveType = false;
    int publisher = -1;
    bool advertiseFailed = false; ///< not retried for every message, only when the type changes
    quint64 typeChanges = 0;
    int latencyPublisher = -1;
    int stampIn = -1;
    int stampOut = -1;
    std::atomic<bool> typeSent {false}; ///< ros2mqtt: announced on this connection
    std::atomic<bool> ros2Said {
        false}; ///< mqtt2ros: a ROS 2 announcement was logged (it comes with every message)
    QString headerMd5; ///< the type whose Header check is cached (its thread only)
    bool headerFirst = false;

    bool hasHeader(const RosRawMessage& m)
    {
        if (headerMd5 != m.md5) {
            headerMd5 = m.md5;
            headerFirst = startsWithHeader(m.definition);
        }
        return headerFirst;
    }
    QString sentMd5; ///< ros2mqtt: the type announced (ROS callback thread only)
};

/// The sample a message is: its Header when it starts with one (the suite's messages all do),
/// else a hash of its bytes (the same at every component that carries it).
StampCodec::Decoded sampleOf(bool headerFirst, const QByteArray& bytes)
{
    if (headerFirst)
        if (std::optional<StampCodec::Decoded> header = StampCodec::decodeHeader(bytes))
            return *header;
    StampCodec::Decoded d;
    d.sampleNs = StampCodec::hashId(bytes) % 4'000'000'000'000'000'000LL; // fits the header's uint32 seconds
    return d;
}

} // namespace

struct ReferenceBridge::Private
{
    Log log;
    Options options;
    BridgeConfig config;
    MqttProfile profile;
    MqttWill will;
    std::vector<std::unique_ptr<Route>> routes;
    Counters counters;
    std::unique_ptr<RosEndpoint> ros;
    std::unique_ptr<MqttLink> mqtt;
    QString stampDefinition = StampCodec::definition();

    qint64 now() const { return wallClockNs() + options.clockOffsetNs; }

    void publishStamp(int publisher, const StampCodec::Decoded& sample, qint64 timeNs)
    {
        if (publisher < 0)
            return;
        StampCodec::Decoded d = sample;
        d.timeNs = timeNs;
        ros->publish(publisher, StampCodec::encodeTimeStamped(d));
    }

    // ROS spinner thread.
    void rosToMqtt(Route& r, const RosRawMessage& msg, qint64 receivedNs)
    {
        StampCodec::Decoded sample;
        if (!r.stampPrefix.isEmpty()) {
            sample = sampleOf(r.hasHeader(msg), msg.bytes);
            publishStamp(r.stampIn, sample, receivedNs + options.clockOffsetNs);
        }
        bool ok = true;
        qint64 outNs = now(); // the moment the message leaves: stamped before, so no receiver is earlier
        if (r.primitive) {
            const std::optional<QByteArray> text = PrimitiveText::toText(msg.type, msg.bytes);
            ok = text && mqtt->send(r.mqttTopic, *text, r.qos, r.retained);
        } else {
            // As mqtt_client does: the type announcement (retained) with every message, then the
            // message, preceded by the send time when stamped.
            // mqtt_client announces with every message; two small publishes back to back then
            // meet Nagle's algorithm and the broker's delayed ACK, 40 ms for the second. The
            // announcement is retained, so once per type and connection says the same.
            if (options.announceEveryMessage || !r.typeSent.exchange(true) || r.sentMd5 != msg.md5) {
                const QByteArray type
                    = MqttClientWire::encodeType({msg.md5, msg.type, msg.definition, r.stamped});
                ok = mqtt->send(MqttClientWire::typeTopicPrefix() + r.mqttTopic, type, r.qos, true);
                r.sentMd5 = msg.md5;
                if (!ok)
                    r.typeSent = false;
            }
            const QByteArray payload = r.stamped ? MqttClientWire::stamped(now(), msg.bytes) : msg.bytes;
            outNs = now();
            ok = ok && mqtt->send(r.mqttTopic, payload, r.qos, r.retained);
        }
        (ok ? counters.toMqtt : counters.failed).fetch_add(1, std::memory_order_relaxed);
        if (ok && !r.stampPrefix.isEmpty())
            publishStamp(r.stampOut, sample, outNs);
    }

    // Paho thread.
    void mqttToRos(Route& r, const QByteArray& payload, qint64 receivedNs)
    {
        RosRawMessage msg;
        std::optional<qint64> sentNs;
        int publisher = -1;
        if (r.primitive) {
            msg = PrimitiveText::fromText(payload);
        } else {
            std::lock_guard<std::mutex> lock(r.mutex);
            if (!r.haveType) {
                counters.failed.fetch_add(1, std::memory_order_relaxed); // type not announced yet
                return;
            }
            msg.type = r.announced.name;
            msg.md5 = r.announced.md5;
            msg.definition = r.announced.definition;
            if (r.announced.stamped) {
                const Result<MqttClientWire::Stamped> s = MqttClientWire::splitStamped(payload);
                if (!s) {
                    counters.failed.fetch_add(1, std::memory_order_relaxed);
                    return;
                }
                sentNs = s->stampNs;
                msg.bytes = s->message;
            } else {
                msg.bytes = payload;
            }
        }
        StampCodec::Decoded sample;
        if (!r.stampPrefix.isEmpty()) {
            sample = sampleOf(r.hasHeader(msg), msg.bytes);
            publishStamp(r.stampIn, sample, receivedNs + options.clockOffsetNs);
        }
        {
            std::lock_guard<std::mutex> lock(r.mutex);
            if (r.primitive && (!r.haveType || r.announced.md5 != msg.md5)) {
                // A primitive's type follows its text ("42", then "hello"): advertised anew.
                r.announced = {msg.md5, msg.type, msg.definition, false};
                r.haveType = true;
                advertiseAnnounced(r);
            } else if (r.publisher < 0 && !r.advertiseFailed) {
                advertiseAnnounced(r);
            }
            publisher = r.publisher;
        }
        const qint64 outNs = now(); // before it leaves, so no receiver stamps earlier
        const RosEndpoint::Sent sent = ros->send(publisher, msg.bytes);
        const bool ok = sent == RosEndpoint::Sent::Ok;
        (ok                                    ? counters.toRos
             : sent == RosEndpoint::Sent::Full ? counters.droppedToRos
                                               : counters.failed)
            .fetch_add(1, std::memory_order_relaxed);
        if (ok && !r.stampPrefix.isEmpty())
            publishStamp(r.stampOut, sample, outNs);
        if (sentNs && r.latencyPublisher >= 0) {
            const double seconds = double(now() - *sentNs) / 1e9;
            QByteArray bytes(8, Qt::Uninitialized);
            std::memcpy(bytes.data(), &seconds, 8);
            ros->publish(r.latencyPublisher, bytes);
        }
    }

    /// (Re)advertises `r.rosTopic` with the announced type, retiring the publisher of the type
    /// before: roscpp refuses a second type on one topic. Called with `r.mutex` held.
    void advertiseAnnounced(Route& r)
    {
        if (r.publisher >= 0) {
            ros->retire(r.publisher);
            r.publisher = -1;
            ++r.typeChanges;
        }
        QString error;
        const RosMsgTypeInfo& t = r.announced;
        r.publisher = ros->advertise(r.rosTopic, t.name, t.md5, t.definition, r.queueSize, r.latched, &error);
        r.advertiseFailed = r.publisher < 0;
        // Anyone on the broker can flip a topic's type with every message: the first changes are
        // logged, the rest only counted.
        constexpr quint64 kLoggedChanges = 5;
        if (r.typeChanges > kLoggedChanges)
            return;
        if (r.publisher < 0)
            log(tr("cannot publish %1 on %2: %3").arg(t.name, r.rosTopic, error));
        else if (r.typeChanges == 0)
            log(tr("MQTT %1 -> ROS %2 (%3%4)")
                    .arg(r.mqttTopic, r.rosTopic, t.name, t.stamped ? tr(", stamped") : QString()));
        else
            log(tr("MQTT %1 -> ROS %2: the type changed to %3%4")
                    .arg(r.mqttTopic, r.rosTopic, t.name,
                         r.typeChanges == kLoggedChanges ? tr(" (further changes are not logged)")
                                                         : QString()));
    }

    // Paho thread: a type announcement for an mqtt2ros route.
    void announce(Route& r, const QByteArray& payload)
    {
        const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(payload);
        if (!info) {
            log(tr("ignored a malformed type announcement for %1: %2")
                    .arg(r.mqttTopic, info.error().toString()));
            return;
        }
        if (info->dialect != RosTypeRegistry::Dialect::Ros1) {
            if (!r.ros2Said.exchange(true))
                log(tr("ignored the ROS 2 type announcement for %1 (%2): this bridge speaks ROS 1")
                        .arg(r.mqttTopic, info->name));
            return;
        }
        std::lock_guard<std::mutex> lock(r.mutex);
        if (r.haveType && r.announced == *info)
            return;
        const bool changed = r.haveType && (r.announced.md5 != info->md5 || r.announced.name != info->name);
        r.announced = *info;
        r.haveType = true;
        if (r.publisher < 0 || changed)
            advertiseAnnounced(r);
        if (info->stamped && r.latencyPublisher < 0) {
            const QString topic = ros->resolve(u"~/latencies/"_s + r.rosTopic);
            QString error; // not shown: without the topic the latencies are not published
            r.latencyPublisher
                = ros->advertise(topic, u"std_msgs/Float64"_s, QString::fromLatin1(kFloat64Md5),
                                 u"float64 data\n"_s, 1, false, &error);
        }
    }
};

ReferenceBridge::ReferenceBridge(Log log)
    : d(std::make_unique<Private>())
{
    d->log = std::move(log);
}

ReferenceBridge::~ReferenceBridge()
{
    stop();
}

const ReferenceBridge::Counters& ReferenceBridge::counters() const
{
    if (d->mqtt) {
        const MqttLink::QueueCounts q = d->mqtt->queueCounts();
        d->counters.droppedToMqtt = q.dropped;
        d->counters.failedWaiting = q.failed;
        d->counters.heldBytes = q.heldBytes + (d->ros ? d->ros->heldBytes() : 0);
    }
    return d->counters;
}

const MqttProfile& ReferenceBridge::profile() const
{
    return d->profile;
}

int ReferenceBridge::mappingCount() const
{
    return int(d->routes.size());
}

bool ReferenceBridge::load(const QByteArray& yaml, const Options& options, QString* error)
{
    std::optional<BridgeSpec> spec = BridgeSpec::load(yaml, options.brokerUrl, options.args, error);
    if (!spec)
        return false;
    d->options = options;
    d->config = spec->config;
    d->profile = spec->profile;
    d->will = spec->will;
    d->routes.clear();
    for (const BridgeRoute& b : spec->routes) {
        auto r = std::make_unique<Route>();
        static_cast<BridgeRoute&>(*r) = b;
        d->routes.push_back(std::move(r));
    }
    return true;
}

bool ReferenceBridge::start(const std::function<bool()>& keepWaiting, QString* error)
{
    d->ros = std::make_unique<RosEndpoint>();
    d->ros->setNoticeHandler(d->log);
    d->ros->setMaxHeldBytes(d->options.maxQueuedBytes / 2);
    qCDebug(lcBridge) << "ROS 1 bridge: at most" << d->options.maxQueuedBytes / 2
                      << "bytes held towards ROS and as many towards the broker";
    const QString name = d->options.nodeName.isEmpty() ? u"mqtt_client"_s : d->options.nodeName;
    d->log(tr("waiting for the ROS master…"));
    if (!d->ros->start(name, d->options.rosMaster, keepWaiting, error))
        return false;
    d->log(tr("ROS node %1 started").arg(d->ros->nodeName()));

    MqttLink::Options linkOptions;
    linkOptions.will = d->will;
    linkOptions.maxQueuedBytes = d->options.maxQueuedBytes / 2;
    d->mqtt = std::make_unique<MqttLink>(d->profile, linkOptions);
    Private* p = d.get();
    QHash<QString, Route*> byMqtt;
    QHash<QString, Route*> byTypeTopic;
    for (const auto& r : d->routes) {
        if (!r->stampPrefix.isEmpty()) {
            QString why;
            for (const auto& [suffix, slot] : {std::pair {u"/in"_s, &r->stampIn}, {u"/out"_s, &r->stampOut}})
                *slot = d->ros->advertise(
                    r->stampPrefix + suffix, QString::fromLatin1(StampCodec::typeName()),
                    QString::fromLatin1(StampCodec::md5()), d->stampDefinition, 1000, false, &why);
        }
        if (r->direction == Direction::Mqtt2Ros) {
            byMqtt.insert(r->mqttTopic, r.get());
            d->mqtt->addSubscription(r->mqttTopic, r->qos);
            if (!r->primitive) {
                byTypeTopic.insert(MqttClientWire::typeTopicPrefix() + r->mqttTopic, r.get());
                d->mqtt->addSubscription(MqttClientWire::typeTopicPrefix() + r->mqttTopic, r->qos);
            } else {
                d->log(tr("MQTT %1 -> ROS %2 (primitive)").arg(r->mqttTopic, r->rosTopic));
            }
        }
    }
    d->mqtt->setMessageHandler(
        [p, byMqtt, byTypeTopic](const QString& topic, const QByteArray& payload, qint64 t) {
            if (Route* r = byTypeTopic.value(topic))
                p->announce(*r, payload);
            else if (Route* r = byMqtt.value(topic))
                p->mqttToRos(*r, payload, t);
        });
    d->mqtt->setConnectedHandler([p](bool reconnect) {
        if (!reconnect)
            return;
        for (const auto& r : p->routes)
            r->typeSent = false; // announced again with the next message
        p->log(tr("reconnected to %1").arg(p->profile.url));
    });
    d->mqtt->setLostHandler([p](const QString& why) {
        p->log(tr("lost the broker (%1); reconnecting").arg(why.isEmpty() ? u"?"_s : why));
    });
    d->log(tr("connecting to %1…").arg(d->profile.url));
    if (!d->mqtt->connect(10000, error))
        return false;
    d->log(tr("connected to %1").arg(d->profile.url));

    for (const auto& r : d->routes) {
        if (r->direction != Direction::Ros2Mqtt)
            continue;
        Route* route = r.get();
        QString why;
        if (!d->ros->subscribe(
                r->rosTopic, r->queueSize,
                [p, route](const RosRawMessage& m, qint64 t) { p->rosToMqtt(*route, m, t); }, &why)) {
            if (error)
                *error = tr("cannot subscribe to %1: %2").arg(r->rosTopic, why);
            return false;
        }
        d->log(tr("ROS %1 -> MQTT %2%3")
                   .arg(r->rosTopic, r->mqttTopic,
                        r->primitive ? tr(" (primitive)") : (r->stamped ? tr(" (stamped)") : QString())));
    }
    return true;
}

void ReferenceBridge::stop()
{
    counters(); // the last figures of the queues, kept
    if (d->mqtt)
        d->mqtt->disconnect();
    if (d->ros)
        d->ros->shutdown();
    d->mqtt.reset();
    d->ros.reset();
}
