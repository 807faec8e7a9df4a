// SPDX-License-Identifier: MIT
#include "linkreader.h"

#include "watch/linktrack.h"
#include "wire/mqttclientwire.h"
#include "wire/sourcemessage.h"
#include "wire/stampcodec.h"

#include <algorithm>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
std::optional<quint32> seqOf(const QByteArray& bytes, qsizetype offset)
{
    if (bytes.size() < offset + 4)
        return std::nullopt;
    return qFromLittleEndian<quint32>(bytes.constData() + offset);
}

} // namespace

LinkReader::LinkReader(Tracks& tracks)
    : m_tracks(tracks)
{ }

void LinkReader::index()
{
    m_byMqtt.clear();
    m_byRos.clear();
    m_byLatencyTopic.clear();
    m_heard.clear(); // their indexes are gone: the monitor judges every link after a change of links
    m_moved.clear(); // and a reader of every link's figures takes them all again (linksVersion())
    m_observedNew.clear();
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        LinkTrack& t = *m_tracks[std::size_t(i)];
        t.heard = false;
        t.moved = false;
        t.observedNew = false;
        if (t.observedToHandOver()) // kept before the change of links
            mark(m_observedNew, &LinkTrack::observedNew, i);
        m_byMqtt[t.def.mqttTopic] << i;
        if (!t.def.rosTopic.isEmpty())
            m_byRos[t.def.rosTopic] << i;
        if (const auto a = m_announced.all().constFind(t.def.mqttTopic); a != m_announced.all().cend())
            applyAnnouncement(t, *a); // announced (and retained) before the link was watched
    }
    indexPipeline();
}

void LinkReader::announce(const QString& dataTopic, const QByteArray& payload)
{
    if (const auto type = m_announced.add(dataTopic, payload))
        for (int i : m_byMqtt.value(dataTopic))
            applyAnnouncement(*m_tracks[std::size_t(i)], *type);
}

QStringList LinkReader::rosTopicsToMonitor(const QStringList& rosTopics) const
{
    QStringList out = m_byRos.keys();
    // mqtt_client: the private "latencies/<ros topic>" of the node that publishes the ROS topic.
    for (const QString& t : rosTopics) {
        const qsizetype at = t.indexOf(u"/latencies/"_s);
        if (at < 0)
            continue;
        const QString rosTopic = t.mid(at + 10);
        for (int i : m_byRos.value(rosTopic)) {
            if (m_tracks[std::size_t(i)]->def.direction == Direction::Mqtt2Ros) {
                out << t;
                break;
            }
        }
    }
    return out;
}

void LinkReader::setRosDefinition(const QString& topic, const QString& type, const QString& definition)
{
    const bool header = AnnouncedTypes::headerFirst(type, definition);
    for (int i : m_byRos.value(topic)) {
        LinkTrack& t = *m_tracks[std::size_t(i)];
        (t.def.direction == Direction::Mqtt2Ros ? t.dstHeader : t.srcHeader) = header;
    }
    // A latency topic is found by its name; its index is kept here, where every ROS topic passes.
    const qsizetype at = topic.indexOf(u"/latencies/"_s);
    if (at >= 0 && (type == u"std_msgs/Float64"_s || type == u"std_msgs/msg/Float64"_s)) {
        for (int i : m_byRos.value(topic.mid(at + 10)))
            if (m_tracks[std::size_t(i)]->def.direction == Direction::Mqtt2Ros)
                m_byLatencyTopic.insert(topic, i);
    }
}

QStringList LinkReader::mqttTopics() const
{
    return m_byMqtt.keys();
}

void LinkReader::applyAnnouncement(LinkTrack& t, const AnnouncedType& type)
{
    t.announcedStamped = type.stamped;
    t.ros2 = type.ros2;
    (t.def.direction == Direction::Ros2Mqtt ? t.dstHeader : t.srcHeader) = type.header;
}

void LinkReader::mark(std::vector<int>& list, bool LinkTrack::*in, int i)
{
    LinkTrack& t = *m_tracks[std::size_t(i)];
    if (t.*in)
        return;
    t.*in = true;
    list.push_back(i);
}

