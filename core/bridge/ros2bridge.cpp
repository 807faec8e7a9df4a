// SPDX-License-Identifier: MIT
#include "bridge/ros2bridge.h"

#include "base/logging.h"
#include "bridge/bridgespec.h"
#include "mqtt/mqttlink.h"
#include "ros2/ros2participant.h"
#include "wire/mqttclientwire.h"
#include "wire/ros2bridgewire.h"
#include "wire/ros2definitions.h"

#include <atomic>
#include <functional>
#include <QHash>
#include <QMetaObject>

using namespace Qt::StringLiterals;

namespace {

/// The config's QoS over `base`: reliable or best effort, volatile or transient local ("auto" or
/// nothing keeps the base's; "system_default" is Cyclone's: reliable, volatile), keep last
/// queue_size.
Ros2Qos configQos(const BridgeRoute& r, Ros2Qos base)
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

/// An mqtt2ros mapping's writer: reliable unless best_effort, volatile unless transient_local.
Ros2Qos writerQos(const BridgeRoute& r)
{
    Ros2Qos qos;
    qos.reliability = r.reliability == u"best_effort"_s ? Ros2Qos::BestEffort : Ros2Qos::Reliable;
    qos.durability = r.durability == u"transient_local"_s ? Ros2Qos::TransientLocal : Ros2Qos::Volatile;
    qos.depth = r.queueSize;
    return qos;
}

bool isAuto(const QString& policy)
{
    return policy.isEmpty() || policy == u"auto"_s;
}

RosMsgTypeInfo ros2Type(const QString& name)
{
    return {QString(), name, QString(), false, RosTypeRegistry::Dialect::Ros2};
}

/// The ROS 2 side of the hops: the participant (its DDS process), CDR, mqtt_client v2.5's texts.
/// Publisher ids stand for topics; the participant is asked by topic. Called on the event loop's
/// thread.
class Ros2Side : public BridgeRosSide
{
public:
    Ros2Side(Ros2Participant& ros, const RosTypeRegistry& registry, std::function<QString(const QString&)> resolve)
        : m_ros(ros)
        , m_registry(registry)
        , m_resolve(std::move(resolve))
    {
    }
    RosTypeRegistry::Dialect dialect() const override { return RosTypeRegistry::Dialect::Ros2; }

    Result<int> advertise(const BridgeRoute& r, const RosMsgTypeInfo& t) override
    {
        return advertise(r.rosTopic, t.name, writerQos(r));
    }
    /// Advertising a topic anew replaces its writer (a writer refused meanwhile keeps the old one).
    void retire(int) override {}
    int advertiseStamps(const QString& topic) override
    {
        Ros2Qos qos;
        qos.depth = 1000;
        return advertise(m_resolve(topic), QString::fromLatin1(Ros2BridgeWire::kTimeStampedType), qos)
            .valueOr(-1);
    }
    int advertiseLatency(const QString& rosTopic) override
    {
        // v2.5: "~/latencies/" + ros_topic with its "//" made one, std_msgs/msg/Float64, depth 1
        QString topic = u"~/latencies/"_s + rosTopic;
        topic.replace(u"//"_s, u"/"_s);
        Ros2Qos qos;
        qos.depth = 1;
        return advertise(m_resolve(topic), u"std_msgs/msg/Float64"_s, qos).valueOr(-1);
    }
    QString publisherLine(const BridgeRoute& r, const RosMsgTypeInfo& t) const override
    {
        return Ros2Bridge::tr("MQTT %1 -> ROS %2 (%3, %4)").arg(r.mqttTopic, r.rosTopic, t.name, writerQos(r).text());
    }
    Sent send(int publisher, const QByteArray& cdr) override
    {
        const QString topic = m_topics.value(publisher);
        if (topic.isEmpty() || !m_ros.node().isAdvertised(topic) || cdr.size() < 4)
            return Sent::Failed; // no writer, or not CDR (no encapsulation header)
        // Refused now: the pipe to the DDS process holds its bound, or the process is restarting.
        return m_ros.node().publish(topic, cdr) ? Sent::Ok : Sent::Full;
    }
    void publish(int publisher, const QByteArray& cdr) override
    {
        if (const QString topic = m_topics.value(publisher); !topic.isEmpty())
            m_ros.node().publish(topic, cdr);
    }

