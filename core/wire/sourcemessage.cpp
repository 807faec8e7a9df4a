// SPDX-License-Identifier: MIT
#include "sourcemessage.h"

std::optional<RosValue> SourceMessage::decode(const RosTypeRegistry& registry, const SourceType& type,
                                              const QByteArray& bytes, QString* error,
                                              const RosDecodeLimits& limits)
{
    switch (type.graph) {
    case SourceGraph::Ros1:
        return RosMessageDecoder::decode(registry, type.type, bytes, error, limits);
    case SourceGraph::Ros2:
        return RosMessageDecoder::decodeCdr(registry, type.type, bytes, error, limits);
    case SourceGraph::Mqtt:
        break;
    }
    if (type.announced)
        return MqttClientWire::decodePayload(registry, *type.announced, bytes, error, limits);
    if (error)
        *error = tr("no ROS type was announced for it");
    return std::nullopt;
}

std::optional<StampCodec::Decoded> SourceMessage::decodeStamp(SourceGraph graph, const QByteArray& bytes,
                                                              QString* error)
{
    return graph == SourceGraph::Ros2 ? StampCodec::decodeTimeStampedCdr(bytes, error)
                                      : StampCodec::decodeTimeStamped(bytes, error);
}

std::optional<qint64> SourceMessage::decodeLatency(SourceGraph graph, const QByteArray& bytes)
{
    return graph == SourceGraph::Ros2 ? StampCodec::decodeFloat64SecondsCdr(bytes)
                                      : StampCodec::decodeFloat64Seconds(bytes);
}

StampReading SourceMessage::readStamp(const SourceArrival& a, bool latency)
{
    StampReading r;
    if (latency) {
        if (const std::optional<qint64> ns = decodeLatency(a.graph, a.bytes))
            r.latency = LatencyValue {a.topic, *ns, a.receivedNs};
        else
            r.error = tr("a latency that is no finite number of seconds");
    } else if (const auto d = decodeStamp(a.graph, a.bytes, &r.error)) {
        r.stamp = StampEvent {a.topic, d->sampleNs, d->timeNs, a.receivedNs};
    }
    return r;
}

QString SourceMessage::stampType(SourceGraph graph)
{
    return QLatin1StringView(graph == SourceGraph::Ros2 ? StampCodec::ros2TypeName() : StampCodec::typeName());
}
