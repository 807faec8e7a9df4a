// SPDX-License-Identifier: MIT
#include "mqttstampdecoder.h"

#include "wire/mqttclientwire.h"
#include "wire/sourcemessage.h"

#include <algorithm>
#include <string_view>

namespace {
/// Cheap test before parsing: a JSON object that mentions "sample" near its start. A larger one is
/// then refused by decodeJson() (and counted), never parsed.
bool mayBeJsonStamp(const QByteArray& payload)
{
    qsizetype i = 0;
    while (i < payload.size()
           && (payload[i] == ' ' || payload[i] == '\n' || payload[i] == '\r' || payload[i] == '\t'))
        ++i;
    return i < payload.size() && payload[i] == '{'
        && std::string_view(payload.constData(),
                            std::size_t(std::min<qsizetype>(payload.size(), 2 * StampCodec::kMaxJsonBytes)))
               .find("\"sample\"")
        != std::string_view::npos;
}
} // namespace

void MqttStampDecoder::fail(const QString& topic, const QString& why)
{
    ++m_malformed;
    ++m_malformedByTopic[topic];
    m_lastError = topic + QStringLiteral(": ") + why;
}

bool MqttStampDecoder::isTimeStamped(const RosMsgTypeInfo& info)
{
    return info.dialect == RosTypeRegistry::Dialect::Ros2
        ? RosTypeRegistry::ros2TypeName(info.name) == QLatin1StringView(StampCodec::ros2TypeName())
        : info.md5 == QLatin1StringView(StampCodec::md5());
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
            if (const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(m.payload); info)
                m_types.insert(data, {isTimeStamped(*info), info->stamped, info->dialect});
            else if (m_types.contains(data) || m.payload.contains(StampCodec::typeName()))
                fail(data,
                     tr("type announcement: %1")
                         .arg(info.error().toString())); // one meant for stamps, or replacing one
            continue; // the topic tree reports every undecodable announcement
        }
        const auto type = m_types.constFind(m.topic);
        if (type != m_types.cend()) {
            QByteArray message = m.payload;
            if (type->stamped) {
                Result<MqttClientWire::Stamped> split
                    = MqttClientWire::splitStamped(m.payload, type->dialect);
                if (!split) {
                    fail(m.topic, split.error().toString());
                    continue;
                }
                latencies.push_back({latencySeries(m.topic), m.receivedNs - split->stampNs, m.receivedNs});
                message = std::move(split->message);
            }
            if (type->timeStamped) {
                const SourceGraph graph
                    = type->dialect == RosTypeRegistry::Dialect::Ros2 ? SourceGraph::Ros2 : SourceGraph::Ros1;
                if (const Result<StampCodec::Decoded> d = SourceMessage::decodeStamp(graph, message); d)
                    stamps.push_back({m.topic, d->sampleNs, d->timeNs, m.receivedNs});
                else
                    fail(m.topic, d.error().toString());
            }
            continue;
        }
        if (mayBeJsonStamp(m.payload)) {
            if (const Result<StampCodec::Decoded> d = StampCodec::decodeJson(m.payload); d)
                stamps.push_back({m.topic, d->sampleNs, d->timeNs, m.receivedNs});
            else
                fail(m.topic, d.error().toString());
        }
    }
}

void MqttStampDecoder::takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies)
{
    stamps.insert(stamps.end(), std::make_move_iterator(m_stamps.begin()), std::make_move_iterator(m_stamps.end()));
    latencies.insert(latencies.end(), m_latencies.begin(), m_latencies.end());
    m_stamps.clear();
    m_latencies.clear();
}

void MqttStampDecoder::clear()
{
    m_types.clear();
    m_malformed = 0;
    m_malformedByTopic.clear();
    m_lastError.clear();
}
