// SPDX-License-Identifier: MIT
#include "sourcemessage.h"

Result<RosValue> SourceMessage::decode(const RosTypeRegistry& registry, const SourceType& type,
                                       const QByteArray& bytes, const RosDecodeLimits& limits)
{
    switch (type.graph) {
    case SourceGraph::Ros1:
        return RosMessageDecoder::decode(registry, type.type, bytes, limits);
    case SourceGraph::Ros2:
        return RosMessageDecoder::decodeCdr(registry, type.type, bytes, limits);
    case SourceGraph::Mqtt:
        break;
    }
    if (type.announced)
        return MqttClientWire::decodePayload(registry, *type.announced, bytes, limits);
    return LocatedError {tr("no ROS type was announced for it")};
}

Result<StampCodec::Decoded> SourceMessage::decodeStamp(SourceGraph graph, const QByteArray& bytes)
{
    return graph == SourceGraph::Ros2 ? StampCodec::decodeTimeStampedCdr(bytes)
                                      : StampCodec::decodeTimeStamped(bytes);
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
    } else if (const Result<StampCodec::Decoded> d = decodeStamp(a.graph, a.bytes); d) {
        r.stamp = StampEvent {a.topic, d->sampleNs, d->timeNs, a.receivedNs};
    } else {
        r.error = d.error().toString();
    }
    return r;
}

QString SourceMessage::stampType(SourceGraph graph)
{
    return QLatin1StringView(graph == SourceGraph::Ros2 ? StampCodec::ros2TypeName() : StampCodec::typeName());
}

SourceHead SourceHead::ofRos(SourceGraph graph, const QString& topic, QStringView type, qint64 receivedNs,
                             const QByteArray& bytes)
{
    const bool ros2 = graph == SourceGraph::Ros2;
    return SourceHead {
        graph,
        topic,
        receivedNs,
        int(bytes.size()),
        ros2 ? bytes.mid(4, kHeadBytes) : bytes.left(kHeadBytes),
        ContentKey::of(bytes),
        0,
        ContentKey::ofText(ros2 ? PrimitiveText::ofCdr(type, bytes) : PrimitiveText::ofRos1(type, bytes))};
}
