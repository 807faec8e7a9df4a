// SPDX-License-Identifier: MIT
#include "bridge/ros2bridge.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "bridge/bridgespec.h"
#include "bridge/ros2bridgewire.h"
#include "mqtt/mqttlink.h"
#include "ros2/ros2participant.h"
#include "wire/mqttclientwire.h"
#include "wire/ros2definitions.h"

#include <atomic>
#include <QHash>
#include <QMetaObject>

using namespace Qt::StringLiterals;

namespace {

/// A mapping as the config says it, and its runtime state (the event loop's thread only).
struct Route : BridgeRoute
{
    // ros2mqtt
    QString subscribedType; ///< empty until subscribed
    bool headerFirst = false;
    bool typeSent = false; ///< announced on this connection
    // mqtt2ros
    QString announcedType; ///< from the RosMsgType announcement
    bool announcedStamped = false;
    QString advertisedType; ///< the writer's type, or empty
    QString latencyTopic; ///< advertised once the first stamped message came
    quint64 typeChanges = 0;
    qint64 changeWindowNs = 0; ///< when the current minute of type changes began
    int changesInWindow = 0;
    QString refusedType; ///< a type whose writer or reader was refused: not asked again
    bool dialectSaid = false; ///< a ROS 1 announcement was logged
    // timestamp_topic_prefix
    QString stampIn;
    QString stampOut;
};

constexpr quint64 kLoggedChanges = 5;
/// A mapping's ROS 2 type may change this often a minute (each change is a new DDS topic and
/// writer in the DDS process); a change beyond is refused, said once a minute, and the messages
/// of the new type are dropped and counted (issue 41: a client flipping the announced type with
/// every message kept the DDS process from its heartbeats until it was killed).
constexpr int kMaxTypeChangesPerMinute = 10;

/// The config's QoS over `base`: reliable or best effort, volatile or transient local ("auto" or
/// nothing keeps the base's; "system_default" is Cyclone's: reliable, volatile), keep last
/// queue_size.
Ros2Qos configQos(const Route& r, Ros2Qos base)
{
    if (r.reliability == u"best_effort"_s)
        base.reliability = Ros2Qos::BestEffort;
    else if (r.reliability == u"reliable"_s || r.reliability == u"system_default"_s)
        base.reliability = Ros2Qos::Reliable;
    if (r.durability == u"transient_local"_s)
        base.durability = Ros2Qos::TransientLocal;
    else if (r.durability == u"volatile"_s || r.durability == u"system_default"_s)
        base.durability = Ros2Qos::Volatile;
    base.depth = r.queueSize;
    return base;
}

bool isAuto(const QString& policy)
{
    return policy.isEmpty() || policy == u"auto"_s;
}

} // namespace

struct Ros2Bridge::Private
{
    Log log;
    Options options;
    BridgeSpec spec;
    std::vector<std::unique_ptr<Route>> routes;
    Counters counters;
    RosTypeRegistry registry = Ros2Definitions::registry();
    QString nameSpace = u"/"_s;
    QString name = u"mqtt_client"_s;
    std::unique_ptr<Ros2Participant> ros;
    std::unique_ptr<MqttLink> mqtt;
    QHash<QString, Route*> byRosTopic; ///< ros2mqtt
    QHash<QString, Route*> byMqtt; ///< mqtt2ros data topics
    QHash<QString, Route*> byTypeTopic; ///< mqtt2ros announcement topics
    std::atomic<qint64> hopBytes {0}; ///< messages from the broker waiting for the event loop

    qint64 now() const { return wallClockNs() + options.clockOffsetNs; }
    QString fullName() const { return nameSpace == u"/"_s ? QString(u"/"_s + name) : QString(nameSpace + u'/' + name); }

    /// A ROS name as rclcpp resolves it in our node: `~/x` below the node, `x` in its namespace.
    QString resolve(const QString& topic) const
    {
        if (topic.startsWith(u'~'))
            return fullName() + topic.mid(1);
        if (topic.startsWith(u'/'))
            return topic;
        return (nameSpace == u"/"_s ? QString() : nameSpace) + u'/' + topic;
    }

    void publishStamp(const QString& topic, StampCodec::Decoded sample, qint64 timeNs)
    {
        if (topic.isEmpty())
            return;
        sample.timeNs = timeNs;
        ros->publish(topic, Ros2BridgeWire::encodeTimeStamped(sample));
    }

