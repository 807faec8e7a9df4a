// SPDX-License-Identifier: MIT
#include "referencebridge.h"

#include "base/logging.h"
#include "bridge/bridgespec.h"
#include "mqtt/mqttlink.h"
#include "ros/rosendpoint.h"
#include "wire/mqttclientwire.h"
#include "wire/primitivetext.h"
#include "wire/stampcodec.h"

#include <cmath>
#include <cstring>
#include <QCryptographicHash>
#include <QRegularExpression>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
/// A std_msgs primitive of mqtt_client's ROS 1 mqtt2primitive(): its bytes and its type.
RosRawMessage primitiveMessage(const QString& field, const QByteArray& bytes)
{
    const QString name = field.front().toUpper() + field.mid(1);
    const QString definition = field + u" data\n"_s;
    // For a message without dependencies ROS hashes its definition's field lines.
    const QString md5 = QString::fromLatin1(
        QCryptographicHash::hash(definition.trimmed().toUtf8(), QCryptographicHash::Md5).toHex());
    return {bytes, u"std_msgs/"_s + (field == u"string"_s ? u"String"_s : name), md5, definition};
}

} // namespace

namespace PrimitiveText {
std::optional<QByteArray> toText(const QString& type, const QByteArray& bytes)
{
    return ofRos1(type, bytes);
}

RosRawMessage fromText(const QByteArray& text)
{
    const PrimitiveText::Parsed p = PrimitiveText::parse(text);
    QByteArray b(4, Qt::Uninitialized);
    switch (p.kind) {
    case PrimitiveText::Parsed::Kind::Bool:
        return primitiveMessage(u"bool"_s, QByteArray(1, p.boolean ? '\1' : '\0'));
    case PrimitiveText::Parsed::Kind::Int32:
        qToLittleEndian(p.integer, b.data());
        return primitiveMessage(u"int32"_s, b);
    case PrimitiveText::Parsed::Kind::Float32:
        qToLittleEndian(p.real, b.data());
        return primitiveMessage(u"float32"_s, b);
    case PrimitiveText::Parsed::Kind::String:
        break;
    }
    qToLittleEndian(quint32(text.size()), b.data());
    return primitiveMessage(u"string"_s, b + text);
}
} // namespace PrimitiveText

namespace {
constexpr const char* kFloat64Md5 = "fdb28210bfa9d7c91146260178d9a584";

/// Whether a message definition starts with a Header field.
bool definitionStartsWithHeader(const QString& definition)
{
    static const QRegularExpression headerFirst(u"^\\s*(#[^\\n]*\\n\\s*)*(std_msgs/)?Header\\s+\\w+"_s);
    return headerFirst.match(definition).hasMatch();
}

/// The ROS 1 side of the hops: a roscpp node, ROS serialization, mqtt_client v2.2.1's texts.
class Ros1Side : public BridgeRosSide
{
public:
    explicit Ros1Side(RosEndpoint& ros)
        : m_ros(ros)
    { }
    RosTypeRegistry::Dialect dialect() const override { return RosTypeRegistry::Dialect::Ros1; }

    Result<int> advertise(const BridgeRoute& r, const RosMsgTypeInfo& t) override
    {
        return m_ros.advertise(r.rosTopic, t.name, t.md5, t.definition, r.queueSize, r.latched);
    }
    void retire(int publisher) override { m_ros.retire(publisher); }
    int advertiseStamps(const QString& topic) override
    {
        return m_ros
            .advertise(topic, QString::fromLatin1(StampCodec::typeName()),
                       QString::fromLatin1(StampCodec::md5()), StampCodec::definition(), 1000, false)
            .valueOr(-1);
    }
    int advertiseLatency(const QString& rosTopic) override
    {
        return m_ros
            .advertise(m_ros.resolve(u"~/latencies/"_s + rosTopic), u"std_msgs/Float64"_s,
                       QString::fromLatin1(kFloat64Md5), u"float64 data\n"_s, 1, false)
            .valueOr(-1);
    }
    QString publisherLine(const BridgeRoute& r, const RosMsgTypeInfo& t) const override
    {
        return ReferenceBridge::tr("MQTT %1 -> ROS %2 (%3%4)")
            .arg(r.mqttTopic, r.rosTopic, t.name, t.stamped ? ReferenceBridge::tr(", stamped") : QString());
    }
    Sent send(int publisher, const QByteArray& bytes) override
    {
        const RosEndpoint::Sent sent = m_ros.send(publisher, bytes);
        return sent == RosEndpoint::Sent::Ok  ? Sent::Ok
            : sent == RosEndpoint::Sent::Full ? Sent::Full
                                              : Sent::Failed;
    }
    void publish(int publisher, const QByteArray& bytes) override
    {
        if (publisher >= 0)
            m_ros.publish(publisher, bytes);
    }

    bool startsWithHeader(const RosMsgTypeInfo& type) override
    {
        return definitionStartsWithHeader(type.definition);
    }
    std::optional<StampCodec::Decoded> header(const QByteArray& bytes) override
    {
        return StampCodec::decodeHeader(bytes);
    }
    QByteArray timeStamped(const StampCodec::Decoded& stamp) override
    {
        return StampCodec::encodeTimeStamped(stamp);
    }
    QByteArray float64(double value) override
    {
        QByteArray bytes(8, Qt::Uninitialized);
        std::memcpy(bytes.data(), &value, 8);
        return bytes;
    }
    std::optional<QByteArray> toText(const BridgeMessage& m) override
    {
        return PrimitiveText::toText(m.type.name, m.bytes);
    }
    std::optional<BridgeMessage> fromText(const BridgeRoute&, const QByteArray& text) override
    {
        RosRawMessage m = PrimitiveText::fromText(text);
        return BridgeMessage {{m.md5, m.type, m.definition, false}, std::move(m.bytes)};
    }

private:
    RosEndpoint& m_ros;
};
} // namespace

