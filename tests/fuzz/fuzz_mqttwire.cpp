// SPDX-License-Identifier: MIT
// Fuzz target for what mqtt_client puts on the broker: the retained type announcement
// (`mqtt_client/ros_msg_type/<topic>`; ROS 1 serialization, or CDR from mqtt_client for ROS 2), the
// stamped payload on `<topic>` (an 8-byte ROS 1 stamp or a 12-byte CDR one), the message decoded
// with the announced type, and the stamp decoder that reads a batch of both.
//
// Input: a 16-bit little-endian length, that many bytes of type announcement, then the payload.
// The payload is also a primitive link's (issue 45): its text as mqtt_client reads it back, and the
// text of each std_msgs primitive whose ROS 1 or CDR bytes it may be.
// Properties: a decoded announcement encodes to bytes that decode to the same announcement; a
// stamped payload split and joined again gives the same stamp and message (and the same bytes,
// where the stamp was written as Bridgescope writes it); errors come with a message.
#include "fuzzcheck.h"
#include "mqtt/mqttstampdecoder.h"
#include "wire/mqttclientwire.h"
#include "wire/primitivetext.h"
#include "wire/ros2bridgewire.h"
#include "wire/rosmessage.h"

namespace {
using Dialect = RosTypeRegistry::Dialect;

/// A few ROS 2 definitions (the fuzz build has no resources): enough for the names a seed or the
/// dictionary announces; an announcement may bring its own definition as well.
const RosTypeRegistry& ros2Types()
{
    static const RosTypeRegistry registry = [] {
        RosTypeRegistry r(Dialect::Ros2);
        (void)r.addDefinition(QStringLiteral("builtin_interfaces/msg/Time"),
                              QStringLiteral("int32 sec\nuint32 nanosec\n"));
        (void)r.addDefinition(QStringLiteral("std_msgs/msg/Header"),
                              QStringLiteral("builtin_interfaces/Time stamp\nstring frame_id\n"));
        (void)r.addDefinition(QStringLiteral("std_msgs/msg/String"), QStringLiteral("string data\n"));
        (void)r.addDefinition(QStringLiteral("geometry_msgs/msg/Point"),
                              QStringLiteral("float64 x\nfloat64 y\nfloat64 z\n"));
        (void)r.addDefinition(QStringLiteral("geometry_msgs/msg/Quaternion"),
                              QStringLiteral("float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"));
        (void)r.addDefinition(QStringLiteral("geometry_msgs/msg/Pose"),
                              QStringLiteral("Point position\nQuaternion orientation\n"));
        (void)r.addDefinition(QStringLiteral("geometry_msgs/msg/PoseStamped"),
                              QStringLiteral("std_msgs/Header header\nPose pose\n"));
        return r;
    }();
    return registry;
}

void splitAndJoin(const QByteArray& payload, Dialect dialect)
{
    const Result<MqttClientWire::Stamped> split = MqttClientWire::splitStamped(payload, dialect);
    if (!split) {
        FUZZ_CHECK(!split.error().toString().isEmpty(), "a stamped payload rejected without a message");
        return;
    }
    const QByteArray joined = MqttClientWire::stamped(split->stampNs, split->message, dialect);
    const Result<MqttClientWire::Stamped> again = MqttClientWire::splitStamped(joined, dialect);
    FUZZ_CHECK(again && again->stampNs == split->stampNs && again->message == split->message,
               "a stamped payload changes when split and joined");
    // ROS 2 stamps are read in either byte order and with any options, written little-endian.
    if (dialect == Dialect::Ros1 || payload.startsWith(QByteArrayView("\x00\x01\x00\x00", 4)))
        FUZZ_CHECK(joined == payload, "a stamped payload's bytes change when split and joined");
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 2)
        return 0;
    const size_t typeSize = std::min<size_t>(size - 2, size_t(data[0]) | size_t(data[1]) << 8);
    const QByteArray announcement = fuzz::bytes(data + 2, typeSize);
    const QByteArray payload = fuzz::bytes(data + 2 + typeSize, size - 2 - typeSize);

