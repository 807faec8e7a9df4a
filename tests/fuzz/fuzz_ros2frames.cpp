// SPDX-License-Identifier: MIT
// Fuzz target for what bridgescope-dds sends Bridgescope: Ros2Protocol frames on a pipe. The child
// runs a DDS library (Cyclone DDS) that a datagram from any host of the domain could take over, so
// its frames are hostile input: cut into frames by FrameReader, each body read by the decoder of
// its kind, and the samples of watched topics on to the CDR decoder, as the field plots decode them.
//
// Input: the byte stream; its first byte sets the slice size it is fed in. Properties: a stream
// that fails says why and keeps nothing; a body that reads writes back to bytes that read the same;
// every CDR sample decodes or is refused with a message.
#include "fuzzcheck.h"
#include "ros2/ros2protocol.h"
#include "wire/rosmessage.h"

using namespace Ros2Protocol;

namespace {

const RosTypeRegistry& ros2Types()
{
    static const RosTypeRegistry registry = [] {
        RosTypeRegistry r(RosTypeRegistry::Dialect::Ros2);
        (void)r.addDefinition(QStringLiteral("builtin_interfaces/msg/Time"),
                              QStringLiteral("int32 sec\nuint32 nanosec\n"));
        (void)r.addDefinition(QStringLiteral("std_msgs/msg/Header"),
                              QStringLiteral("builtin_interfaces/Time stamp\nstring frame_id\n"));
        (void)r.addDefinition(QStringLiteral("std_msgs/msg/String"), QStringLiteral("string data\n"));
        (void)r.addDefinition(QStringLiteral("std_msgs/msg/Float64"), QStringLiteral("float64 data\n"));
        (void)r.addDefinition(QStringLiteral("sensor_msgs/msg/PointField"),
                              QStringLiteral("string name\nuint32 offset\nuint8 datatype\nuint32 count\n"));
        (void)r.addDefinition(
            QStringLiteral("sensor_msgs/msg/PointCloud2"),
            QStringLiteral("std_msgs/Header header\nuint32 height\nuint32 width\nPointField[] fields\n"
                           "bool is_bigendian\nuint32 point_step\nuint32 row_step\nuint8[] data\n"
                           "bool is_dense\n"));
        return r;
    }();
    return registry;
}

void decodeEachSample(const SampleBatch& batch)
{
    static const QStringList types {QStringLiteral("std_msgs/msg/String"), QStringLiteral("std_msgs/msg/Float64"),
                                    QStringLiteral("sensor_msgs/msg/PointCloud2")};
    for (const Ros2Sample& s : batch.samples)
        for (const QString& type : types) {
            if (const Result<RosValue> value = RosMessageDecoder::decodeCdr(ros2Types(), type, s.bytes);
                !value)
                FUZZ_CHECK(!value.error().toString().isEmpty(), "a CDR sample refused without a message");
        }
}

/// Decodes a body, writes what it read and reads that again: the same value.
void body(const Frame& f)
{
    switch (f.kind) {
    case Kind::Graph:
        if (const auto g = decodeGraph(f.body)) {
            const auto again = decodeGraph(encodeGraph(*g));
            FUZZ_CHECK(again && again->graph == g->graph && again->badDiscoveryInfo == g->badDiscoveryInfo,
                       "a graph that does not read back");
            for (const Ros2Topic& t : g->graph.topics)
                for (const Ros2Endpoint& e : t.publishers + t.subscribers)
                    FUZZ_CHECK(e.gid.size() == 16, "an endpoint GUID that is not 16 bytes");
        }
        break;
    case Kind::Stats:
        if (const auto s = decodeStats(f.body)) {
            const auto again = decodeStats(encodeStats(*s));
            FUZZ_CHECK(again && again->size() == s->size(), "figures that do not read back");
        }
        break;
    case Kind::Samples:
    case Kind::Received:
        if (const auto b = decodeSamples(f.body)) {
            const auto again = decodeSamples(encodeSamples(*b));
            FUZZ_CHECK(again && again->samples.size() == b->samples.size(), "samples that do not read back");
            decodeEachSample(*b);
        }
        break;
    case Kind::Arrivals:
        if (const auto a = decodeArrivals(f.body)) {
            for (const SourceHead& x : a->arrivals)
                FUZZ_CHECK(x.head.size() <= SourceHead::kHeadBytes && x.size >= 0, "an arrival out of bounds");
        }
        break;
    case Kind::Start:
        if (const auto s = decodeStart(f.body))
            FUZZ_CHECK(s->options.domain >= 0 && s->options.domain <= Ros2Options::kMaxDomain, "a domain out of range");
        break;
    case Kind::Advertise:
    case Kind::Subscribe:
        if (const auto e = decodeEndpoint(f.body)) {
            const auto again = decodeEndpoint(encodeEndpoint(*e));
            FUZZ_CHECK(again && again->topic == e->topic && again->qos == e->qos && e->qos.depth >= 1,
                       "an endpoint request that does not read back");
        }
        break;
    case Kind::Publish:
        if (const auto p = decodePublish(f.body)) {
            const auto again = decodePublish(encodePublish(*p));
            FUZZ_CHECK(again && again->cdr == p->cdr && p->cdr.size() >= 4, "a sample to publish that does not read back");
        }
        break;
    case Kind::Watch:
        if (const auto w = decodeWatch(f.body))
            FUZZ_CHECK(w->maxBytes >= 0, "a negative byte bound");
        break;
    default:
        (void)decodeStrings(f.body, 2);
        (void)decodeNumber(f.body);
        break;
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray stream = fuzz::bytes(data + 1, size - 1);
    const qsizetype slice = 1 + data[0] % 64;
    FrameReader reader;
    for (qsizetype i = 0; i < stream.size(); i += slice) {
        reader.append(stream.mid(i, slice));
        while (auto f = reader.next())
            body(*f);
        if (reader.failed()) {
            FUZZ_CHECK(!reader.error().isEmpty(), "a stream ended without a reason");
            FUZZ_CHECK(reader.pending() == 0, "a failed stream keeps bytes");
            break;
        }
        FUZZ_CHECK(reader.pending() <= qsizetype(kMaxFrameBytes) + 5 + slice, "more held than a frame");
    }
    return 0;
}