    /// The sample a message is: its header.stamp when it starts with a Header (the suite's messages
    /// all do), else a hash of its bytes (the same at every component that carries it).
    static StampCodec::Decoded sampleOf(bool headerFirst, const QByteArray& cdr)
    {
        StampCodec::Decoded d;
        const std::optional<qint64> stamp = headerFirst ? Ros2BridgeWire::headerStampNs(cdr) : std::nullopt;
        d.sampleNs = stamp ? *stamp : StampCodec::hashId(cdr) % 4'000'000'000'000'000'000LL;
        return d;
    }

    void setupSubscriptions();
    void subscribe(Route& r, const QString& type, const Ros2Qos& qos);
    void rosToMqtt(Route& r, const Ros2Sample& s);
    void fromMqtt(const QString& topic, const QByteArray& payload, qint64 receivedNs);
    void announce(Route& r, const QByteArray& payload);
    void mqttToRos(Route& r, const QByteArray& payload, qint64 receivedNs);
    bool advertiseRoute(Route& r, const QString& type);
    void refused(const QString& rosTopic, const QString& why);
    void refuseTooLarge(const QString& from, qsizetype bytes);
    void startMqtt();
};

/// ros2mqtt mappings not subscribed yet: a fixed type with both QoS policies given at once, else
/// as v2.5's setupSubscriptions() does, once a publisher of the topic (of the fixed type, if
/// any) is in the graph, with its QoS under what the config sets.
void Ros2Bridge::Private::setupSubscriptions()
{
    const QString own = fullName();
    for (const auto& route : routes) {
        Route& r = *route;
        if (r.direction != Direction::Ros2Mqtt || !r.subscribedType.isEmpty())
            continue;
        if (!r.rosType.isEmpty() && !isAuto(r.reliability) && !isAuto(r.durability)) {
            subscribe(r, r.rosType, configQos(r, {}));
            continue;
        }
        const Ros2Topic* t = ros->graph().topic(r.rosTopic);
        if (!t)
            continue;
        for (const Ros2Endpoint& pub : t->publishers) {
            if (pub.node == own || (!r.rosType.isEmpty() && pub.type != r.rosType))
                continue;
            const Ros2Qos qos = configQos(r, pub.qos);
            if (ros2QosCompatible(pub.qos, qos)) {
                subscribe(r, pub.type, qos);
                break;
            }
        }
    }
}

void Ros2Bridge::Private::subscribe(Route& r, const QString& type, const Ros2Qos& qos)
{
    r.subscribedType = type;
    r.headerFirst = Ros2BridgeWire::startsWithHeader(registry, type);
    ros->subscribe(r.rosTopic, type, qos);
    log(tr("ROS %1 -> MQTT %2 (%3, %4%5)")
            .arg(r.rosTopic, r.mqttTopic, type, qos.text(),
                 r.primitive ? tr(", primitive") : (r.stamped ? tr(", stamped") : QString())));
}

// The event loop's thread: a sample from DDS.
void Ros2Bridge::Private::rosToMqtt(Route& r, const Ros2Sample& s)
{
    StampCodec::Decoded sample;
    if (!r.stampIn.isEmpty()) {
        sample = sampleOf(r.headerFirst, s.bytes);
        publishStamp(r.stampIn, sample, s.receivedNs + options.clockOffsetNs);
    }
    bool ok = true;
    qint64 outNs = now(); // the moment the message leaves: stamped before, so no receiver is earlier
    if (r.primitive) {
        const std::optional<QByteArray> text = Ros2BridgeWire::primitiveText(registry, r.subscribedType, s.bytes);
        ok = text && mqtt->send(r.mqttTopic, *text, r.qos, r.retained);
    } else if (r.json && s.bytes.size() > Ros2BridgeWire::kMaxJsonBytes) {
        refuseTooLarge(tr("ROS %1").arg(r.rosTopic), s.bytes.size());
        ok = false;
    } else if (r.json) {
        const Result<QByteArray> json = Ros2BridgeWire::toJson(registry, r.subscribedType, s.bytes);
        ok = json && mqtt->send(r.mqttTopic, *json, r.qos, r.retained);
    } else {
        // v2.5 announces (retained) with every message; once per type and connection says the same
        // and spares the broker, unless asked for every message.
        if (options.announceEveryMessage || !r.typeSent) {
            const QByteArray type = MqttClientWire::encodeType(
                {QString(), r.subscribedType, QString(), r.stamped, RosTypeRegistry::Dialect::Ros2});
            r.typeSent = mqtt->send(MqttClientWire::typeTopicPrefix() + r.mqttTopic, type, r.qos, true);
            ok = r.typeSent;
        }
        const QByteArray payload
            = r.stamped ? MqttClientWire::stamped(now(), s.bytes, RosTypeRegistry::Dialect::Ros2) : s.bytes;
        outNs = now();
        ok = ok && mqtt->send(r.mqttTopic, payload, r.qos, r.retained);
    }
    (ok ? counters.toMqtt : counters.failed).fetch_add(1, std::memory_order_relaxed);
    if (ok && !r.stampOut.isEmpty())
        publishStamp(r.stampOut, sample, outNs);
}

