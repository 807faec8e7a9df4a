// SPDX-License-Identifier: MIT
#include "mappinghealthevaluator.h"

#include "ros/rosmasterapi.h"
#include "ros2/ros2graph.h"
#include "session/flowrates.h"
#include "topics/topicfigures.h"

using namespace Qt::StringLiterals;

bool MappingHealthEvaluator::sameType(const QString& a, const QString& b)
{
    auto norm = [](QString t) { return t.replace(u"/msg/"_s, u"/"_s); };
    return norm(a) == norm(b);
}

bool MappingHealthEvaluator::bridgeQos(const Mapping& m, const Ros2Qos& matched, Ros2Qos* qos)
{
    const bool subscription = m.direction == Direction::Ros2Mqtt;
    const QString reliability = m.value(u"advanced.ros.qos.reliability"_s).trimmed();
    const QString durability = m.value(u"advanced.ros.qos.durability"_s).trimmed();
    Ros2Qos q;
    if (reliability == u"reliable"_s || reliability == u"system_default"_s
        || (reliability.isEmpty() && !subscription))
        q.reliability = Ros2Qos::Reliable;
    else if (reliability == u"best_effort"_s)
        q.reliability = Ros2Qos::BestEffort;
    else if (subscription && (reliability.isEmpty() || reliability == u"auto"_s))
        q.reliability = matched.reliability;
    else
        return false;
    if (durability == u"volatile"_s || durability == u"system_default"_s
        || (durability.isEmpty() && !subscription))
        q.durability = Ros2Qos::Volatile;
    else if (durability == u"transient_local"_s)
        q.durability = Ros2Qos::TransientLocal;
    else if (subscription && (durability.isEmpty() || durability == u"auto"_s))
        q.durability = matched.durability;
    else
        return false;
    *qos = q;
    return true;
}

QString MappingHealthEvaluator::qosProblem(const Mapping& m, const Ros2Topic& topic)
{
    const QString fixedType = m.value(u"ros_type"_s).trimmed();
    QStringList why;
    if (m.direction == Direction::Ros2Mqtt) {
        // mqtt_client subscribes when one publisher of the (fixed) type is compatible
        bool candidate = false;
        for (const Ros2Endpoint& pub : topic.publishers) {
            if (!fixedType.isEmpty() && !MappingHealthEvaluator::sameType(fixedType, pub.type))
                continue;
            candidate = true;
            Ros2Qos sub;
            QString reason;
            if (!MappingHealthEvaluator::bridgeQos(m, pub.qos, &sub)
                || ros2QosCompatible(pub.qos, sub, &reason))
                return {};
            why << MappingHealthEvaluator::tr("%1 publishes %2: %3")
                       .arg(pub.node.isEmpty() ? MappingHealthEvaluator::tr("a node") : pub.node,
                            pub.qos.text(), reason);
        }
        return candidate ? why.join(u"; "_s) : QString();
    }
    // mqtt2ros: every subscriber that cannot get the bridge's messages
    Ros2Qos pub;
    if (!MappingHealthEvaluator::bridgeQos(m, {}, &pub))
        return {};
    for (const Ros2Endpoint& sub : topic.subscribers) {
        QString reason;
        if (!ros2QosCompatible(pub, sub.qos, &reason))
            why << MappingHealthEvaluator::tr("%1 subscribes with %2: %3")
                       .arg(sub.node.isEmpty() ? MappingHealthEvaluator::tr("a node") : sub.node,
                            sub.qos.text(), reason);
    }
    return why.join(u"; "_s);
}

namespace {
/// A rate's figure: one decimal below 1000 Hz, so that two rates side by side have one precision.
QString rateFigure(double hz)
{
    return QString::number(hz, 'f', hz < 1000 ? 1 : 0);
}

QString rate(double hz)
{
    return MappingHealthEvaluator::tr("%1 Hz").arg(rateFigure(hz));
}

/// The table's few words for a healthy mapping: `10.0 → 9.9 Hz` when both ends have a rate (one
/// unit for both, so that the destination's rate is not the part a narrow column cuts).
QString flowSummary(const TopicFigures* mon, const QString& rosRate, double mqttHz, bool rosFirst)
{
    if (!mon || !mon->messages) {
        const QString mqttRate = rate(mqttHz);
        return rosFirst ? rosRate + u" → "_s + mqttRate : mqttRate + u" → "_s + rosRate;
    }
    const QString ros = rateFigure(mon->rateHz);
    const QString mqtt = rateFigure(mqttHz);
    return MappingHealthEvaluator::tr("%1 Hz").arg(rosFirst ? ros + u" → "_s + mqtt : mqtt + u" → "_s + ros);
}
} // namespace