    const Result<RosMsgTypeInfo> info = MqttClientWire::decodeType(announcement);
    if (!info)
        FUZZ_CHECK(!info.error().toString().isEmpty(), "an announcement rejected without a message");
    else
        FUZZ_CHECK(info->dialect == MqttClientWire::dialectOf(announcement),
                   "an announcement of the other dialect");

    splitAndJoin(payload, Dialect::Ros1);
    splitAndJoin(payload, Dialect::Ros2);

    const QByteArray text = PrimitiveText::roundTrip(payload);
    if (payload.size() > PrimitiveText::kMaxRoundTripBytes)
        FUZZ_CHECK(text == payload, "a long payload read back as another text");
    FUZZ_CHECK(PrimitiveText::roundTripChanged(payload).value_or(payload) == text,
               "a payload's text read back differs from its change");
    for (const char* type :
         {"String", "Bool", "Char", "Int16", "UInt32", "Int64", "Float32", "Float64", "UInt8MultiArray"}) {
        const QString ros1 = QStringLiteral("std_msgs/") + QString::fromLatin1(type);
        const QString ros2 = QStringLiteral("std_msgs/msg/") + QString::fromLatin1(type);
        for (const std::optional<QByteArray>& t :
             {PrimitiveText::ofRos1(ros1, payload), PrimitiveText::ofCdr(ros2, payload)})
            FUZZ_CHECK(!t || t->size() <= payload.size() + 400,
                       "a primitive's text longer than its bytes allow");
    }

    if (info) {
        const QByteArray encoded = MqttClientWire::encodeType(*info);
        const Result<RosMsgTypeInfo> again = MqttClientWire::decodeType(encoded);
        FUZZ_CHECK(again && *again == *info, "an announcement does not survive encode and decode");

        // The payload as the announced type: ROS 1 with the announced definition, ROS 2 with the
        // known definitions (and the announced one, when there is one).
        RosTypeRegistry registry(info->dialect);
        bool known = false;
        if (info->dialect == Dialect::Ros2) {
            registry = ros2Types();
            if (!info->definition.isEmpty())
                (void)registry.addDefinition(info->name, info->definition); // contains() tells
            known = registry.contains(RosTypeRegistry::ros2TypeName(info->name));
        } else {
            const Result<void> added = registry.addDefinition(info->name, info->definition);
            known = added.ok();
        }
        if (known) {
            if (const Result<RosValue> value = MqttClientWire::decodePayload(registry, *info, payload);
                !value)
                FUZZ_CHECK(!value.error().toString().isEmpty(), "a message rejected without a message");
        }
    }

    // The stamp decoder reads a batch as the drain timer hands it over: the announcement, the
    // payload on its data topic, and the payload once more on a topic without an announcement
    // (where it may be a JSON stamp).
    MqttStampDecoder decoder;
    std::vector<MqttMessage> batch(3);
    batch[0].topic = MqttClientWire::typeTopicPrefix() + QStringLiteral("fuzz/data");
    batch[0].payload = announcement;
    batch[1].topic = QStringLiteral("fuzz/data");
    batch[1].payload = payload;
    batch[1].receivedNs = 1'700'000'000'000'000'000LL;
    batch[2].topic = QStringLiteral("fuzz/json");
    batch[2].payload = payload;
    std::vector<StampEvent> stamps;
    std::vector<LatencyValue> latencies;
    decoder.decode(batch, stamps, latencies);
    if (decoder.malformed() > 0)
        FUZZ_CHECK(!decoder.lastError().isEmpty(), "a malformed stamp counted without a message");

    // The payload of a json link as the watch converts it (MqttSource::jsonKey(), issue 45).
    for (const char* type : {"geometry_msgs/msg/PoseStamped", "std_msgs/msg/String"})
        if (const Result<QByteArray> cdr
            = Ros2BridgeWire::fromJson(ros2Types(), QString::fromLatin1(type), payload);
            !cdr)
            FUZZ_CHECK(!cdr.error().toString().isEmpty(), "a JSON payload refused without a message");
    return 0;
}