void Ros2Bridge::Private::fromMqtt(const QString& topic, const QByteArray& payload, qint64 receivedNs)
{
    if (Route* r = byTypeTopic.value(topic))
        announce(*r, payload);
    else if (Route* r = byMqtt.value(topic))
        mqttToRos(*r, payload, receivedNs);
}

void Ros2Bridge::Private::announce(Route& r, const QByteArray& payload)
{
    const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(payload);
    if (!info) {
        log(tr("ignored a malformed type announcement for %1: %2").arg(r.mqttTopic, info.error().toString()));
        return;
    }
    if (info->dialect != RosTypeRegistry::Dialect::Ros2) {
        if (!std::exchange(r.dialectSaid, true))
            log(tr("ignored the ROS 1 type announcement for %1 (%2): this bridge speaks ROS 2")
                    .arg(r.mqttTopic, info->name));
        return;
    }
    if (!r.rosType.isEmpty()) { // a fixed type: announcements change nothing (v2.5 says so when they differ)
        if (info->name != r.rosType && !std::exchange(r.dialectSaid, true))
            log(tr("%1 announces %2, but the config fixes %3: kept").arg(r.mqttTopic, info->name, r.rosType));
        return;
    }
    r.announcedStamped = info->stamped;
    if (info->name != r.announcedType) {
        r.announcedType = info->name;
        advertiseRoute(r, info->name);
    }
}

/// (Re)advertises the mapping's ROS topic with `type`; false when that is refused (a type
/// refused before, a change past kMaxTypeChangesPerMinute, a name DDS may not be given).
bool Ros2Bridge::Private::advertiseRoute(Route& r, const QString& type)
{
    if (type == r.refusedType)
        return false;
    Ros2Qos qos;
    qos.reliability = r.reliability == u"best_effort"_s ? Ros2Qos::BestEffort : Ros2Qos::Reliable;
    qos.durability = r.durability == u"transient_local"_s ? Ros2Qos::TransientLocal : Ros2Qos::Volatile;
    qos.depth = r.queueSize;
    const bool changed = !r.advertisedType.isEmpty();
    if (changed) {
        const qint64 nowNs = wallClockNs();
        if (nowNs - r.changeWindowNs >= 60'000'000'000LL) {
            r.changeWindowNs = nowNs;
            r.changesInWindow = 0;
        }
        if (++r.changesInWindow > kMaxTypeChangesPerMinute) {
            if (r.changesInWindow == kMaxTypeChangesPerMinute + 1)
                log(tr("MQTT %1 -> ROS %2: refused: the announced type changed more than %3 times in a minute "
                       "(kept %4; messages of other types dropped)")
                        .arg(r.mqttTopic, r.rosTopic)
                        .arg(kMaxTypeChangesPerMinute)
                        .arg(r.advertisedType));
            return false;
        }
    }
    const QString before = r.advertisedType;
    r.advertisedType = type;
    if (!ros->advertise(r.rosTopic, type, qos)) {
        r.advertisedType = before; // said by refused()
        return false;
    }
    if (changed && ++r.typeChanges > kLoggedChanges)
        return true; // anyone on the broker can flip the type with every message: counted, not logged
    if (!changed)
        log(tr("MQTT %1 -> ROS %2 (%3, %4)").arg(r.mqttTopic, r.rosTopic, type, qos.text()));
    else
        log(tr("MQTT %1 -> ROS %2: the type changed to %3%4")
                .arg(r.mqttTopic, r.rosTopic, type,
                     r.typeChanges == kLoggedChanges ? tr(" (further changes are not logged)") : QString()));
    return true;
}