    bool startsWithHeader(const RosMsgTypeInfo& type) override
    {
        return Ros2BridgeWire::startsWithHeader(m_registry, type.name);
    }
    std::optional<StampCodec::Decoded> header(const QByteArray& cdr) override
    {
        const std::optional<qint64> stamp = Ros2BridgeWire::headerStampNs(cdr);
        if (!stamp)
            return std::nullopt;
        StampCodec::Decoded d;
        d.sampleNs = *stamp;
        return d;
    }
    QByteArray timeStamped(const StampCodec::Decoded& stamp) override
    {
        return Ros2BridgeWire::encodeTimeStamped(stamp);
    }
    QByteArray float64(double value) override { return Ros2BridgeWire::encodeFloat64(value); }
    std::optional<QByteArray> toText(const BridgeMessage& m) override
    {
        return Ros2BridgeWire::primitiveText(m_registry, m.type.name, m.bytes);
    }
    std::optional<BridgeMessage> fromText(const BridgeRoute& r, const QByteArray& text) override
    {
        if (r.rosType.isEmpty()) {
            Ros2BridgeWire::Typed t = Ros2BridgeWire::primitiveFromText(text);
            return BridgeMessage {ros2Type(t.type), std::move(t.cdr)};
        }
        std::optional<QByteArray> cdr = Ros2BridgeWire::fixedPrimitive(m_registry, r.rosType, text);
        if (!cdr)
            return std::nullopt;
        return BridgeMessage {ros2Type(r.rosType), std::move(*cdr)};
    }
    Result<QByteArray> toJson(const BridgeMessage& m) override
    {
        return Ros2BridgeWire::toJson(m_registry, m.type.name, m.bytes);
    }
    Result<QByteArray> fromJson(const QString& type, const QByteArray& json) override
    {
        return Ros2BridgeWire::fromJson(m_registry, type, json);
    }

    /// The participant refused `topic` while advertise() asked for it: the reason is kept for
    /// advertise() to return (true); otherwise it is the bridge's to handle (false).
    bool takeRefusal(const QString& topic, const QString& why)
    {
        if (topic != m_advertising)
            return false;
        m_refusal = why;
        return true;
    }

private:
    Result<int> advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
    {
        m_advertising = topic;
        m_refusal.clear();
        const bool ok = m_ros.node().advertise(topic, type, qos);
        m_advertising.clear();
        if (!ok)
            return LocatedError {m_refusal};
        const qsizetype id = m_topics.indexOf(topic);
        if (id >= 0)
            return int(id);
        m_topics.append(topic);
        return int(m_topics.size() - 1);
    }

    Ros2Participant& m_ros;
    const RosTypeRegistry& m_registry;
    std::function<QString(const QString&)> m_resolve;
    QStringList m_topics; ///< by publisher id
    QString m_advertising; ///< the topic advertise() is asking for
    QString m_refusal;
};

/// A mapping: its hop, and for ros2mqtt its subscription (the event loop's thread only).
struct Route
{
    std::unique_ptr<BridgeHop> hop;
    QString subscribedType; ///< empty until subscribed
    QString refusedType; ///< a type whose reader was refused: said once
};

} // namespace

struct Ros2Bridge::Private
{
    BridgeHop::Log log;
    BridgeOptions options;
    BridgeSpec spec;
    std::vector<Route> routes;
    BridgeCounters counters;
    RosTypeRegistry registry = Ros2Definitions::registry();
    QString nameSpace = u"/"_s;
    QString name = u"mqtt_client"_s;
    std::unique_ptr<Ros2Participant> ros;
    std::unique_ptr<Ros2Side> side;
    std::unique_ptr<MqttLink> mqtt;
    QHash<QString, Route*> byRosTopic; ///< ros2mqtt
    QHash<QString, BridgeHop*> byMqtt; ///< mqtt2ros data topics
    QHash<QString, BridgeHop*> byTypeTopic; ///< mqtt2ros announcement topics
    std::atomic<qint64> hopBytes {0}; ///< messages from the broker waiting for the event loop

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

