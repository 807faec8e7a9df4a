// SPDX-License-Identifier: MIT
#include "peerconfig.h"

#include "text/topicnames.h"

using namespace Qt::StringLiterals;

PeerConfig::Result PeerConfig::make(const BridgeConfig& config, const QString& clientId)
{
    Result r;
    BridgeConfig& peer = r.config;
    peer.layout = config.layout;
    peer.ros2NodeName = config.ros2NodeName;
    peer.broker.values = config.broker.values;
    peer.broker.extras = config.broker.extras;
    peer.client.values = config.client.values;
    peer.client.extras = config.client.extras;
    peer.rootExtras = config.rootExtras;
    peer.bridgeExtras = config.bridgeExtras;
    peer.documentExtras = config.documentExtras;

    const QString oldId = config.client.values.text(u"id"_s);
    QString newId = clientId;
    if (newId.isEmpty() && !oldId.isEmpty())
        newId = oldId + u"_peer"_s;
    if (newId.isEmpty())
        peer.client.values.remove(u"id"_s);
    else
        peer.client.values.setText(u"id"_s, newId);
    const QString will = config.client.values.text(u"last_will.topic"_s);
    if (!will.isEmpty()) {
        if (!oldId.isEmpty() && will.contains(oldId)) {
            peer.client.values.setText(u"last_will.topic"_s, QString(will).replace(oldId, newId));
        } else {
            r.notes
                << tr("client.last_will.topic '%1' is kept; both ends would announce their death on the same "
                      "topic.")
                       .arg(will);
        }
    }

    static const QStringList carried = {u"primitive"_s,
                                        u"json"_s,
                                        u"ros_type"_s,
                                        u"advanced.ros.queue_size"_s,
                                        u"advanced.ros.qos.reliability"_s,
                                        u"advanced.ros.qos.durability"_s,
                                        u"advanced.mqtt.qos"_s};
    for (const Mapping& m : config.mappings) {
        const bool out = m.direction == Direction::Ros2Mqtt;
        if (out && TopicNames::hasWildcard(m.mqttTopic())) {
            r.notes << tr("ros2mqtt '%1' publishes on '%2', which has a wildcard; it has no peer mapping.")
                           .arg(m.rosTopic(), m.mqttTopic());
            continue;
        }
        if (!out && TopicNames::hasWildcard(m.mqttTopic())) {
            r.notes
                << tr("mqtt2ros '%1' is a wildcard subscription; the peer cannot publish on it, so it has no "
                      "peer mapping.")
                       .arg(m.mqttTopic());
            continue;
        }
        Mapping p
            = Mapping::create(out ? Direction::Mqtt2Ros : Direction::Ros2Mqtt, m.rosTopic(), m.mqttTopic());
        for (const QString& path : carried)
            p.block.values.copyFrom(m.block.values, path);
        // A retained MQTT message and a latched ROS topic both give late subscribers the last value.
        if (out && m.isSet(u"advanced.mqtt.retained"_s))
            p.set(u"advanced.ros.latched"_s, m.value(u"advanced.mqtt.retained"_s));
        if (!out && m.isSet(u"advanced.ros.latched"_s))
            p.set(u"advanced.mqtt.retained"_s, m.value(u"advanced.ros.latched"_s));
        if (out && m.isSet(u"inject_timestamp"_s)) {
            r.notes << tr("'%1' is stamped: the peer publishes its latency on ~/latencies%2.")
                           .arg(m.mqttTopic(),
                                m.rosTopic().startsWith(u'/') ? m.rosTopic() : u'/' + m.rosTopic());
        }
        if (m.isSet(u"timestamp_topic_prefix"_s)) {
            r.notes
                << tr("timestamp_topic_prefix of '%1' names this host's stamps; set the peer's own prefix by "
                      "hand.")
                       .arg(m.sourceTopic());
        }
        p.block.extras = m.block.extras;
        peer.mappings.append(p);
    }
    return r;
}