/// The participant refused a mapping's writer or reader (a name DDS may not be given, Cyclone
/// refused it, or the DDS process ended while making it): said once per type, not asked again;
/// the other mappings go on.
void Ros2Bridge::Private::refused(const QString& rosTopic, const QString& why)
{
    for (const auto& route : routes) {
        Route& r = *route;
        if (r.rosTopic != rosTopic)
            continue;
        QString& type = r.direction == Direction::Ros2Mqtt ? r.subscribedType : r.advertisedType;
        const QString refusedType = type.isEmpty() ? r.announcedType : type;
        if (refusedType == r.refusedType)
            continue;
        r.refusedType = refusedType;
        if (r.direction == Direction::Ros2Mqtt) {
            log(tr("ROS %1 -> MQTT %2: refused: %3").arg(r.rosTopic, r.mqttTopic, why));
        } else {
            log(tr("MQTT %1 -> ROS %2: refused: %3").arg(r.mqttTopic, r.rosTopic, why));
            type.clear(); // the next type announced is asked for anew
        }
    }
}

// A json mapping's payload too large to convert: counted, the first one logged (a peer can send
// them as fast as it likes).
void Ros2Bridge::Private::refuseTooLarge(const QString& from, qsizetype bytes)
{
    if (counters.tooLarge.fetch_add(1, std::memory_order_relaxed) == 0)
        log(tr("%1: %2 (further ones are counted)").arg(from, Ros2BridgeWire::tooLargeForJson(bytes)));
}