QHash<quint64, MappingHealth> MappingHealthEvaluator::evaluate(const BridgeConfig& config, const Inputs& in)
{
    QHash<quint64, MappingHealth> out;
    for (const Mapping& m : config.mappings) {
        MappingHealth h;
        const QString ros = m.rosTopic();
        const QString mqtt = m.mqttTopic();
        const TopicInfo* rosInfo = in.graph ? in.graph->topic(ros) : nullptr;
        const TopicFigures* mqttInfo = nullptr;
        if (in.mqtt) {
            const auto it = in.mqtt->constFind(mqtt);
            if (it != in.mqtt->cend())
                mqttInfo = &*it;
        }
        const bool mqttActive = mqttInfo && in.nowNs - mqttInfo->lastNs <= in.activeWindowNs;
        const TopicFigures* mon = nullptr;
        if (in.monitored) {
            const auto it = in.monitored->constFind(ros);
            if (it != in.monitored->cend())
                mon = &*it;
        }
        const bool rosPublished = rosInfo && !rosInfo->publishers.isEmpty();
        const QString rosRate = mon && mon->messages
            ? rate(mon->rateHz)
            : (rosPublished ? tr("publishers: %1").arg(rosInfo->publishers.size()) : tr("no publisher"));
        const QString mqttRate
            = mqttActive ? rate(mqttInfo->rateHz) : (mqttInfo ? tr("silent") : tr("never seen"));
        if (mqttInfo && mqttInfo->lastLatencyMs)
            h.latencyMs = *mqttInfo->lastLatencyMs;

        if (!in.rosReachable || !in.mqttConnected) {
            h.state = MappingHealth::Unknown;
            h.summary = !in.rosReachable
                ? (in.ros2 ? tr("ROS 2 domain not joined") : tr("ROS master not reachable"))
                : tr("broker not connected");
            h.detail = tr("Connect to the ROS master and the broker on the Discover page to see this "
                          "mapping's traffic.");
            out.insert(m.id, h);
            continue;
        }
        if (m.direction == Direction::Ros2Mqtt) {
            if (!rosInfo) {
                h.state = MappingHealth::Missing;
                h.summary = in.ros2 ? tr("ROS 2 topic not in the graph") : tr("ROS topic not on the master");
                h.detail = in.ros2 ? tr("Nobody publishes or subscribes '%1' on this ROS 2 domain.").arg(ros)
                                   : tr("Nobody publishes or subscribes '%1' on this master.").arg(ros);
            } else if (!rosPublished) {
                h.state = MappingHealth::Idle;
                h.summary = tr("no publisher on ROS");
                h.detail = tr("'%1' exists but nobody publishes it, so there is nothing to bridge.").arg(ros);
            } else if (!mqttActive) {
                h.state = MappingHealth::NoBridge;
                h.summary = tr("no bridge running?");
                h.detail = tr("'%1' is published (%2) but nothing arrived on '%3' in the last %4 s.")
                               .arg(ros, rosRate, mqtt)
                               .arg(in.activeWindowNs / 1000000000);
            } else {
                h.state = MappingHealth::Healthy;
                h.summary = flowSummary(mon, rosRate, mqttInfo->rateHz, true);
                h.detail = tr("'%1' (%2) arrives on '%3' (%4).").arg(ros, rosRate, mqtt, mqttRate);
            }
        } else {
            if (!mqttInfo) {
                h.state = MappingHealth::Missing;
                h.summary = tr("MQTT topic never seen");
                h.detail = tr("Nothing has been published on '%1' since Bridgescope connected.").arg(mqtt);
            } else if (!mqttActive) {
                h.state = MappingHealth::Idle;
                h.summary = tr("MQTT topic silent");
                h.detail = tr("'%1' has been silent for %2 s.")
                               .arg(mqtt)
                               .arg((in.nowNs - mqttInfo->lastNs) / 1000000000);
            } else if (!rosPublished) {
                h.state = MappingHealth::NoBridge;
                h.summary = tr("no bridge running?");
                h.detail = tr("'%1' carries %2 but nobody publishes '%3' on ROS.").arg(mqtt, mqttRate, ros);
            } else {
                h.state = MappingHealth::Healthy;
                h.summary = flowSummary(mon, rosRate, mqttInfo->rateHz, false);
                h.detail = tr("'%1' (%2) is published on '%3' (%4).").arg(mqtt, mqttRate, ros, rosRate);
            }
        }
        if (h.state == MappingHealth::Healthy)
            rateOverOneWindow(m, in, &h);
        overrule(m, rosInfo, mqttInfo, in, &h);
        out.insert(m.id, h);
    }
    return out;
}

