// SPDX-License-Identifier: MIT
#include "ros2/ros2protocol.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <QCoreApplication>
#include <QHostAddress>
#include <QtEndian>
#include <type_traits>

namespace Ros2Protocol {

bool isKnown(quint8 kind)
{
    return (kind >= quint8(Kind::Start) && kind <= quint8(Kind::Unsubscribe))
        || (kind >= quint8(Kind::Started) && kind <= quint8(Kind::EndpointDone));
}

QByteArray frameHeader(Kind kind, qsizetype bodySize)
{
    QByteArray out(5, '\0');
    qToLittleEndian(quint32(bodySize), out.data());
    out[4] = char(kind);
    return out;
}

QByteArray frame(Kind kind, const QByteArray& body)
{
    return frameHeader(kind, body.size()) + body;
}

void FrameReader::append(const QByteArray& bytes)
{
    if (failed())
        return;
    if (m_offset > 0 && m_offset >= m_buffer.size() / 2) { // drop what was read, now and then
        m_buffer.remove(0, m_offset);
        m_offset = 0;
    }
    m_buffer += bytes;
}

std::optional<Frame> FrameReader::next()
{
    if (failed() || pending() < 5)
        return std::nullopt;
    const char* head = m_buffer.constData() + m_offset;
    const quint32 length = qFromLittleEndian<quint32>(head);
    const quint8 kind = quint8(head[4]);
    if (length > kMaxFrameBytes) {
        m_error = QCoreApplication::translate("Ros2Protocol", "a frame of %1 bytes (at most %2)")
                      .arg(length)
                      .arg(kMaxFrameBytes);
    } else if (!isKnown(kind)) {
        m_error = QCoreApplication::translate("Ros2Protocol", "a frame of unknown kind %1").arg(kind);
    }
    if (failed()) {
        m_buffer.clear();
        m_offset = 0;
        return std::nullopt;
    }
    if (pending() < 5 + qsizetype(length))
        return std::nullopt;
    Frame f {Kind(kind), m_buffer.mid(m_offset + 5, qsizetype(length))};
    m_offset += 5 + qsizetype(length);
    if (m_offset == m_buffer.size()) {
        m_buffer.clear();
        m_offset = 0;
    }
    return f;
}

void Writer::u32(quint32 v)
{
    char b[4];
    qToLittleEndian(v, b);
    m_bytes.append(b, 4);
}

void Writer::u64(quint64 v)
{
    char b[8];
    qToLittleEndian(v, b);
    m_bytes.append(b, 8);
}

void Writer::f64(double v)
{
    quint64 bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    u64(bits);
}

void Writer::bytes(const QByteArray& b)
{
    u32(quint32(b.size()));
    m_bytes += b;
}

void Writer::patchU32(qsizetype at, quint32 v)
{
    Q_ASSERT(at >= 0 && at + 4 <= m_bytes.size());
    qToLittleEndian(v, m_bytes.data() + at);
}

void Writer::patchU64(qsizetype at, quint64 v)
{
    Q_ASSERT(at >= 0 && at + 8 <= m_bytes.size());
    qToLittleEndian(v, m_bytes.data() + at);
}

void Writer::strings(const QStringList& list)
{
    u32(quint32(list.size()));
    for (const QString& s : list)
        string(s);
}

bool Reader::take(qsizetype n)
{
    if (!m_ok || n < 0 || m_bytes.size() - m_pos < n) {
        m_ok = false;
        return false;
    }
    return true;
}

quint8 Reader::u8()
{
    if (!take(1))
        return 0;
    return quint8(m_bytes[m_pos++]);
}

quint32 Reader::u32()
{
    if (!take(4))
        return 0;
    const quint32 v = qFromLittleEndian<quint32>(m_bytes.constData() + m_pos);
    m_pos += 4;
    return v;
}

quint64 Reader::u64()
{
    if (!take(8))
        return 0;
    const quint64 v = qFromLittleEndian<quint64>(m_bytes.constData() + m_pos);
    m_pos += 8;
    return v;
}

double Reader::f64()
{
    const quint64 bits = u64();
    double v = 0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

QByteArray Reader::bytes()
{
    const quint32 n = u32();
    if (!take(qsizetype(n)))
        return {};
    const QByteArray b = m_bytes.mid(m_pos, qsizetype(n));
    m_pos += qsizetype(n);
    return b;
}

QStringList Reader::strings()
{
    const quint32 n = count(4);
    QStringList out;
    out.reserve(qsizetype(n));
    for (quint32 i = 0; i < n && m_ok; ++i)
        out.append(string());
    return m_ok ? out : QStringList();
}

quint32 Reader::count(int minBytes)
{
    const quint32 n = u32();
    if (!m_ok)
        return 0;
    if (minBytes > 0 && quint64(n) * quint64(minBytes) > quint64(m_bytes.size() - m_pos)) {
        m_ok = false;
        return 0;
    }
    return n;
}

namespace {

// Each body's fields, once: the same list writes it (IO = Writer, a const body) and reads it back
// (IO = Reader), so that the two sides cannot drift apart. The decoders check the values after.
template <class B, class T>
using IfBody = std::enable_if_t<std::is_same_v<std::remove_const_t<B>, T>>;

template <class IO, class B>
IfBody<B, WatchRequest> fieldsOf(IO& io, B& w)
{
    io.field(w.topic);
    io.field(w.maxMessages);
    io.field(w.maxBytes);
}

template <class IO, class B>
IfBody<B, Ros2Endpoint> fieldsOf(IO& io, B& e)
{
    io.field(e.gid);
    io.field(e.topic);
    io.field(e.type);
    io.field(e.publisher);
    io.enumeration(e.qos.reliability, Ros2Qos::Reliable);
    io.enumeration(e.qos.durability, Ros2Qos::Persistent);
    io.field(e.qos.depth);
    io.field(e.node);
}

template <class IO, class B>
IfBody<B, TopicStats> fieldsOf(IO& io, B& t)
{
    auto& s = t.stats;
    io.field(t.topic);
    io.field(s.messages);
    io.field(s.bytes);
    io.field(s.lastSize);
    io.field(s.lastNs);
    io.field(s.rateHz);
    io.field(s.bytesPerSecond);
    io.field(s.type);
    io.field(s.lost);
    io.field(s.matchedPublishers);
    io.field(s.ageMs);
    io.field(t.withMessage);
    if (t.withMessage)
        io.field(s.lastMessage);
}

template <class IO, class B>
IfBody<B, SampleBatch> fieldsOf(IO& io, B& b)
{
    io.field(b.topic);
    io.field(b.dropped);
    io.list(b.samples, 8 + 4, [&](auto& sample) {
        io.field(sample.receivedNs);
        io.field(sample.bytes);
    });
}

template <class IO, class B>
IfBody<B, ArrivalBatch> fieldsOf(IO& io, B& b)
{
    io.field(b.dropped);
    io.list(b.arrivals, 4 + 8 + 4 + 4 + 1 + 8 + 8 + 1, [&](auto& a) {
        io.field(a.topic);
        io.field(a.receivedNs);
        io.field(a.size);
        io.field(a.head);
        io.field(a.key);
        io.field(a.textKey);
    });
}

template <class IO, class B>
IfBody<B, EndpointRequest> fieldsOf(IO& io, B& e)
{
    io.field(e.topic);
    io.field(e.type);
    // only what an endpoint of ours can be: volatile or transient local
    io.enumeration(e.qos.reliability, Ros2Qos::Reliable);
    io.enumeration(e.qos.durability, Ros2Qos::TransientLocal);
    io.field(e.qos.depth);
}

template <class IO, class B>
IfBody<B, EndpointDone> fieldsOf(IO& io, B& d)
{
    io.field(d.advertise);
    io.field(d.topic);
    io.field(d.type);
    io.field(d.why);
}

template <class IO, class B>
IfBody<B, PublishRequest> fieldsOf(IO& io, B& p)
{
    io.field(p.topic);
    io.field(p.cdr);
}

template <class B>
QByteArray encodeBody(const B& body, qsizetype reserve = 0)
{
    Writer w;
    w.reserve(reserve);
    fieldsOf(w, body);
    return w.data();
}

/// The body read as a whole and `valid`, or nothing.
template <class B, class Valid>
std::optional<B> decodeBody(const QByteArray& bytes, Valid valid)
{
    Reader r(bytes);
    B body;
    fieldsOf(r, body);
    if (!r.done() || !valid(body))
        return std::nullopt;
    return body;
}

// The smallest an encoded element can be: what a count is checked against.
constexpr int kMinEndpointBytes = 4 + 4 + 4 + 1 + 1 + 1 + 4 + 4; // gid, topic, type, flags, depth, node
constexpr int kMinTopicBytes = 4 * 4; // name, types, publishers, subscribers
constexpr int kMinNodeBytes = 4 * 3;
constexpr int kMinStatsBytes = 4 + 8 + 8 + 4 + 8 + 8 + 8 + 4 + 8 + 4 + 8 + 1;

} // namespace

QByteArray encodeStart(const StartRequest& r)
{
    Writer w;
    w.u32(quint32(r.options.domain));
    w.u8((r.options.localhostOnly ? 1 : 0) | (r.options.limitedGraph ? 2 : 0));
    w.u32(quint32(r.graphIntervalMs));
    w.strings(r.options.staticPeers);
    return w.data();
}

std::optional<StartRequest> decodeStart(const QByteArray& body)
{
    Reader r(body);
    StartRequest s;
    // compared as read, before they become ints (0xffffffff would be the domain -1)
    const quint32 domain = r.u32();
    const quint8 local = r.u8();
    const quint32 interval = r.u32();
    const QStringList peers = r.strings();
    if (!r.done() || local > 3 || peers.size() > Ros2Options::kMaxStaticPeers
        || std::any_of(peers.begin(), peers.end(),
                       [](const QString& p) { return p.size() > 64 || QHostAddress(p).isNull(); })
        || domain > quint32(Ros2Options::kMaxDomain) || interval < 1 || interval > 3'600'000)
        return std::nullopt;
    s.options.domain = int(domain);
    s.graphIntervalMs = int(interval);
    s.options.localhostOnly = (local & 1) != 0;
    s.options.limitedGraph = (local & 2) != 0;
    for (const QString& p : peers)
        s.options.staticPeers << QHostAddress(p).toString(); // only what an address reads as
    return s;
}

QByteArray encodeWatch(const WatchRequest& r)
{
    return encodeBody(r);
}

std::optional<WatchRequest> decodeWatch(const QByteArray& body)
{
    return decodeBody<WatchRequest>(body, [](const WatchRequest& w) { return w.maxBytes >= 0; });
}

QByteArray encodeStrings(const QStringList& strings)
{
    Writer w;
    for (const QString& s : strings)
        w.string(s);
    return w.data();
}

std::optional<QStringList> decodeStrings(const QByteArray& body, int count)
{
    Reader r(body);
    QStringList out;
    for (int i = 0; i < count; ++i)
        out.append(r.string());
    if (!r.done())
        return std::nullopt;
    return out;
}

QByteArray encodeNumber(quint64 n)
{
    Writer w;
    w.u64(n);
    return w.data();
}

std::optional<quint64> decodeNumber(const QByteArray& body)
{
    Reader r(body);
    const quint64 n = r.u64();
    if (!r.done())
        return std::nullopt;
    return n;
}

QByteArray encodeGraph(const GraphUpdate& g, qsizetype maxBytes)
{
    Writer w;
    quint64 omitted = g.graph.omitted;
    // Written, then taken back when it passed the budget: counted in `omitted` instead.
    auto fits = [&](qsizetype before, quint64 count) {
        if (w.size() <= maxBytes)
            return true;
        w.truncate(before);
        omitted += count;
        return false;
    };
    auto writeEndpoints = [&](const QList<Ros2Endpoint>& list) {
        const qsizetype countAt = w.size();
        w.u32(0);
        quint32 written = 0;
        for (const Ros2Endpoint& e : list) {
            const qsizetype before = w.size();
            fieldsOf(w, e);
            if (fits(before, 1))
                ++written;
        }
        w.patchU32(countAt, written);
    };
    w.u64(g.badDiscoveryInfo);
    w.u32(quint32(g.graph.participants));
    w.u32(quint32(g.graph.services));
    const qsizetype omittedAt = w.size();
    w.u64(0);
    qsizetype countAt = w.size();
    w.u32(0);
    quint32 written = 0;
    for (const Ros2Topic& t : g.graph.topics) {
        const qsizetype before = w.size();
        w.string(t.name);
        w.strings(t.types);
        if (!fits(before, quint64(t.publishers.size() + t.subscribers.size())))
            continue;
        writeEndpoints(t.publishers);
        writeEndpoints(t.subscribers);
        ++written;
    }
    w.patchU32(countAt, written);
    countAt = w.size();
    w.u32(0);
    written = 0;
    for (const Ros2Node& n : g.graph.nodes) {
        const qsizetype before = w.size();
        w.string(n.name);
        w.strings(n.publishes);
        w.strings(n.subscribes);
        if (fits(before, 1))
            ++written;
    }
    w.patchU32(countAt, written);
    w.patchU64(omittedAt, omitted);
    return w.data();
}

std::optional<GraphUpdate> decodeGraph(const QByteArray& body)
{
    Reader r(body);
    GraphUpdate g;
    g.badDiscoveryInfo = r.u64();
    g.graph.participants = int(r.u32());
    g.graph.services = int(r.u32());
    g.graph.omitted = r.u64();
    if (g.graph.participants < 0 || g.graph.services < 0)
        r.fail();
    const quint32 topics = r.count(kMinTopicBytes);
    g.graph.topics.reserve(qsizetype(topics));
    for (quint32 i = 0; i < topics && r.ok(); ++i) {
        Ros2Topic t;
        t.name = r.string();
        t.types = r.strings();
        r.list(t.publishers, kMinEndpointBytes, [&](Ros2Endpoint& e) { fieldsOf(r, e); });
        r.list(t.subscribers, kMinEndpointBytes, [&](Ros2Endpoint& e) { fieldsOf(r, e); });
        g.graph.topics.append(std::move(t));
    }
    const quint32 nodes = r.count(kMinNodeBytes);
    g.graph.nodes.reserve(qsizetype(nodes));
    for (quint32 i = 0; i < nodes && r.ok(); ++i) {
        Ros2Node n;
        n.name = r.string();
        n.publishes = r.strings();
        n.subscribes = r.strings();
        g.graph.nodes.append(std::move(n));
    }
    for (const Ros2Topic& t : std::as_const(g.graph.topics))
        for (const QList<Ros2Endpoint>* list : {&t.publishers, &t.subscribers})
            for (const Ros2Endpoint& e : *list)
                if (e.gid.size() != 16 || e.qos.depth < -1)
                    r.fail();
    // Ros2Graph::build() gives each topic once, sorted by name: a list that is not did not come
    // from it.
    for (qsizetype i = 1; i < g.graph.topics.size() && r.ok(); ++i)
        if (!(g.graph.topics[i - 1].name < g.graph.topics[i].name))
            r.fail();
    if (!r.done())
        return std::nullopt;
    return g;
}

QByteArray encodeStats(const QList<TopicStats>& stats)
{
    Writer w;
    w.list(stats, kMinStatsBytes, [&](const TopicStats& t) { fieldsOf(w, t); });
    return w.data();
}

std::optional<QList<TopicStats>> decodeStats(const QByteArray& body)
{
    Reader r(body);
    QList<TopicStats> out;
    r.list(out, kMinStatsBytes, [&](TopicStats& t) {
        fieldsOf(r, t);
        const Ros2MonitorStats& s = t.stats;
        if (s.lastSize < 0 || s.matchedPublishers < 0 || !std::isfinite(s.rateHz)
            || !std::isfinite(s.bytesPerSecond) || s.rateHz < 0 || s.bytesPerSecond < 0
            || std::isinf(s.ageMs))
            r.fail();
    });
    if (!r.done())
        return std::nullopt;
    return out;
}

QByteArray encodeSamples(const SampleBatch& b)
{
    qsizetype size = 4 + b.topic.size() * 3 + 8 + 4;
    for (const Ros2Sample& s : b.samples)
        size += 8 + 4 + s.bytes.size();
    return encodeBody(b, size);
}

std::optional<SampleBatch> decodeSamples(const QByteArray& body)
{
    return decodeBody<SampleBatch>(body, [](const SampleBatch&) { return true; });
}

QByteArray encodeArrivals(const ArrivalBatch& b)
{
    return encodeBody(b);
}

std::optional<ArrivalBatch> decodeArrivals(const QByteArray& body)
{
    std::optional<ArrivalBatch> batch = decodeBody<ArrivalBatch>(body, [](const ArrivalBatch& b) {
        return std::all_of(b.arrivals.begin(), b.arrivals.end(), [](const SourceHead& a) {
            return a.size >= 0 && a.head.size() <= SourceHead::kHeadBytes;
        });
    });
    if (batch)
        for (SourceHead& a : batch->arrivals)
            a.graph = SourceGraph::Ros2; // the graph is not on the wire: the child's are ROS 2's
    return batch;
}

QByteArray encodeEndpoint(const EndpointRequest& r)
{
    return encodeBody(r);
}

std::optional<EndpointRequest> decodeEndpoint(const QByteArray& body)
{
    // keep last 1..kMaxDepth (a depth past INT_MAX reads negative)
    return decodeBody<EndpointRequest>(body, [](const EndpointRequest& e) {
        return !e.topic.isEmpty() && !e.type.isEmpty() && e.qos.depth >= 1 && e.qos.depth <= kMaxDepth;
    });
}

QByteArray encodeEndpointDone(const EndpointDone& d)
{
    return encodeBody(d);
}

std::optional<EndpointDone> decodeEndpointDone(const QByteArray& body)
{
    return decodeBody<EndpointDone>(body, [](const EndpointDone&) { return true; });
}

QByteArray encodePublish(const PublishRequest& r)
{
    return encodeBody(r, 4 + r.topic.size() * 3 + 4 + r.cdr.size());
}

std::optional<PublishRequest> decodePublish(const QByteArray& body)
{
    // a sample is at least its encapsulation header
    return decodeBody<PublishRequest>(body, [](const PublishRequest& p) {
        return !p.topic.isEmpty() && p.cdr.size() >= 4;
    });
}

} // namespace Ros2Protocol
