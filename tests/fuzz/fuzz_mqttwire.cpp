// SPDX-License-Identifier: MIT
// Fuzz target for what mqtt_client puts on the broker: the retained type announcement
// (`mqtt_client/ros_msg_type/<topic>`), the stamped payload on `<topic>`, the message decoded
// with the announced definition, and the stamp decoder that reads a batch of both.
//
// Input: a 16-bit little-endian length, that many bytes of type announcement, then the payload.
// Properties: a decoded announcement encodes to bytes that decode to the same announcement; a
// stamped payload split and joined again gives the same bytes; errors come with a message.
#include "fuzzcheck.h"
#include "mqtt/mqttstampdecoder.h"
#include "wire/mqttclientwire.h"
#include "wire/rosmessage.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 2)
        return 0;
    const size_t typeSize = std::min<size_t>(size - 2, size_t(data[0]) | size_t(data[1]) << 8);
    const QByteArray announcement = fuzz::bytes(data + 2, typeSize);
    const QByteArray payload = fuzz::bytes(data + 2 + typeSize, size - 2 - typeSize);

    QString error;
    const std::optional<RosMsgTypeInfo> info = MqttClientWire::decodeType(announcement, &error);
    if (!info)
        FUZZ_CHECK(!error.isEmpty(), "an announcement rejected without a message");

    const std::optional<MqttClientWire::Stamped> split = MqttClientWire::splitStamped(payload);
    if (split)
        FUZZ_CHECK(MqttClientWire::stamped(split->stampNs, split->message) == payload,
                   "a stamped payload changes when split and joined");

    if (info) {
        const std::optional<RosMsgTypeInfo> again
            = MqttClientWire::decodeType(MqttClientWire::encodeType(*info));
        FUZZ_CHECK(again && *again == *info, "an announcement does not survive encode and decode");

        RosTypeRegistry registry;
        if (registry.addDefinition(info->name, info->definition, &error)) {
            const QByteArray message = info->stamped && split ? split->message : payload;
            error.clear();
            if (!RosMessageDecoder::decode(registry, info->name, message, &error))
                FUZZ_CHECK(!error.isEmpty(), "a message rejected without a message");
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
    return 0;
}