void MappingHealthEvaluator::rateOverOneWindow(const Mapping& m, const Inputs& in, MappingHealth* h)
{
    const std::optional<FlowRates::Flow> f
        = in.flows ? in.flows->flow(m.rosTopic(), m.mqttTopic()) : std::nullopt;
    if (!f)
        return;
    const bool out = m.direction == Direction::Ros2Mqtt;
    const quint64 sent = out ? f->rosMessages : f->mqttMessages;
    const quint64 arrived = out ? f->mqttMessages : f->rosMessages;
    const QString from = out ? m.rosTopic() : m.mqttTopic();
    const QString to = out ? m.mqttTopic() : m.rosTopic();
    const double seconds = double(f->spanNs) / 1e9;
    const double sentHz = double(sent) / seconds;
    // A message in flight at an edge of the interval is counted on one side only: one message
    // more or less is the count's resolution, not a faster or slower destination.
    const bool sameCount = arrived + 1 >= sent && arrived <= sent + 1;
    const double arrivedHz = sameCount ? sentHz : double(arrived) / seconds;
    h->summary = tr("%1 Hz").arg(rateFigure(sentHz) + u" → "_s + rateFigure(arrivedHz));
    QString detail = tr("Over the same %1 s, %2 messages were published on '%3' and %4 arrived on '%5'.")
                         .arg(QString::number(seconds, 'f', 1), QString::number(sent), from,
                              QString::number(arrived), to); // one arg(): names are not patterns
    if (sameCount && arrived != sent)
        detail += u' ' + tr("One message in flight at the interval's edge is counted on one side only.");
    else if (arrived > sent)
        detail
            += u' ' + tr("More arrive than are published: does something else publish on '%1' too?").arg(to);
    h->detail = detail;
}

void MappingHealthEvaluator::overrule(const Mapping& m, const TopicInfo* rosInfo, const TopicFigures* mqttInfo,
                                      const Inputs& in, MappingHealth* h)
{
    const QString ros = m.rosTopic();
    const QString mqtt = m.mqttTopic();
    // A type announcement that contradicts the ROS graph outranks everything but a missing side.
    if (rosInfo && mqttInfo && !mqttInfo->type.isEmpty() && !rosInfo->type.isEmpty()
        && !sameType(mqttInfo->type, rosInfo->type)) {
        h->state = MappingHealth::TypeMismatch;
        h->summary = tr("type mismatch");
        h->detail = tr("The broker announces '%1' for '%2', but '%3' has type '%4' on ROS.")
                       .arg(mqttInfo->type, mqtt, ros, rosInfo->type);
    }
    // A QoS that keeps the bridge's ROS 2 endpoint from matching explains any silence.
    if (in.ros2 && h->state != MappingHealth::Missing) {
        if (const Ros2Topic* t = in.ros2->topic(ros)) {
            if (const QString why = qosProblem(m, *t); !why.isEmpty()) {
                h->state = MappingHealth::QosMismatch;
                h->summary = tr("QoS incompatible");
                h->detail = m.direction == Direction::Ros2Mqtt
                    ? tr("mqtt_client's subscription to '%1' cannot match a publisher: %2. Set "
                         "advanced.ros.qos to auto or to what the publishers offer.")
                          .arg(ros, why)
                    : tr("Subscribers of '%1' cannot get mqtt_client's messages: %2. Offer at least what "
                         "they "
                         "ask for in advanced.ros.qos.")
                          .arg(ros, why);
            }
        }
    }
    if (h->latencyMs >= 0 && h->state == MappingHealth::Healthy) {
        h->summary += u" · "_s + tr("%1 ms").arg(h->latencyMs, 0, 'f', 1);
        h->detail
            += u"\n"_s + tr("Last one-way latency on the broker: %1 ms.").arg(h->latencyMs, 0, 'f', 1);
    }
}