struct ReferenceBridge::Private
{
    Log log;
    Options options;
    MqttProfile profile;
    MqttWill will;
    std::vector<std::unique_ptr<BridgeHop>> hops;
    Counters counters;
    std::unique_ptr<RosEndpoint> ros;
    std::unique_ptr<Ros1Side> side;
    std::unique_ptr<MqttLink> mqtt;
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
    return int(d->hops.size());
}

Status ReferenceBridge::load(const QByteArray& yaml, const Options& options)
{
    Result<BridgeSpec> spec = BridgeSpec::load(yaml, options.brokerUrl, options.args);
    if (!spec)
        return spec.error();
    d->options = options;
    d->profile = spec->profile;
    d->will = spec->will;
    d->hops.clear();
    for (BridgeRoute r : spec->routes) {
        r.json = false; // mqtt_client v2.2.1 knows neither
        r.rosType.clear();
        d->hops.push_back(std::make_unique<BridgeHop>(r, d->options, d->counters, d->log));
    }
    return {};
}

Status ReferenceBridge::start(const std::function<bool()>& keepWaiting)
{
    d->ros = std::make_unique<RosEndpoint>();
    d->ros->setNoticeHandler(d->log);
    d->ros->setMaxHeldBytes(d->options.maxQueuedBytes / 2);
    qCDebug(lcBridge) << "ROS 1 bridge: at most" << d->options.maxQueuedBytes / 2
                      << "bytes held towards ROS and as many towards the broker";
    const QString name = d->options.nodeName.isEmpty() ? u"mqtt_client"_s : d->options.nodeName;
    d->log(tr("waiting for the ROS master…"));
    if (Status started = d->ros->start(name, d->options.rosMaster, keepWaiting); !started)
        return started;
    d->log(tr("ROS node %1 started").arg(d->ros->nodeName()));

    MqttLink::Options linkOptions;
    linkOptions.will = d->will;
    linkOptions.maxQueuedBytes = d->options.maxQueuedBytes / 2;
    d->mqtt = std::make_unique<MqttLink>(d->profile, linkOptions);
    d->side = std::make_unique<Ros1Side>(*d->ros);
    Private* p = d.get();
    QHash<QString, BridgeHop*> byMqtt;
    QHash<QString, BridgeHop*> byTypeTopic;
    for (const auto& hop : d->hops) {
        hop->start(*d->side, *d->mqtt);
        const BridgeRoute& r = hop->route();
        if (r.direction != Direction::Mqtt2Ros)
            continue;
        byMqtt.insert(r.mqttTopic, hop.get());
        d->mqtt->addSubscription(r.mqttTopic, r.qos);
        if (!r.primitive) {
            byTypeTopic.insert(MqttClientWire::typeTopicPrefix() + r.mqttTopic, hop.get());
            d->mqtt->addSubscription(MqttClientWire::typeTopicPrefix() + r.mqttTopic, r.qos);
        } else {
            d->log(tr("MQTT %1 -> ROS %2 (primitive)").arg(r.mqttTopic, r.rosTopic));
        }
    }
    d->mqtt->setMessageHandler(
        [byMqtt, byTypeTopic](const QString& topic, const QByteArray& payload, qint64 t) {
            if (BridgeHop* hop = byTypeTopic.value(topic))
                hop->announce(payload);
            else if (BridgeHop* hop = byMqtt.value(topic))
                hop->fromMqtt(payload, t);
        });
    d->mqtt->setConnectedHandler([p](bool reconnect) {
        if (!reconnect)
            return;
        for (const auto& hop : p->hops)
            hop->reconnected();
        p->log(tr("reconnected to %1").arg(p->profile.url));
    });
    d->mqtt->setLostHandler([p](const QString& why) {
        p->log(tr("lost the broker (%1); reconnecting").arg(why.isEmpty() ? u"?"_s : why));
    });
    d->log(tr("connecting to %1…").arg(d->profile.url));
    if (Status connected = d->mqtt->connect(10000); !connected)
        return connected;
    d->log(tr("connected to %1").arg(d->profile.url));

    for (const auto& h : d->hops) {
        const BridgeRoute& r = h->route();
        if (r.direction != Direction::Ros2Mqtt)
            continue;
        BridgeHop* hop = h.get();
        if (Status subscribed
            = d->ros->subscribe(r.rosTopic, r.queueSize,
                                [hop](const RosRawMessage& m, qint64 t) {
                                    hop->fromRos({{m.md5, m.type, m.definition, false}, m.bytes}, t);
                                });
            !subscribed)
            return LocatedError {
                tr("cannot subscribe to %1: %2").arg(r.rosTopic, subscribed.error().toString())};
        d->log(tr("ROS %1 -> MQTT %2%3")
                   .arg(r.rosTopic, r.mqttTopic,
                        r.primitive ? tr(" (primitive)") : (r.stamped ? tr(" (stamped)") : QString())));
    }
    return {};
}

void ReferenceBridge::stop()
{
    counters(); // the last figures of the queues, kept
    if (d->mqtt)
        d->mqtt->disconnect();
    if (d->ros)
        d->ros->shutdown();
    d->mqtt.reset();
    d->side.reset();
    d->ros.reset();
}