    void setupSubscriptions();
    void subscribe(Route& r, const QString& type, const Ros2Qos& qos);
    void fromMqtt(const QString& topic, const QByteArray& payload, qint64 receivedNs);
    void refused(const QString& rosTopic, const QString& why);
    void startMqtt();
};

/// ros2mqtt mappings not subscribed yet: a fixed type with both QoS policies given at once, else
/// as v2.5's setupSubscriptions() does, once a publisher of the topic (of the fixed type, if
/// any) is in the graph, with its QoS under what the config sets.
void Ros2Bridge::Private::setupSubscriptions()
{
    const QString own = fullName();
    for (Route& r : routes) {
        const BridgeRoute& b = r.hop->route();
        if (b.direction != Direction::Ros2Mqtt || !r.subscribedType.isEmpty())
            continue;
        if (!b.rosType.isEmpty() && !isAuto(b.reliability) && !isAuto(b.durability)) {
            subscribe(r, b.rosType, configQos(b, {}));
            continue;
        }
        const Ros2Topic* t = ros->graph().topic(b.rosTopic);
        if (!t)
            continue;
        for (const Ros2Endpoint& pub : t->publishers) {
            if (pub.node == own || (!b.rosType.isEmpty() && pub.type != b.rosType))
                continue;
            const Ros2Qos qos = configQos(b, pub.qos);
            if (ros2QosCompatible(pub.qos, qos)) {
                subscribe(r, pub.type, qos);
                break;
            }
        }
    }
}

void Ros2Bridge::Private::subscribe(Route& r, const QString& type, const Ros2Qos& qos)
{
    const BridgeRoute& b = r.hop->route();
    r.subscribedType = type;
    ros->node().subscribe(b.rosTopic, type, qos);
    log(tr("ROS %1 -> MQTT %2 (%3, %4%5)")
            .arg(b.rosTopic, b.mqttTopic, type, qos.text(),
                 b.primitive ? tr(", primitive") : (b.stamped ? tr(", stamped") : QString())));
}

void Ros2Bridge::Private::fromMqtt(const QString& topic, const QByteArray& payload, qint64 receivedNs)
{
    if (BridgeHop* hop = byTypeTopic.value(topic))
        hop->announce(payload);
    else if (BridgeHop* hop = byMqtt.value(topic))
        hop->fromMqtt(payload, receivedNs);
}

/// The participant refused a mapping's writer or reader (a name DDS may not be given, Cyclone
/// refused it, or the DDS process ended while making it): said once per type, not asked again;
/// the other mappings go on.
void Ros2Bridge::Private::refused(const QString& rosTopic, const QString& why)
{
    if (side && side->takeRefusal(rosTopic, why))
        return; // the hop that asked says it
    for (Route& r : routes) {
        const BridgeRoute& b = r.hop->route();
        if (b.rosTopic != rosTopic)
            continue;
        if (b.direction == Direction::Mqtt2Ros) {
            r.hop->refused(why);
        } else if (r.subscribedType != r.refusedType) {
            r.refusedType = r.subscribedType;
            log(tr("ROS %1 -> MQTT %2: refused: %3").arg(b.rosTopic, b.mqttTopic, why));
        }
    }
}

Ros2Bridge::Ros2Bridge(BridgeHop::Log log)
    : d(std::make_unique<Private>())
{
    d->log = std::move(log);
}

Ros2Bridge::~Ros2Bridge()
{
    stop();
}

