// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ros2graph.h"
#include "ros2/ros2types.h"

#include <optional>
#include <QByteArray>
#include <QList>
#include <QString>
#include <vector>

/// The pipe between Ros2Participant and `bridgescope-dds`, the child process that runs Cyclone DDS.
///
/// Both directions are frames: a 4-byte little-endian length, a kind byte, and a body of at most
/// kMaxFrameBytes. Bodies are written with Writer and read with Reader, which checks every length
/// and count against the bytes left before it allocates anything. The child parses what a DDS
/// domain sends with a library that can be made to misbehave, so the parent reads its frames as
/// hostile input: a frame that does not read ends the child (and it is started again).
namespace Ros2Protocol {

/// A 64 MiB sample (Ros2RawType's bound) with room for its header.
constexpr quint32 kMaxFrameBytes = 65 * 1024 * 1024;
/// The child packs samples into frames of about this size.
constexpr qsizetype kBatchBytes = 4 * 1024 * 1024;
/// The child sends the monitored topics' figures this often.
constexpr int kStatsMs = 100;

enum class Kind : quint8 {
    // parent to child
    Start = 1, ///< Ros2Options and the graph interval; the child joins the domain
    Monitor, ///< a topic
    Unmonitor, ///< a topic
    Watch, ///< a topic, its message and byte bounds
    Unwatch, ///< a topic
    KeepArrivals, ///< the bound (0: none)
    GraphInterval, ///< milliseconds
    SetNode, ///< the node announced in ros_discovery_info: namespace and name (both empty: none)
    Advertise, ///< an EndpointRequest: a writer
    Unadvertise, ///< a topic
    Publish, ///< a PublishRequest: one sample
    Subscribe, ///< an EndpointRequest: a reader whose samples come back as Received
    Unsubscribe, ///< a topic
    // child to parent
    Started = 64, ///< the participant is on the domain
    StartFailed, ///< why
    Graph, ///< a Ros2Graph and the bad ros_discovery_info count
    Stats, ///< the monitored topics' figures
    Samples, ///< a watched topic's whole samples and its drop count
    Arrivals, ///< monitored topics' arrivals and the drop count
    MonitorFailed, ///< a topic and why
    Heartbeat, ///< nothing: the child's event loop runs
    Received, ///< a SampleBatch of a subscribed topic (its drops: those of the child's queue)
    EndpointDone, ///< an EndpointDone: the answer to an Advertise or Subscribe
};
bool isKnown(quint8 kind);

struct Frame
{
    Kind kind = Kind::Heartbeat;
    QByteArray body;
};

/// A frame as bytes.
QByteArray frame(Kind kind, const QByteArray& body = {});
/// The 5 bytes before a body of `bodySize` bytes: for writers that send the body as it is.
QByteArray frameHeader(Kind kind, qsizetype bodySize);

/// Cuts a byte stream into frames. It holds at most one frame and what came after it; a length
/// over kMaxFrameBytes or an unknown kind ends the stream (error() says why).
class FrameReader
{
public:
    void append(const QByteArray& bytes);
    /// The next whole frame, if there is one.
    std::optional<Frame> next();
    bool failed() const { return !m_error.isEmpty(); }
    QString error() const { return m_error; }
    /// Bytes held that are not a whole frame yet.
    qsizetype pending() const { return m_buffer.size() - m_offset; }

private:
    QByteArray m_buffer;
    qsizetype m_offset = 0;
    QString m_error;
};

/// Appends little-endian numbers and length-prefixed bytes.
class Writer
{
public:
    void u8(quint8 v) { m_bytes.append(char(v)); }
    void u32(quint32 v);
    void u64(quint64 v);
    void i64(qint64 v) { u64(quint64(v)); }
    void f64(double v);
    void bytes(const QByteArray& b);
    void string(const QString& s) { bytes(s.toUtf8()); }
    void strings(const QStringList& list);
    /// One name for every field, the same as Reader's: a body's field list (ros2protocol.cpp,
    /// fieldsOf) is written once and serves encoding and decoding alike.
    void field(bool v) { u8(v ? 1 : 0); }
    void field(quint8 v) { u8(v); }
    void field(int v) { u32(quint32(v)); }
    void field(quint32 v) { u32(v); }
    void field(quint64 v) { u64(v); }
    void field(qint64 v) { i64(v); }
    void field(double v) { f64(v); }
    void field(const QByteArray& v) { bytes(v); }
    void field(const QString& v) { string(v); }
    void field(const QStringList& v) { strings(v); }
    /// A content key: a byte saying whether there is one, its hash and its size.
    void field(const std::optional<ContentKey>& v)
    {
        u8(v ? 1 : 0);
        u64(v ? v->hash : 0);
        i64(v ? v->size : 0);
    }
    /// An enum in one byte; `max` is for the reader.
    template <class E>
    void enumeration(E v, int /*max*/)
    {
        u8(quint8(v));
    }
    /// A count, then each element as `each` writes it.
    template <class List, class Each>
    void list(const List& elements, int /*minBytes*/, Each each)
    {
        u32(quint32(elements.size()));
        for (const auto& e : elements)
            each(e);
    }
    /// Room for `bytes` in all, so that a body of megabytes is not copied as it grows.
    void reserve(qsizetype bytes) { m_bytes.reserve(bytes); }
    qsizetype size() const { return m_bytes.size(); }
    /// Takes back what was written after the first `size` bytes.
    void truncate(qsizetype size) { m_bytes.truncate(size); }
    /// Writes over what u32() or u64() wrote at `at` (a count known only afterwards).
    void patchU32(qsizetype at, quint32 v);
    void patchU64(qsizetype at, quint64 v);
    const QByteArray& data() const { return m_bytes; }

private:
    QByteArray m_bytes;
};

/// Reads what Writer wrote. Every read checks the bytes left; the first failure sticks (ok() is
/// false and every later read gives zero or empty), so a decoder reads on and checks once.
class Reader
{
public:
    explicit Reader(const QByteArray& bytes)
        : m_bytes(bytes)
    { }
    quint8 u8();
    quint32 u32();
    quint64 u64();
    qint64 i64() { return qint64(u64()); }
    double f64();
    QByteArray bytes();
    QString string() { return QString::fromUtf8(bytes()); }
    QStringList strings();
    /// A count of elements of at least `minBytes` each: 0 and a failure when the bytes left cannot
    /// hold that many, so that no count from the stream sizes an allocation on its own.
    quint32 count(int minBytes);
    /// Writer's field() read back: a bool is 0 or 1, anything else fails.
    void field(bool& v)
    {
        const quint8 b = u8();
        if (b > 1)
            fail();
        v = b == 1;
    }
    void field(quint8& v) { v = u8(); }
    void field(int& v) { v = int(u32()); } ///< past INT_MAX it is negative: the decoders' checks see it
    void field(quint32& v) { v = u32(); }
    void field(quint64& v) { v = u64(); }
    void field(qint64& v) { v = i64(); }
    void field(double& v) { v = f64(); }
    void field(QByteArray& v) { v = bytes(); }
    void field(QString& v) { v = string(); }
    void field(QStringList& v) { v = strings(); }
    /// Writer's content key read back: a negative size fails.
    void field(std::optional<ContentKey>& v)
    {
        bool has = false;
        field(has);
        ContentKey k;
        k.hash = u64();
        k.size = qsizetype(i64());
        if (k.size < 0)
            fail();
        v = has && m_ok ? std::optional<ContentKey>(k) : std::nullopt;
    }
    /// An enum of at most `max`: a byte past it fails and leaves `v` as it was (never an enum
    /// holding a value it does not have).
    template <class E>
    void enumeration(E& v, int max)
    {
        const quint8 b = u8();
        if (b > max)
            fail();
        else
            v = E(b);
    }
    /// A count of elements of at least `minBytes` each (count()), then each as `each` reads it.
    template <class List, class Each>
    void list(List& elements, int minBytes, Each each)
    {
        const quint32 n = count(minBytes);
        elements.reserve(qsizetype(n));
        for (quint32 i = 0; i < n && m_ok; ++i) {
            typename List::value_type e;
            each(e);
            elements.push_back(std::move(e));
        }
    }
    bool ok() const { return m_ok; }
    bool atEnd() const { return m_pos == m_bytes.size(); }
    /// ok() and every byte read.
    bool done() const { return m_ok && atEnd(); }
    void fail() { m_ok = false; }

private:
    bool take(qsizetype n);
    QByteArray m_bytes;
    qsizetype m_pos = 0;
    bool m_ok = true;
};

// The bodies, one encoder and decoder per kind; a decoder returns nothing for a body that does not
// read as a whole.

struct StartRequest
{
    Ros2Options options;
    int graphIntervalMs = 250;
};
QByteArray encodeStart(const StartRequest& r);
std::optional<StartRequest> decodeStart(const QByteArray& body);

struct WatchRequest
{
    QString topic;
    quint64 maxMessages = 0;
    qint64 maxBytes = 0;
};
QByteArray encodeWatch(const WatchRequest& r);
std::optional<WatchRequest> decodeWatch(const QByteArray& body);

/// One string (a topic, an error), or two (a topic and why).
QByteArray encodeStrings(const QStringList& strings);
std::optional<QStringList> decodeStrings(const QByteArray& body, int count);
QByteArray encodeNumber(quint64 n);
std::optional<quint64> decodeNumber(const QByteArray& body);

struct GraphUpdate
{
    Ros2Graph graph;
    quint64 badDiscoveryInfo = 0;
};
/// The most a graph frame takes: a graph larger than this is sent in part, what is left out
/// counted in Ros2Graph::omitted (the parent refuses a frame over kMaxFrameBytes and restarts the
/// child, which would find the same graph again: issue 41).
constexpr qsizetype kMaxGraphBytes = 32 * 1024 * 1024;
/// The graph, its topics in order until `maxBytes`: a topic, endpoint or node that would pass it
/// is left out and counted in the encoded Ros2Graph::omitted.
QByteArray encodeGraph(const GraphUpdate& g, qsizetype maxBytes = kMaxGraphBytes);
std::optional<GraphUpdate> decodeGraph(const QByteArray& body);

struct TopicStats
{
    QString topic;
    Ros2MonitorStats stats;
    bool withMessage = false; ///< stats.lastMessage came with it (else: unchanged since the last)
};
QByteArray encodeStats(const QList<TopicStats>& stats);
std::optional<QList<TopicStats>> decodeStats(const QByteArray& body);

struct SampleBatch
{
    QString topic;
    quint64 dropped = 0; ///< the child's drops of this topic since it was watched
    std::vector<Ros2Sample> samples;
};
QByteArray encodeSamples(const SampleBatch& b);
std::optional<SampleBatch> decodeSamples(const QByteArray& body);

struct ArrivalBatch
{
    quint64 dropped = 0; ///< the child's drops since arrivals were kept
    std::vector<SourceHead> arrivals;
};
QByteArray encodeArrivals(const ArrivalBatch& b);
std::optional<ArrivalBatch> decodeArrivals(const QByteArray& body);

/// A writer or reader this program makes (Ros2Participant::advertise(), subscribe()).
struct EndpointRequest
{
    QString topic;
    QString type; ///< ROS 2 name, `std_msgs/msg/String`
    Ros2Qos qos; ///< reliability, volatile or transient local, depth 1..kMaxDepth
};
constexpr int kMaxDepth = 10000;
QByteArray encodeEndpoint(const EndpointRequest& r);
std::optional<EndpointRequest> decodeEndpoint(const QByteArray& body);

/// The child's answer to an Advertise or a Subscribe: made (why empty) or refused, and why.
struct EndpointDone
{
    bool advertise = true; ///< else a Subscribe
    QString topic;
    QString type;
    QString why;
};
QByteArray encodeEndpointDone(const EndpointDone& d);
std::optional<EndpointDone> decodeEndpointDone(const QByteArray& body);

struct PublishRequest
{
    QString topic;
    QByteArray cdr; ///< with its encapsulation header
};
QByteArray encodePublish(const PublishRequest& r);
std::optional<PublishRequest> decodePublish(const QByteArray& body);

} // namespace Ros2Protocol