// The event loop's thread: a message from the broker (handed over from Paho's).
void Ros2Bridge::Private::mqttToRos(Route& r, const QByteArray& payload, qint64 receivedNs)
{
    std::optional<QByteArray> cdr;
    QString type = r.rosType;
    std::optional<qint64> sentNs;
    if (r.primitive && type.isEmpty()) {
        Ros2BridgeWire::Typed t = Ros2BridgeWire::primitiveFromText(payload);
        type = t.type;
        cdr = t.cdr;
    } else if (r.primitive) {
        cdr = Ros2BridgeWire::fixedPrimitive(registry, type, payload);
    } else if (r.json && payload.size() > Ros2BridgeWire::kMaxJsonBytes) {
        refuseTooLarge(tr("MQTT %1").arg(r.mqttTopic), payload.size()); // counted as failed below
    } else if (r.json) {
        if (Result<QByteArray> converted = Ros2BridgeWire::fromJson(registry, type, payload))
            cdr = std::move(converted).value();
    } else if (!type.isEmpty()) {
        cdr = payload; // v2.5: a fixed type is never stamped
    } else if (!r.announcedType.isEmpty()) {
        type = r.announcedType;
        if (!r.announcedStamped) {
            cdr = payload;
        } else if (auto s = MqttClientWire::splitStamped(payload, RosTypeRegistry::Dialect::Ros2)) {
            sentNs = s->stampNs;
            cdr = s->message;
        }
    }
    if (!cdr || type.isEmpty()) { // not announced yet, or not of its type
        counters.failed.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    StampCodec::Decoded sample;
    if (!r.stampIn.isEmpty()) {
        sample = sampleOf(Ros2BridgeWire::startsWithHeader(registry, type), *cdr);
        publishStamp(r.stampIn, sample, receivedNs + options.clockOffsetNs);
    }
    if (type != r.advertisedType && !advertiseRoute(r, type)) {
        counters.failed.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    const qint64 outNs = now(); // before it leaves, so no receiver stamps earlier
    const bool ok = ros->publish(r.rosTopic, *cdr);
    (ok ? counters.toRos : counters.droppedToRos).fetch_add(1, std::memory_order_relaxed);
    if (ok && !r.stampOut.isEmpty())
        publishStamp(r.stampOut, sample, outNs);
    if (sentNs) {
        if (r.latencyTopic.isEmpty()) {
            // v2.5: "~/latencies/" + ros_topic with its "//" made one, std_msgs/msg/Float64, depth 1
            QString topic = u"~/latencies/"_s + r.rosTopic;
            topic.replace(u"//"_s, u"/"_s);
            r.latencyTopic = resolve(topic);
            Ros2Qos qos;
            qos.depth = 1;
            ros->advertise(r.latencyTopic, u"std_msgs/msg/Float64"_s, qos);
        }
        ros->publish(r.latencyTopic, Ros2BridgeWire::encodeFloat64(double(receivedNs + options.clockOffsetNs - *sentNs) / 1e9));
    }
}

Ros2Bridge::Ros2Bridge(Log log)
    : d(std::make_unique<Private>())
{
    d->log = std::move(log);
}

Ros2Bridge::~Ros2Bridge()
{
    stop();
}

bool Ros2Bridge::load(const QByteArray& yaml, const Options& options, QString* error)
{
    std::optional<BridgeSpec> spec = BridgeSpec::load(yaml, options.brokerUrl, options.args, error);
    if (!spec)
        return false;
    d->options = options;
    d->spec = std::move(*spec);
    QString full = options.nodeName;
    if (full.isEmpty() && d->spec.config.layout == ConfigLayout::Ros2 && !d->spec.config.ros2NodeName.contains(u'*'))
        full = d->spec.config.ros2NodeName; // the node key of a params file; "/**" matches any node
    if (full.isEmpty())
        full = u"mqtt_client"_s;
    if (!full.startsWith(u'/'))
        full.prepend(u'/');
    const qsizetype slash = full.lastIndexOf(u'/');
    d->nameSpace = slash == 0 ? u"/"_s : full.left(slash);
    d->name = full.mid(slash + 1);
    d->routes.clear();
    for (const BridgeRoute& b : d->spec.routes) {
        auto r = std::make_unique<Route>();
        static_cast<BridgeRoute&>(*r) = b;
        r->rosTopic = d->resolve(r->rosTopic);
        if (r->primitive && r->json)
            r->json = false; // v2.5: primitive wins
        if (r->primitive || r->json)
            r->stamped = false; // v2.5 injects no stamp into text
        if (r->json && r->rosType.isEmpty()) {
            if (error)
                *error = tr("%1: json needs a ros_type, as mqtt_client says").arg(r->mqttTopic);
            return false;
        }
        if (!r->stampPrefix.isEmpty()) {
            r->stampIn = d->resolve(r->stampPrefix + u"/in"_s);
            r->stampOut = d->resolve(r->stampPrefix + u"/out"_s);
        }
        d->routes.push_back(std::move(r));
    }
    return true;
}

QString Ros2Bridge::nodeName() const
{
    return d->fullName();
}

const Ros2Bridge::Counters& Ros2Bridge::counters() const
{
    if (d->mqtt) {
        const MqttLink::QueueCounts q = d->mqtt->queueCounts();
        d->counters.droppedToMqtt = q.dropped;
        d->counters.failedWaiting = q.failed;
        d->counters.heldBytes = q.heldBytes + d->hopBytes.load();
    }
    return d->counters;
}

const MqttProfile& Ros2Bridge::profile() const
{
    return d->spec.profile;
}

int Ros2Bridge::mappingCount() const
{
    return int(d->routes.size());
}

bool Ros2Bridge::start(const Ros2Options& rosOptions, QString* error)
{
    d->ros = std::make_unique<Ros2Participant>();
    Private* p = d.get();
    Ros2Participant* ros = d->ros.get();
    QObject::connect(ros, &Ros2Participant::received, ros, [p](const QString& topic, const Ros2Sample& s) {
        if (Route* r = p->byRosTopic.value(topic))
            p->rosToMqtt(*r, s);
    });
    QObject::connect(ros, &Ros2Participant::graphChanged, ros, [p] { p->setupSubscriptions(); });
    QObject::connect(ros, &Ros2Participant::joined, ros, [p, rosOptions](bool ok) {
        if (ok)
            p->log(tr("ROS 2 node %1 on domain %2%3")
                       .arg(p->fullName())
                       .arg(rosOptions.domain)
                       .arg(rosOptions.localhostOnly ? tr(" (this host only)") : QString()));
        else
            p->log(tr("not on the ROS 2 domain: %1").arg(p->ros->lastError()));
    });
    QObject::connect(ros, &Ros2Participant::endpointRefused, ros,
                     [p](const QString& topic, const QString& why) { p->refused(topic, why); });
    QObject::connect(ros, &Ros2Participant::restarted, ros, [p](const QString& why) {
        p->log(tr("the DDS process %1; starting it again (%2)").arg(why, p->ros->restartText()));
    });
    QObject::connect(ros, &Ros2Participant::restartLoopBroken, ros,
                     [p](const QString& what) { p->log(what); });
    if (!ros->start(rosOptions, error))
        return false;
    ros->setNode(d->nameSpace, d->name);
    Ros2Qos stampQos;
    stampQos.depth = 1000;
    for (const auto& r : d->routes) {
        for (const QString& topic : {r->stampIn, r->stampOut})
            if (!topic.isEmpty())
                ros->advertise(topic, QString::fromLatin1(Ros2BridgeWire::kTimeStampedType), stampQos);
        if (r->direction == Direction::Ros2Mqtt) {
            d->byRosTopic.insert(r->rosTopic, r.get());
        } else {
            d->byMqtt.insert(r->mqttTopic, r.get());
            if (!r->rosType.isEmpty())
                d->advertiseRoute(*r, r->rosType); // v2.5's setupPublishers(): before any message
            if (!r->primitive && !r->json)
                d->byTypeTopic.insert(MqttClientWire::typeTopicPrefix() + r->mqttTopic, r.get());
        }
    }
    d->setupSubscriptions();
    d->startMqtt();
    d->log(tr("connecting to %1…").arg(d->spec.profile.url));
    if (!d->mqtt->connect(10000, error))
        return false;
    d->log(tr("connected to %1").arg(d->spec.profile.url));
    return true;
}

void Ros2Bridge::Private::startMqtt()
{
    MqttLink::Options linkOptions;
    linkOptions.will = spec.will;
    linkOptions.maxQueuedBytes = options.maxQueuedBytes / 2;
    mqtt = std::make_unique<MqttLink>(spec.profile, linkOptions);
    for (auto it = byMqtt.cbegin(); it != byMqtt.cend(); ++it)
        mqtt->addSubscription(it.key(), (*it)->qos);
    for (auto it = byTypeTopic.cbegin(); it != byTypeTopic.cend(); ++it)
        mqtt->addSubscription(it.key(), (*it)->qos);
    Private* p = this;
    // Towards ROS, half of the bound: a quarter for messages waiting for the event loop, a quarter
    // for those in the pipe to the DDS process.
    const qint64 bound = options.maxQueuedBytes / 4;
    ros->setPublishBound(bound);
    qCDebug(lcBridge) << "ROS 2 bridge: at most" << options.maxQueuedBytes / 2 << "bytes held towards the broker,"
                      << bound << "waiting for the event loop and" << bound << "in the pipe to DDS";
    // Paho's thread: handed to the event loop within the bound, in order.
    mqtt->setMessageHandler([p, bound](const QString& topic, const QByteArray& payload, qint64 t) {
        const qint64 size = payload.size();
        const qint64 held = p->hopBytes.fetch_add(size);
        if (held > 0 && held + size > bound) { // one larger than the bound passes alone
            p->hopBytes.fetch_sub(size);
            p->counters.droppedToRos.fetch_add(1, std::memory_order_relaxed);
            return;
        }
        QMetaObject::invokeMethod(
            p->ros.get(),
            [p, topic, payload, t] {
                p->hopBytes.fetch_sub(payload.size());
                p->fromMqtt(topic, payload, t);
            },
            Qt::QueuedConnection);
    });
    mqtt->setConnectedHandler([p](bool reconnect) {
        if (!reconnect)
            return;
        QMetaObject::invokeMethod(p->ros.get(), [p] {
            for (const auto& r : p->routes)
                r->typeSent = false; // announced again with the next message
        });
        p->log(tr("reconnected to %1").arg(p->spec.profile.url));
    });
    mqtt->setLostHandler([p](const QString& why) {
        p->log(tr("lost the broker (%1); reconnecting").arg(why.isEmpty() ? u"?"_s : why));
    });
}

void Ros2Bridge::stop()
{
    counters(); // the last figures of the queues, kept
    if (d->mqtt)
        d->mqtt->disconnect();
    d->mqtt.reset();
    d->ros.reset(); // with the events still queued for it
    d->byRosTopic.clear();
    d->byMqtt.clear();
    d->byTypeTopic.clear();
}
