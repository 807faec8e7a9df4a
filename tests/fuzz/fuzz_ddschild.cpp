// SPDX-License-Identifier: MIT
// Fuzz target for the request dispatcher of bridgescope-dds (DdsChildServer, issue 41): what the
// parent writes on the child's stdin, cut into frames and handed to the DDS participant. Here the
// participant is a recording one (no domain is joined), which checks what reaches it.
//
// Input: the byte stream from the parent. Properties: a turn handles at most its frames; a stream
// that fails says why; no endpoint reaches the participant with a topic or type DDS may not be
// given (Ros2Names) or a depth out of range; every Advertise and Subscribe is answered by exactly
// one EndpointDone that reads, and only those are; a graph interval in 1..3,600,000 ms.
#include "fuzzcheck.h"
#include "ros2/ddschildserver.h"
#include "ros2/ros2names.h"

namespace {

class RecordingEngine : public Ros2ChildEngine
{
public:
    int endpointCalls = 0;
    Status start(const Ros2Options& options) override
    {
        FUZZ_CHECK(options.domain >= 0 && options.domain <= Ros2Options::kMaxDomain, "a domain out of range");
        return LocatedError {QStringLiteral("not here")};
    }
    void setGraphInterval(int ms) override
    {
        FUZZ_CHECK(ms >= 1 && ms <= 3'600'000, "a graph interval out of range");
    }
    void monitor(const QString&, bool) override { }
    void unmonitor(const QString&) override { }
    void watchMessages(const QString&, std::size_t, qint64 maxBytes) override
    {
        FUZZ_CHECK(maxBytes >= 0, "a negative byte bound");
    }
    void unwatchMessages(const QString&) override { }
    void keepArrivals(std::size_t n) override
    {
        FUZZ_CHECK(n <= 100'000'000, "an arrival bound out of range");
    }
    void setNode(const QString&, const QString&) override { }
    Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        return endpoint(topic, type, qos);
    }
    void unadvertise(const QString&) override { }
    bool publish(const QString&, const QByteArray& cdr) override
    {
        FUZZ_CHECK(cdr.size() >= 4, "a sample without its encapsulation header");
        return true;
    }
    Status subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos) override
    {
        return endpoint(topic, type, qos);
    }
    void unsubscribeSamples(const QString&) override { }

private:
    Status endpoint(const QString& topic, const QString& type, const Ros2Qos& qos)
    {
        ++endpointCalls;
        FUZZ_CHECK(Ros2Names::isValidTopic(topic) && Ros2Names::isValidType(type),
                   "an unchecked name reached DDS");
        FUZZ_CHECK(type.size() <= Ros2Names::kMaxNameChars, "a type name past the bound reached DDS");
        FUZZ_CHECK(qos.depth >= 1 && qos.depth <= Ros2Protocol::kMaxDepth, "a depth out of range");
        if (topic.size() % 2) // refused now and then, as Cyclone may
            return LocatedError {QStringLiteral("refused")};
        return {};
    }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    RecordingEngine engine;
    int answers = 0;
    int endpointRequests = 0;
    DdsChildServer server(engine, [&](Ros2Protocol::Kind kind, const QByteArray& body) {
        if (kind == Ros2Protocol::Kind::EndpointDone) {
            ++answers;
            const auto done = Ros2Protocol::decodeEndpointDone(body);
            FUZZ_CHECK(done.has_value(), "an EndpointDone that does not read");
        } else {
            FUZZ_CHECK(kind == Ros2Protocol::Kind::StartFailed || kind == Ros2Protocol::Kind::Started,
                       "an answer of a kind the dispatcher does not send");
        }
    });
    // fed in slices of the first byte's size, a turn of at most a few frames each
    const int slice = input.isEmpty() ? 1 : 1 + quint8(input[0]);
    const int perTurn = input.size() > 1 ? 1 + quint8(input[1]) % 8 : 1;
    // count the Advertise and Subscribe frames as a reader of our own sees them
    Ros2Protocol::FrameReader counter;
    counter.append(input.mid(2));
    while (auto f = counter.next())
        if (f->kind == Ros2Protocol::Kind::Advertise || f->kind == Ros2Protocol::Kind::Subscribe)
            ++endpointRequests;
    DdsChildServer::Turn turn = DdsChildServer::Turn::Idle;
    int handledRequests = 0;
    for (qsizetype at = 2; at < input.size() && turn != DdsChildServer::Turn::Failed; at += slice) {
        server.append(input.mid(at, slice));
        do {
            const int before = answers;
            turn = server.handlePending(perTurn);
            FUZZ_CHECK(answers - before <= perTurn, "more requests in a turn than its bound");
        } while (turn == DdsChildServer::Turn::More);
        handledRequests = answers;
    }
    if (turn == DdsChildServer::Turn::Failed) {
        FUZZ_CHECK(!server.error().isEmpty(), "a failed stream without a reason");
    } else {
        FUZZ_CHECK(handledRequests == endpointRequests,
                   "an Advertise or Subscribe not answered exactly once");
        FUZZ_CHECK(engine.endpointCalls <= endpointRequests, "more endpoints made than asked for");
    }
    return 0;
}