std::vector<int> LinkReader::take(std::vector<int>& list, bool LinkTrack::*in)
{
    std::vector<int> out;
    out.swap(list);
    for (int i : out)
        (*m_tracks[std::size_t(i)]).*in = false;
    return out;
}

void LinkReader::heard(int i)
{
    mark(m_heard, &LinkTrack::heard, i);
    mark(m_moved, &LinkTrack::moved, i);
}

void LinkReader::moved(int i)
{
    mark(m_moved, &LinkTrack::moved, i);
}

std::vector<int> LinkReader::takeMoved()
{
    return take(m_moved, &LinkTrack::moved);
}

std::vector<int> LinkReader::takeObservedNew()
{
    std::vector<int> out = take(m_observedNew, &LinkTrack::observedNew);
    std::sort(out.begin(), out.end()); // the first links get the measurement's series first
    return out;
}

void LinkReader::addContent(int i, bool atSource, const ContentKey& key, qint64 ns)
{
    LinkTrack& t = *m_tracks[std::size_t(i)];
    t.addContent(atSource, key, ns);
    if (t.keepObserved && t.observedToHandOver())
        mark(m_observedNew, &LinkTrack::observedNew, i);
}

std::vector<int> LinkReader::takeHeard()
{
    return take(m_heard, &LinkTrack::heard);
}

void LinkReader::addDrained(std::vector<std::vector<SourceHead>> batches)
{
    std::vector<SourceHead> all;
    for (std::vector<SourceHead>& b : batches) {
        if (all.empty())
            all = std::move(b);
        else
            all.insert(all.end(), std::make_move_iterator(b.begin()), std::make_move_iterator(b.end()));
    }
    // Each source's batch is in its arrival order; stable: one topic's messages keep theirs.
    std::stable_sort(all.begin(), all.end(),
                     [](const SourceHead& a, const SourceHead& b) { return a.receivedNs < b.receivedNs; });
    add(all);
}

void LinkReader::add(const std::vector<SourceHead>& batch)
{
    m_read += batch.size();
    for (const SourceHead& a : batch) {
        if (a.graph == SourceGraph::Mqtt)
            addMqttHead(a);
        else
            addRosHead(a);
    }
}

/// What a link matches its two ends by (issue 45): the ROS serialization on a raw link, the text on
/// a primitive one; an MQTT payload a primitive link receives counts as the text its ROS message
/// has; on a JSON link, the CDR its MQTT payload converts to and the ROS 2 message's CDR (mqtt_client
/// bridges JSON on ROS 2 only). None for discovered links (only one end known).
std::optional<ContentKey> LinkReader::contentKey(const LinkDef& link, const SourceHead& head)
{
    if (link.discovered)
        return std::nullopt;
    if (link.rawPayload())
        return head.key;
    if (link.json) {
        if (head.graph == SourceGraph::Mqtt)
            return head.jsonKey;
        return head.graph == SourceGraph::Ros2 ? head.key : std::nullopt;
    }
    if (!link.primitive)
        return std::nullopt;
    if (head.graph != SourceGraph::Mqtt)
        return head.textKey;
    if (link.direction == Direction::Mqtt2Ros && head.textKey)
        return head.textKey;
    return head.key;
}

void LinkReader::addMqttHead(const SourceHead& m)
{
    const auto it = m_byMqtt.constFind(m.topic);
    if (it == m_byMqtt.cend())
        return;
    for (int i : *it) {
        heard(i);
        LinkTrack& t = *m_tracks[std::size_t(i)];
        // mqtt_client's ROS 2 payloads are CDR: their Header has no seq.
        // The content after the stamp the link's announcement says it has (issue 45).
        if (const std::optional<ContentKey> key = contentKey(t.def, m); key && m.keySkipped == t.stampBytes())
            addContent(i, t.def.direction == Direction::Mqtt2Ros, *key, m.receivedNs);
        else if (t.def.json && !t.blind)
            ++t.unconverted; // not JSON, not the link's type, too large (MqttSource::jsonKey())
        if (t.def.direction == Direction::Mqtt2Ros) {
            t.src.add(m.receivedNs, m.size);
            if (t.srcHeader && !t.ros2)
                if (const auto seq = seqOf(m.head, t.stamped() ? MqttClientWire::kRos1StampBytes : 0))
                    t.srcSeq.add(*seq);
            continue;
        }
        t.dst.add(m.receivedNs, m.size);
        qsizetype offset = 0;
        if (t.stamped()) {
            if (const auto s = MqttClientWire::splitStamped(m.head, t.dialect())) {
                if (!t.pipelineLatency)
                    t.addLatency(m.receivedNs, double(m.receivedNs - s->stampNs) / 1e6,
                                 LatencySource::Stamps);
                offset = t.stampBytes();
            }
        }
        if (t.dstHeader && !t.ros2)
            if (const auto seq = seqOf(m.head, offset))
                t.seq.add(*seq);
    }
}

