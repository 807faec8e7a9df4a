// SPDX-License-Identifier: MIT
// Fuzz target for the graph of bridgescope-dds fed hostile discovery data (issue 41): endpoints as
// any participant may announce them (names and types of any length, one topic with thousands of
// types, thousands of endpoints of one participant), put together by Ros2Graph::build and sent as
// a graph frame within its budget (Ros2Protocol::encodeGraph).
//
// Input: a header byte (a count of generated endpoints: 0, or n * 500 on one topic, each of a type
// of its own), a budget byte, then records: participant byte, flags byte, topic length byte, topic,
// type length byte, type. Properties: a topic keeps at most kMaxEndpointsPerTopic endpoints and
// kMaxTypesPerTopic types; every endpoint is listed or counted in `omitted`; the frame is within
// its budget (plus one item) and reads back, with at least the graph's omitted; under a budget
// that holds it all, it reads back the same graph.
#include "fuzzcheck.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"

#include <QElapsedTimer>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    if (input.size() < 2)
        return 0;
    QList<Ros2Endpoint> endpoints;
    const int generated = quint8(input[0]) % 32 * 500; // at most 15,500
    for (int i = 0; i < generated; ++i) {
        Ros2Endpoint e;
        e.gid = QByteArray(12, '\x01') + QByteArray::number(i).rightJustified(4, '0').right(4);
        e.topic = QStringLiteral("/flood");
        e.type = QStringLiteral("flood_msgs/msg/T%1").arg(i);
        e.publisher = i % 3 != 0;
        endpoints.append(e);
    }
    const qsizetype budget = 64 + qsizetype(quint8(input[1])) * 64;
    qsizetype at = 2;
    auto take = [&](qsizetype n) {
        const QByteArray out = input.mid(at, n);
        at += n;
        return out;
    };
    quint16 serial = 0;
    while (at + 3 <= input.size()) {
        Ros2Endpoint e;
        const quint8 participant = quint8(input[at++]) % 4;
        const quint8 flags = quint8(input[at++]);
        e.gid = QByteArray(12, char(participant)) + QByteArray(2, '\0') + char(serial >> 8)
            + char(serial & 0xff);
        ++serial;
        e.publisher = flags & 1;
        e.qos.reliability = (flags & 2) ? Ros2Qos::Reliable : Ros2Qos::BestEffort;
        e.qos.durability = Ros2Qos::Durability((flags >> 2) & 3);
        e.node = (flags & 16) ? QStringLiteral("/n%1").arg(participant) : QString();
        e.topic = QString::fromUtf8(take(quint8(input[at++])));
        e.type = at < input.size() ? QString::fromUtf8(take(quint8(input[at++]))) : QString();
        endpoints.append(e);
    }
    QElapsedTimer timer;
    timer.start();
    const Ros2Graph g = Ros2Graph::build(endpoints, {}, 4);
    FUZZ_CHECK(timer.elapsed() < 5000, "building the graph took more than 5 s");
    qsizetype listed = 0;
    for (const Ros2Topic& t : g.topics) {
        const qsizetype n = t.publishers.size() + t.subscribers.size();
        FUZZ_CHECK(n > 0, "a topic without endpoints");
        FUZZ_CHECK(n <= Ros2Graph::kMaxEndpointsPerTopic, "a topic past its endpoint bound");
        FUZZ_CHECK(t.types.size() <= Ros2Graph::kMaxTypesPerTopic, "a topic past its type bound");
        listed += n;
    }
    FUZZ_CHECK(quint64(listed) + g.omitted == quint64(endpoints.size()),
               "an endpoint neither listed nor counted");

    const QByteArray small = Ros2Protocol::encodeGraph({g, 7}, budget);
    const auto partial = Ros2Protocol::decodeGraph(small);
    FUZZ_CHECK(partial.has_value(), "a partial graph that does not read");
    FUZZ_CHECK(partial->graph.omitted >= g.omitted,
               "a partial graph that counts less than the graph left out");
    FUZZ_CHECK(partial->badDiscoveryInfo == 7, "the bad discovery count lost");
    // every item the frame holds was within the budget when written
    const QByteArray whole = Ros2Protocol::encodeGraph({g, 7}, Ros2Protocol::kMaxGraphBytes);
    if (whole.size() < Ros2Protocol::kMaxGraphBytes) {
        const auto back = Ros2Protocol::decodeGraph(whole);
        FUZZ_CHECK(back.has_value() && back->graph == g, "a whole graph that does not read back the same");
        FUZZ_CHECK(small.size() <= std::max(budget, whole.size()), "a partial graph larger than the whole");
        if (whole.size() <= budget)
            FUZZ_CHECK(small == whole, "a graph within the budget sent in part");
    }
    return 0;
}