Status Ros2Bridge::load(const QByteArray& yaml, const BridgeOptions& options)
{
    Result<BridgeSpec> spec = BridgeSpec::load(yaml, options.brokerUrl, options.args);
    if (!spec)
        return spec.error();
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
    for (BridgeRoute r : d->spec.routes) {
        r.rosTopic = d->resolve(r.rosTopic);
        if (r.primitive && r.json)
            r.json = false; // v2.5: primitive wins
        if (r.primitive || r.json)
            r.stamped = false; // v2.5 injects no stamp into text
        if (r.json && r.rosType.isEmpty())
            return LocatedError {tr("%1: json needs a ros_type, as mqtt_client says").arg(r.mqttTopic)};
        d->routes.push_back({std::make_unique<BridgeHop>(r, d->options, d->counters, d->log), {}, {}});
    }
    return {};
}

QString Ros2Bridge::nodeName() const
{
    return d->fullName();
}

const BridgeCounters& Ros2Bridge::counters() const
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

Status Ros2Bridge::start(const Ros2Options& rosOptions)
{
    d->ros = std::make_unique<Ros2Participant>();
    Private* p = d.get();
    Ros2Participant* ros = d->ros.get();
    QObject::connect(&ros->node(), &Ros2EndpointLink::received, ros, [p](const QString& topic, const Ros2Sample& s) {
        if (Route* r = p->byRosTopic.value(topic))
            r->hop->fromRos({ros2Type(r->subscribedType), s.bytes}, s.receivedNs);
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
    QObject::connect(&ros->node(), &Ros2EndpointLink::endpointRefused, ros,
                     [p](const QString& topic, const QString& why) { p->refused(topic, why); });
    QObject::connect(ros, &Ros2Participant::restarted, ros, [p](const QString& why) {
        p->log(tr("the DDS process %1; starting it again (%2)").arg(why, p->ros->restartText()));
    });
    QObject::connect(ros, &Ros2Participant::restartLoopBroken, ros,
                     [p](const QString& what) { p->log(what); });
    if (Status joined = ros->start(rosOptions); !joined)
        return joined;
    ros->node().setNode(d->nameSpace, d->name);
    d->side = std::make_unique<Ros2Side>(*ros, d->registry, [p](const QString& topic) { return p->resolve(topic); });
    for (Route& r : d->routes) {
        const BridgeRoute& b = r.hop->route();
        if (b.direction == Direction::Ros2Mqtt) {
            d->byRosTopic.insert(b.rosTopic, &r);
        } else {
            d->byMqtt.insert(b.mqttTopic, r.hop.get());
            if (!b.primitive && !b.json)
                d->byTypeTopic.insert(MqttClientWire::typeTopicPrefix() + b.mqttTopic, r.hop.get());
        }
    }
    d->startMqtt();
    for (Route& r : d->routes)
        r.hop->start(*d->side, *d->mqtt); // stamp topics; a fixed type's writer before any message
    d->setupSubscriptions();
    d->log(tr("connecting to %1…").arg(d->spec.profile.url));
    if (Status connected = d->mqtt->connect(10000); !connected)
        return connected;
    d->log(tr("connected to %1").arg(d->spec.profile.url));
    return {};
}

void Ros2Bridge::Private::startMqtt()
{
    MqttLink::Options linkOptions;
    linkOptions.will = spec.will;
    linkOptions.maxQueuedBytes = options.maxQueuedBytes / 2;
    mqtt = std::make_unique<MqttLink>(spec.profile, linkOptions);
    for (auto it = byMqtt.cbegin(); it != byMqtt.cend(); ++it)
        mqtt->addSubscription(it.key(), (*it)->route().qos);
    for (auto it = byTypeTopic.cbegin(); it != byTypeTopic.cend(); ++it)
        mqtt->addSubscription(it.key(), (*it)->route().qos);
    Private* p = this;
    // Towards ROS, half of the bound: a quarter for messages waiting for the event loop, a quarter
    // for those in the pipe to the DDS process.
    const qint64 bound = options.maxQueuedBytes / 4;
    ros->node().setPublishBound(bound);
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
        for (const Route& r : p->routes)
            r.hop->reconnected();
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
    d->side.reset();
    d->ros.reset(); // with the events still queued for it
    d->byRosTopic.clear();
    d->byMqtt.clear();
    d->byTypeTopic.clear();
}
