// SPDX-License-Identifier: MIT
#include "ros2/ros2protocol.h"

#include <cmath>
#include <cstring>
#include <QCoreApplication>
#include <QtEndian>

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

QByteArray encodeStart(const StartRequest& r)
{
    Writer w;
    w.u32(quint32(r.options.domain));
    w.u8((r.options.localhostOnly ? 1 : 0) | (r.options.limitedGraph ? 2 : 0));
    w.u32(quint32(r.graphIntervalMs));
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
    if (!r.done() || local > 3 || domain > quint32(Ros2Options::kMaxDomain) || interval < 1
        || interval > 3'600'000)
        return std::nullopt;
    s.options.domain = int(domain);
    s.graphIntervalMs = int(interval);
    s.options.localhostOnly = (local & 1) != 0;
    s.options.limitedGraph = (local & 2) != 0;
    return s;
}

QByteArray encodeWatch(const WatchRequest& r)
{
    Writer w;
    w.string(r.topic);
    w.u64(r.maxMessages);
    w.i64(r.maxBytes);
    return w.data();
}

std::optional<WatchRequest> decodeWatch(const QByteArray& body)
{
    Reader r(body);
    WatchRequest w;
    w.topic = r.string();
    w.maxMessages = r.u64();
    w.maxBytes = r.i64();
    if (!r.done() || w.maxBytes < 0)
        return std::nullopt;
    return w;
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

namespace {

// The smallest an encoded element can be: what a count is checked against.
constexpr int kMinEndpointBytes = 4 + 4 + 4 + 1 + 1 + 1 + 4 + 4; // gid, topic, type, flags, depth, node
constexpr int kMinTopicBytes = 4 * 4; // name, types, publishers, subscribers
constexpr int kMinNodeBytes = 4 * 3;

void writeEndpoint(Writer& w, const Ros2Endpoint& e)
{
    w.bytes(e.gid);
    w.string(e.topic);
    w.string(e.type);
    w.u8(e.publisher ? 1 : 0);
    w.u8(quint8(e.qos.reliability));
    w.u8(quint8(e.qos.durability));
    w.u32(quint32(e.qos.depth));
    w.string(e.node);
}

Ros2Endpoint readEndpoint(Reader& r)
{
    Ros2Endpoint e;
    e.gid = r.bytes();
    e.topic = r.string();
    e.type = r.string();
    const quint8 publisher = r.u8();
    const quint8 reliability = r.u8();
    const quint8 durability = r.u8();
    e.qos.depth = int(r.u32());
    e.node = r.string();
    if (e.gid.size() != 16 || publisher > 1 || reliability > Ros2Qos::Reliable || durability > Ros2Qos::Persistent
        || e.qos.depth < -1)
        r.fail();
    e.publisher = publisher == 1;
    e.qos.reliability = Ros2Qos::Reliability(reliability);
    e.qos.durability = Ros2Qos::Durability(durability);
    return e;
}

QList<Ros2Endpoint> readEndpoints(Reader& r)
{
    const quint32 n = r.count(kMinEndpointBytes);
    QList<Ros2Endpoint> out;
    out.reserve(qsizetype(n));
    for (quint32 i = 0; i < n && r.ok(); ++i)
        out.append(readEndpoint(r));
    return out;
}

} // namespace

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
            writeEndpoint(w, e);
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
        t.publishers = readEndpoints(r);
        t.subscribers = readEndpoints(r);
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
    w.u32(quint32(stats.size()));
    for (const TopicStats& t : stats) {
        const Ros2MonitorStats& s = t.stats;
        w.string(t.topic);
        w.u64(s.messages);
        w.u64(s.bytes);
        w.u32(quint32(s.lastSize));
        w.i64(s.lastNs);
        w.f64(s.rateHz);
        w.f64(s.bytesPerSecond);
        w.string(s.type);
        w.u64(s.lost);
        w.u32(quint32(s.matchedPublishers));
        w.u8(t.withMessage ? 1 : 0);
        if (t.withMessage)
            w.bytes(s.lastMessage);
    }
    return w.data();
}

std::optional<QList<TopicStats>> decodeStats(const QByteArray& body)
{
    Reader r(body);
    constexpr int kMinBytes = 4 + 8 + 8 + 4 + 8 + 8 + 8 + 4 + 8 + 4 + 1;
    const quint32 n = r.count(kMinBytes);
    QList<TopicStats> out;
    out.reserve(qsizetype(n));
    for (quint32 i = 0; i < n && r.ok(); ++i) {
        TopicStats t;
        Ros2MonitorStats& s = t.stats;
        t.topic = r.string();
        s.messages = r.u64();
        s.bytes = r.u64();
        s.lastSize = int(r.u32());
        s.lastNs = r.i64();
        s.rateHz = r.f64();
        s.bytesPerSecond = r.f64();
        s.type = r.string();
        s.lost = r.u64();
        s.matchedPublishers = int(r.u32());
        const quint8 with = r.u8();
        if (with > 1 || s.lastSize < 0 || s.matchedPublishers < 0 || !std::isfinite(s.rateHz)
            || !std::isfinite(s.bytesPerSecond) || s.rateHz < 0 || s.bytesPerSecond < 0)
            r.fail();
        t.withMessage = with == 1;
        if (t.withMessage)
            s.lastMessage = r.bytes();
        out.append(std::move(t));
    }
    if (!r.done())
        return std::nullopt;
    return out;
}

