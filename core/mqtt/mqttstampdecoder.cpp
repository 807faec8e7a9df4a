// SPDX-License-Identifier: MIT
#include "mqttstampdecoder.h"

#include "latency/stampcodec.h"
#include "mqttclientwire.h"

namespace {
/// Cheap test before parsing: a JSON object that mentions "sample".
bool mayBeJsonStamp(const QByteArray& payload)
{
    qsizetype i = 0;
    while (i < payload.size()
           && (payload[i] == ' ' || payload[i] == '\n' || payload[i] == '\r' || payload[i] == '\t'))
        ++i;
    return i < payload.size() && payload[i] == '{' && payload.size() < 4096 && payload.contains("\"sample\"");
}
} // namespace

void MqttStampDecoder::fail(const QString& topic, const QString& why)
{
    ++m_malformed;
    m_lastError = topic + QStringLiteral(": ") + why;
}

void MqttStampDecoder::decode(const std::vector<MqttMessage>& batch, std::vector<StampEvent>& stamps,
                              std::vector<LatencyValue>& latencies)
{
    const QString typePrefix = MqttClientWire::typeTopicPrefix();
    for (const MqttMessage& m : batch) {
        if (m.topic.startsWith(typePrefix)) {
            const QString data = MqttClientWire::dataTopicOf(m.topic);
            if (m.payload.isEmpty()) { // a cleared retained announcement
                m_types.remove(data);
                continue;
            }
            if (const std::optional<RosMsgTypeInfo> info = MqttClientWire::decodeType(m.payload))
                m_types.insert(data, {info->md5 == QLatin1StringView(StampCodec::md5()), info->stamped});
            continue; // the topic tree reports undecodable announcements
        }
        const auto type = m_types.constFind(m.topic);
        if (type != m_types.cend()) {
            QByteArray message = m.payload;
            if (type->stamped) {
                std::optional<MqttClientWire::Stamped> split = MqttClientWire::splitStamped(m.payload);
                if (!split) {
                    fail(m.topic, tr("stamped payload shorter than its 8-byte stamp"));
                    continue;
                }
                latencies.push_back({latencySeries(m.topic), m.receivedNs - split->stampNs, m.receivedNs});
                message = std::move(split->message);
            }
            if (type->timeStamped) {
                QString why;
                if (const auto d = StampCodec::decodeTimeStamped(message, &why))
                    stamps.push_back({m.topic, d->sampleNs, d->timeNs, m.receivedNs});
                else
                    fail(m.topic, why);
            }
            continue;
        }
        if (mayBeJsonStamp(m.payload)) {
            QString why;
            if (const auto d = StampCodec::decodeJson(m.payload, &why))
                stamps.push_back({m.topic, d->sampleNs, d->timeNs, m.receivedNs});
            else
                fail(m.topic, why);
        }
    }
}

void MqttStampDecoder::clear()
{
    m_types.clear();
    m_malformed = 0;
    m_lastError.clear();
}
