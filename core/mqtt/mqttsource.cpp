// SPDX-License-Identifier: MIT
#include "mqttsource.h"

#include "mqtt/mqtttopics.h"
#include "wire/ros2bridgewire.h"

#include <algorithm>

MqttSource::MqttSource(const MqttTopics* topics)
    : m_topics(topics)
{ }

MqttSource::~MqttSource() = default;

void MqttSource::add(const std::vector<MqttMessage>& batch)
{
    if (m_monitored.isEmpty() && m_taps.empty())
        return;
    QHash<QString, QString> types; // a watched topic's announced type, looked up once per batch
    QHash<QString, qint8> stamps; // a monitored topic's injected stamp bytes, once per batch
    qint64 jsonBudget = kMaxJsonBytesPerBatch;
    for (const MqttMessage& m : batch) {
        if (m_heads.active() && m_monitored.contains(m.topic)) {
            auto stamp = stamps.find(m.topic);
            if (stamp == stamps.end()) {
                const auto announced = m_topics->announcedType(m.topic);
                stamp = stamps.insert(m.topic,
                                      announced && announced->stamped
                                          ? qint8(MqttClientWire::stampBytes(announced->dialect))
                                          : qint8(0));
            }
            SourceHead head {SourceGraph::Mqtt, m.topic, m.receivedNs, int(m.payload.size()),
                             m.payload.left(SourceHead::kHeadBytes),
                             // the content after mqtt_client's stamp is the ROS message's (issue 45)
                             ContentKey::ofPayload(m.payload, *stamp), *stamp, std::nullopt};
            // What a primitive link makes of it, when that is not the payload (whose key it has).
            if (m.payload.size() <= PrimitiveText::kMaxRoundTripBytes)
                head.textKey = ContentKey::ofText(PrimitiveText::roundTripChanged(m.payload));
            if (const auto json = m_jsonTypes.constFind(m.topic); json != m_jsonTypes.cend()) {
                // Parsing is the costly part, on the GUI thread: bounded per drain, not only per message.
                jsonBudget -= m.payload.size();
                if (jsonBudget >= 0)
                    head.jsonKey = jsonKey(*json, m.payload);
                else
                    ++m_jsonOverBudget;
            }
            m_heads.deliver(std::move(head));
        }
        if (m_taps.tapped(m.topic)) {
            auto type = types.find(m.topic);
            if (type == types.end()) {
                const auto announced = m_topics->announcedType(m.topic);
                type = types.insert(m.topic, announced ? announced->name : QString());
            }
            m_taps.deliver(SourceArrival {SourceGraph::Mqtt, m.topic, *type, m.receivedNs, m.payload});
        }
    }
}

std::optional<ContentKey> MqttSource::jsonKey(const QString& type, const QByteArray& payload)
{
    // As mqtt_client v2.5 makes the ROS message of it (issue 45): the fields in the JSON, defaults
    // for those it lacks. fromJson() refuses more than kMaxJsonBytes before parsing anything.
    if (m_ros2Types) {
        if (const Result<QByteArray> cdr = Ros2BridgeWire::fromJson(*m_ros2Types, type, payload))
            return ContentKey::of(*cdr);
    }
    ++m_jsonUnconverted;
    return std::nullopt;
}

void MqttSource::monitor(const QString& topic)
{
    ++m_monitored[topic];
}

void MqttSource::unmonitor(const QString& topic)
{
    const auto it = m_monitored.find(topic);
    if (it != m_monitored.end() && --*it <= 0)
        m_monitored.erase(it);
}

bool MqttSource::isMonitored(const QString& topic) const
{
    return m_monitored.contains(topic);
}

QHash<QString, TopicFigures> MqttSource::figures(qint64 nowNs) const
{
    Q_UNUSED(nowNs) // the tree's rates are those of its last tick, on the same drain
    QHash<QString, TopicFigures> out;
    for (auto it = m_monitored.cbegin(); it != m_monitored.cend(); ++it) {
        const auto info = m_topics->info(it.key());
        if (!info)
            continue; // never seen on the broker
        TopicFigures f;
        f.messages = info->messages;
        f.bytes = info->bytes;
        f.lastSize = info->lastSize;
        f.lastNs = info->lastNs;
        f.rateHz = info->rate;
        f.bytesPerSecond = info->messages ? info->rate * double(info->bytes) / double(info->messages) : 0;
        f.type = info->rosType ? info->rosType->name : QString();
        if (info->latencySamples)
            f.lastLatencyMs = info->lastLatencyMs;
        out.insert(it.key(), f);
    }
    return out;
}

std::unique_ptr<HeadTap> MqttSource::openHeadTap(std::size_t maxHeads)
{
    return m_heads.open(maxHeads);
}

std::unique_ptr<Tap> MqttSource::openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    return m_taps.open(topic, maxMessages, maxBytes);
}