QByteArray encodeSamples(const SampleBatch& b)
{
    Writer w;
    qsizetype size = 4 + b.topic.size() * 3 + 8 + 4;
    for (const Ros2Sample& s : b.samples)
        size += 8 + 4 + s.bytes.size();
    w.reserve(size);
    w.string(b.topic);
    w.u64(b.dropped);
    w.u32(quint32(b.samples.size()));
    for (const Ros2Sample& s : b.samples) {
        w.i64(s.receivedNs);
        w.bytes(s.bytes);
    }
    return w.data();
}

std::optional<SampleBatch> decodeSamples(const QByteArray& body)
{
    Reader r(body);
    SampleBatch b;
    b.topic = r.string();
    b.dropped = r.u64();
    const quint32 n = r.count(8 + 4);
    b.samples.reserve(n);
    for (quint32 i = 0; i < n && r.ok(); ++i) {
        Ros2Sample s;
        s.receivedNs = r.i64();
        s.bytes = r.bytes();
        b.samples.push_back(std::move(s));
    }
    if (!r.done())
        return std::nullopt;
    return b;
}

QByteArray encodeArrivals(const ArrivalBatch& b)
{
    Writer w;
    w.u64(b.dropped);
    w.u32(quint32(b.arrivals.size()));
    for (const Ros2Arrival& a : b.arrivals) {
        w.string(a.topic);
        w.i64(a.receivedNs);
        w.u32(quint32(a.size));
        w.bytes(a.head);
    }
    return w.data();
}

std::optional<ArrivalBatch> decodeArrivals(const QByteArray& body)
{
    Reader r(body);
    ArrivalBatch b;
    b.dropped = r.u64();
    const quint32 n = r.count(4 + 8 + 4 + 4);
    b.arrivals.reserve(n);
    for (quint32 i = 0; i < n && r.ok(); ++i) {
        Ros2Arrival a;
        a.topic = r.string();
        a.receivedNs = r.i64();
        a.size = int(r.u32());
        a.head = r.bytes();
        if (a.size < 0 || a.head.size() > Ros2Arrival::kHeadBytes)
            r.fail();
        b.arrivals.push_back(std::move(a));
    }
    if (!r.done())
        return std::nullopt;
    return b;
}

QByteArray encodeEndpoint(const EndpointRequest& r)
{
    Writer w;
    w.string(r.topic);
    w.string(r.type);
    w.u8(quint8(r.qos.reliability));
    w.u8(quint8(r.qos.durability));
    w.u32(quint32(r.qos.depth));
    return w.data();
}

std::optional<EndpointRequest> decodeEndpoint(const QByteArray& body)
{
    Reader r(body);
    EndpointRequest e;
    e.topic = r.string();
    e.type = r.string();
    const quint8 reliability = r.u8();
    const quint8 durability = r.u8();
    const quint32 depth = r.u32();
    // only what an endpoint of ours can be: volatile or transient local, keep last 1..kMaxDepth
    if (!r.done() || e.topic.isEmpty() || e.type.isEmpty() || reliability > Ros2Qos::Reliable
        || durability > Ros2Qos::TransientLocal || depth < 1 || depth > quint32(kMaxDepth))
        return std::nullopt;
    e.qos.reliability = Ros2Qos::Reliability(reliability);
    e.qos.durability = Ros2Qos::Durability(durability);
    e.qos.depth = int(depth);
    return e;
}

QByteArray encodeEndpointDone(const EndpointDone& d)
{
    Writer w;
    w.u8(d.advertise ? 1 : 0);
    w.string(d.topic);
    w.string(d.type);
    w.string(d.why);
    return w.data();
}

std::optional<EndpointDone> decodeEndpointDone(const QByteArray& body)
{
    Reader r(body);
    EndpointDone d;
    const quint8 advertise = r.u8();
    d.advertise = advertise == 1;
    d.topic = r.string();
    d.type = r.string();
    d.why = r.string();
    if (advertise > 1 || !r.done())
        return std::nullopt;
    return d;
}

QByteArray encodePublish(const PublishRequest& r)
{
    Writer w;
    w.reserve(4 + r.topic.size() * 3 + 4 + r.cdr.size());
    w.string(r.topic);
    w.bytes(r.cdr);
    return w.data();
}

std::optional<PublishRequest> decodePublish(const QByteArray& body)
{
    Reader r(body);
    PublishRequest p;
    p.topic = r.string();
    p.cdr = r.bytes();
    // a sample is at least its encapsulation header
    if (!r.done() || p.topic.isEmpty() || p.cdr.size() < 4)
        return std::nullopt;
    return p;
}

} // namespace Ros2Protocol