void LinkReader::addRosHead(const SourceHead& a)
{
    if (const auto it = m_byRos.constFind(a.topic); it != m_byRos.cend()) {
        // A ROS 2 Header has no seq: its first bytes are the stamp.
        const bool hasSeq = a.graph == SourceGraph::Ros1;
        for (int i : *it) {
            heard(i);
            LinkTrack& t = *m_tracks[std::size_t(i)];
            if (const std::optional<ContentKey> key = contentKey(t.def, a))
                addContent(i, t.def.direction == Direction::Ros2Mqtt, *key, a.receivedNs);
            if (t.def.direction == Direction::Ros2Mqtt) {
                t.src.add(a.receivedNs, a.size);
                if (t.srcHeader && hasSeq)
                    if (const auto seq = seqOf(a.head, 0))
                        t.srcSeq.add(*seq);
                continue;
            }
            t.dst.add(a.receivedNs, a.size);
            if (t.dstHeader && hasSeq)
                if (const auto seq = seqOf(a.head, 0))
                    t.seq.add(*seq);
        }
    } else if (const auto lt = m_byLatencyTopic.constFind(a.topic); lt != m_byLatencyTopic.cend()) {
        // std_msgs/Float64 in seconds, as mqtt_client publishes it.
        heard(*lt);
        LinkTrack& t = *m_tracks[std::size_t(*lt)];
        if (const auto ns = StampCodec::decodeFloat64Seconds(a.head.left(8)); ns && !t.pipelineLatency)
            t.addLatency(a.receivedNs, double(*ns) / 1e6, LatencySource::LatencyTopic);
    }
}

void LinkReader::setPipeline(const QStringList& stampTopics)
{
    m_pipeline = stampTopics;
    indexPipeline();
}

void LinkReader::indexPipeline()
{
    QHash<QString, int> at;
    for (qsizetype i = 0; i < m_pipeline.size(); ++i) {
        // The suite's configs name their prefix with or without the leading slash.
        QString name = m_pipeline[i];
        if (name.startsWith(u'/'))
            name.remove(0, 1);
        at.insert(name, int(i));
    }
    m_pipelineLinks.clear();
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        LinkTrack& t = *m_tracks[std::size_t(i)];
        QString prefix = t.def.stampPrefix;
        while (prefix.startsWith(u'/'))
            prefix.remove(0, 1);
        while (prefix.endsWith(u'/'))
            prefix.chop(1);
        t.pipelineIn = prefix.isEmpty() ? -1 : at.value(prefix + u"/in"_s, -1);
        t.pipelineOut = prefix.isEmpty() ? -1 : at.value(prefix + u"/out"_s, -1);
        if (t.pipelineIn >= 0 && t.pipelineOut >= 0)
            m_pipelineLinks.push_back(i);
        else
            t.pipelineLatency = false;
    }
}

void LinkReader::addPipelineSample(const std::vector<qint64>& times, qint64 nowNs)
{
    ++m_read;
    for (int i : m_pipelineLinks) {
        LinkTrack& t = *m_tracks[std::size_t(i)];
        if (std::size_t(std::max(t.pipelineIn, t.pipelineOut)) >= times.size())
            continue; // a sample of another pipeline than the one set
        heard(i);
        t.pipelineLatency = true;
        t.addLatency(nowNs,
                     double(times[std::size_t(t.pipelineOut)] - times[std::size_t(t.pipelineIn)]) / 1e6,
                     LatencySource::Pipeline);
    }
}
