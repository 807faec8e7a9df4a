// SPDX-License-Identifier: MIT
#include "linkmonitor.h"

#include "mqtt/mqttconnection.h"
#include "wire/mqttclientwire.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"
#include "wire/stampcodec.h"

#include <algorithm>
#include <limits>
#include <map>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = 1'000'000'000LL;
constexpr qint64 kRateWindowNs = 5 * kSecond;
constexpr qint64 kLossWindowNs = 10 * kSecond;
constexpr qint64 kLossLagNs = kSecond; ///< what the source sent in the last second may still be on its way
constexpr qint64 kLatencyWindowNs = 60 * kSecond;
constexpr qint64 kKeepArrivalsNs
    = kLossWindowNs + kLossLagNs + kSecond; ///< arrivals kept for the loss window
constexpr std::size_t kMaxLatencies = 10000;
constexpr std::size_t kMaxArrivals = 100000;
constexpr std::size_t kHistoryPoints = 600;
constexpr std::size_t kEndedEvents = 1000;
constexpr quint64 kMinLossSample = 10; ///< source messages a loss figure needs

QString directionName(Direction d)
{
    return d == Direction::Ros2Mqtt ? u"ros2mqtt"_s : u"mqtt2ros"_s;
}

/// One end of a link.
struct Side
{
    SideFigures f;
    std::deque<std::pair<qint64, int>> arrivals; ///< (time, bytes) of the last 12 s
    std::deque<std::pair<qint64, quint64>> cumulative; ///< (time, messages) once a second, for loss
    double rateAtLastHz = 0; ///< the rate while it last published: its expected period
    qint64 resumedNs = 0; ///< the first message after a silence (or ever)
    qint64 firstNs = 0; ///< the first message ever (0: none yet)

    void add(qint64 ns, int size)
    {
        if (firstNs == 0)
            firstNs = ns;
        if (f.lastNs == 0 || ns - f.lastNs > std::max<qint64>(3 * expectedPeriodNs(), 1'000'000'000LL))
            resumedNs = ns;
        ++f.messages;
        f.bytes += quint64(size);
        f.lastNs = std::max(f.lastNs, ns);
        arrivals.emplace_back(ns, size);
        if (arrivals.size() > kMaxArrivals)
            arrivals.pop_front();
    }

    void refresh(qint64 now)
    {
        while (!arrivals.empty() && now - arrivals.front().first > kKeepArrivalsNs)
            arrivals.pop_front();
        // As rostopic hz: the intervals between the arrivals of the last 5 s.
        qsizetype n = 0;
        qint64 bytes = 0;
        qint64 first = 0;
        for (auto it = arrivals.crbegin(); it != arrivals.crend() && now - it->first <= kRateWindowNs; ++it) {
            ++n;
            bytes += it->second;
            first = it->first;
        }
        const qint64 last = n ? arrivals.back().first : 0;
        f.rateHz = n >= 2 && last > first ? double(n - 1) / (double(last - first) / 1e9) : 0;
        f.bytesPerSecond = n ? double(bytes) / (double(kRateWindowNs) / 1e9) : 0;
        if (f.rateHz > 0)
            rateAtLastHz = f.rateHz;
        cumulative.emplace_back(now, f.messages);
        while (cumulative.size() > 2 && now - cumulative.front().first > kLossWindowNs + 5 * kSecond)
            cumulative.pop_front();
    }

    /// Messages that arrived in (from, to].
    quint64 countIn(qint64 from, qint64 to) const
    {
        quint64 n = 0;
        for (auto it = arrivals.crbegin(); it != arrivals.crend() && it->first > from; ++it)
            n += it->first <= to;
        return n;
    }

    /// Messages counted up to `ns` (0 before the first refresh).
    quint64 messagesAt(qint64 ns) const
    {
        quint64 m = 0;
        for (const auto& [t, count] : cumulative) {
            if (t > ns)
                break;
            m = count;
        }
        return m;
    }

    qint64 expectedPeriodNs() const { return rateAtLastHz > 0 ? qint64(1e9 / rateAtLastHz) : kSecond; }
};

/// Header.seq at the destination: gaps, duplicates and reordering.
struct SeqTracker
{
    bool started = false;
    quint32 last = 0;
    quint64 gaps = 0;
    quint64 duplicates = 0;
    quint64 reordered = 0;

    void add(quint32 seq)
    {
        constexpr quint32 kRestart = 1'000'000; // a jump this large is a restarted publisher
        if (!started) {
            started = true;
            last = seq;
            return;
        }
        if (seq == last) {
            ++duplicates;
        } else if (seq > last) {
            const quint32 skipped = seq - last - 1;
            if (skipped < kRestart)
                gaps += skipped;
            last = seq;
        } else if (last - seq < kRestart && seq != 0) {
            ++reordered; // counted as a gap when the later one came
            if (gaps > 0)
                --gaps;
        } else {
            last = seq; // restarted from 0 or wrapped
        }
    }
};

bool headerFirst(const QString& type, const QString& definition)
{
    RosTypeRegistry registry;
    if (type.isEmpty() || !registry.addDefinition(type, definition))
        return false;
    const RosMessageType* t = registry.find(type);
    if (!t || t->fields.isEmpty())
        return false;
    const RosField& f = t->fields.first();
    return !f.isArray && (f.type == u"Header"_s || f.type == u"std_msgs/Header"_s);
}

std::optional<quint32> seqOf(const QByteArray& bytes, qsizetype offset)
{
    if (bytes.size() < offset + 4)
        return std::nullopt;
    return qFromLittleEndian<quint32>(bytes.constData() + offset);
}

double percentile(std::vector<double> values, double p)
{
    if (values.empty())
        return qQNaN();
    const std::size_t k = std::min(values.size() - 1, std::size_t(p * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

QString isoTime(qint64 ns)
{
    return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000, Qt::UTC).toString(Qt::ISODateWithMs);
}

QJsonValue number(double v)
{
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}
} // namespace

QString LinkDef::id() const
{
    return u"%1|%2|%3|%4"_s.arg(config, directionName(direction), rosTopic, mqttTopic);
}

QString LinkDef::bridge() const
{
    return client.isEmpty() ? config : client;
}

QList<LinkDef> LinkDef::fromConfig(const BridgeConfig& config, const QString& name)
{
    QList<LinkDef> out;
    const QString client = config.client.values.text(u"id"_s);
    const QString will = config.client.values.text(u"last_will.topic"_s);
    const QByteArray willMessage = config.effective(OptionScope::Client, u"last_will.message"_s).toUtf8();
    for (const Mapping& m : config.mappings) {
        LinkDef l;
        l.config = name;
        l.client = client;
        l.direction = m.direction;
        l.rosTopic = m.rosTopic();
        l.mqttTopic = m.mqttTopic();
        if (l.rosTopic.isEmpty() || l.mqttTopic.isEmpty())
            continue;
        l.stamped = m.direction == Direction::Ros2Mqtt && m.effective(u"inject_timestamp"_s) == u"true"_s;
        l.willTopic = will;
        l.willMessage = will.isEmpty() ? QByteArray() : willMessage;
        l.stampPrefix = m.effective(u"timestamp_topic_prefix"_s);
        out << l;
    }
    return out;
}

LinkDef LinkDef::discoveredAt(const QString& mqttTopic, bool stamped)
{
    LinkDef l;
    l.config = discoveredConfig();
    l.direction = Direction::Ros2Mqtt;
    l.mqttTopic = mqttTopic;
    l.stamped = stamped;
    l.discovered = true;
    return l;
}

QJsonObject LinkFigures::toJson() const
{
    const auto side = [](const SideFigures& s) {
        return QJsonObject {{u"messages"_s, double(s.messages)},
                            {u"bytes"_s, double(s.bytes)},
                            {u"rate_hz"_s, s.rateHz},
                            {u"bytes_per_s"_s, s.bytesPerSecond}};
    };
    return QJsonObject {{u"source"_s, side(source)},
                        {u"destination"_s, side(destination)},
                        {u"lost"_s, double(lost)},
                        {u"loss_percent"_s, lossPercent},
                        {u"seq_gaps"_s, double(seqGaps)},
                        {u"duplicates"_s, double(duplicates)},
                        {u"reordered"_s, double(reordered)},
                        {u"latency_p50_ms"_s, number(latencyP50Ms)},
                        {u"latency_p99_ms"_s, number(latencyP99Ms)},
                        {u"latency_source"_s, latencySourceName(latencySource)},
                        {u"stalls"_s, double(stalls)}};
}

QString LinkFigures::latencySourceName(LatencySource source)
{
    switch (source) {
    case LatencySource::None:
        return u"none"_s;
    case LatencySource::Stamps:
        return u"stamps"_s;
    case LatencySource::LatencyTopic:
        return u"latency_topic"_s;
    case LatencySource::Pipeline:
        return u"pipeline"_s;
    }
    return {};
}

QString WatchEvent::levelName(LinkLevel level)
{
    switch (level) {
    case LinkLevel::Ok:
        return u"ok"_s;
    case LinkLevel::Warning:
        return u"warning"_s;
    case LinkLevel::Alert:
        return u"alert"_s;
    }
    return QString();
}

QJsonObject WatchEvent::toJson() const
{
    QJsonObject o {{u"event"_s, endNs > 0 ? u"end"_s : u"start"_s},
                   {u"subject"_s, subject},
                   {u"config"_s, config},
                   {u"client"_s, client},
                   {u"level"_s, levelName(level)},
                   {u"reasons"_s, QJsonArray::fromStringList(reasons)},
                   {u"detail"_s, detail},
                   {u"start"_s, isoTime(startNs)},
                   {u"figures"_s, (endNs > 0 ? atEnd : atStart).toJson()}};
    if (!direction.isEmpty()) {
        o.insert(u"direction"_s, direction);
        o.insert(u"ros_topic"_s, rosTopic);
        o.insert(u"mqtt_topic"_s, mqttTopic);
    }
    if (endNs > 0) {
        o.insert(u"end"_s, isoTime(endNs));
        o.insert(u"duration_s"_s, durationSeconds());
    }
    return o;
}

RecordedEvent WatchEvent::toRecorded() const
{
    QJsonObject o = toJson();
    o.insert(u"figures_at_start"_s, atStart.toJson());
    RecordedEvent r;
    r.subject = subject;
    r.level = levelName(level);
    r.reasons = reasons;
    r.detail = detail;
    r.startNs = startNs;
    r.endNs = endNs;
    r.json = QJsonDocument(o).toJson(QJsonDocument::Compact);
    return r;
}

struct LinkMonitor::Track
{
    LinkDef def;
    LinkRules rules;
    qint64 startNs = 0;
    Side src;
    Side dst;
    SeqTracker seq; ///< at the destination
    SeqTracker srcSeq; ///< at the source: gaps the publisher made are not the bridge's losses
    /// What the source sent before the destination's first message, which no loss can be told
    /// of (the destination's subscription may not have been up yet); counted once it arrives.
    std::optional<quint64> beforeDestination;
    bool dstHeader = false; ///< the destination's messages start with a Header
    bool srcHeader = false;
    std::optional<bool> announcedStamped;
    bool ros2 = false; ///< announced by mqtt_client for ROS 2: CDR, a 12-byte stamp
    std::deque<std::pair<qint64, double>> latencies;
    quint64 latencySamples = 0;
    std::vector<double> newLatencies;
    LinkFigures figures;
    LinkLevel level = LinkLevel::Ok;
    QStringList reasons;
    std::deque<HistoryPoint> history;
    quint64 lostMax = 0;
    quint64 stalls = 0;
    bool stalled = false;
    qint64 stallEndedNs = 0;

    bool stamped() const { return announcedStamped.value_or(def.stamped); }

    int pipelineIn = -1; ///< index of PREFIX/in in the pipeline
    int pipelineOut = -1;
    bool pipelineLatency = false; ///< a pipeline sample arrived: other latency sources are ignored

    void addLatency(qint64 ns, double ms, LatencySource source)
    {
        if (!std::isfinite(ms) || std::abs(ms) > 86'400'000.0)
            return; // not a latency: a stamp from another day
        figures.latencySource = source;
        latencies.emplace_back(ns, ms);
        if (latencies.size() > kMaxLatencies)
            latencies.pop_front();
        ++latencySamples;
        if (newLatencies.size() < kMaxLatencies)
            newLatencies.push_back(ms);
    }
};

struct LinkMonitor::Bridge
{
    QList<int> links;
    qint64 willDownNs = 0; ///< when its last will arrived (0: not since it last carried data)
    BridgeState state = BridgeState::Unknown;
};

LinkMonitor::LinkMonitor(QObject* parent)
    : QObject(parent)
{ }

LinkMonitor::~LinkMonitor() = default;

void LinkMonitor::setLinks(const QList<LinkDef>& links, qint64 nowNs)
{
    std::map<QString, std::unique_ptr<Track>> old;
    for (auto& t : m_tracks)
        old[t->def.id()] = std::move(t);
    m_tracks.clear();
    QSet<QString> seen;
    for (const LinkDef& def : links) {
        const QString id = def.id();
        if (seen.contains(id))
            continue; // the same mapping twice in one config: one link
        seen.insert(id);
        auto it = old.find(id);
        std::unique_ptr<Track> t;
        bool sameKey = false;
        if (it != old.end() && it->second) {
            t = std::move(it->second);
            const LinkKey was = t->def.key(), is = def.key();
            sameKey = was.rosTopic == is.rosTopic && was.mqttTopic == is.mqttTopic && was.client == is.client
                && was.config == is.config;
        } else {
            t = std::make_unique<Track>();
            t->startNs = nowNs;
        }
        t->def = def;
        if (!sameKey) // the rules of a link that stays are kept: setRules() sets them anew
            t->rules = m_rules.forLink(def.key());
        if (const auto a = m_announced.constFind(def.mqttTopic); a != m_announced.cend())
            applyAnnouncement(*t, *a); // announced (and retained) before the link was watched
        m_tracks.push_back(std::move(t));
    }
    index();
}

void LinkMonitor::setRules(const WatchRules& rules)
{
    m_rules = rules;
    for (auto& t : m_tracks)
        t->rules = m_rules.forLink(t->def.key());
}

void LinkMonitor::index()
{
    m_byMqtt.clear();
    m_byRos.clear();
    m_byId.clear();
    m_byLatencyTopic.clear();
    m_willTopics.clear();
    QHash<QString, std::shared_ptr<Bridge>> bridges;
    for (int i = 0; i < int(m_tracks.size()); ++i) {
        const LinkDef& d = m_tracks[std::size_t(i)]->def;
        m_byMqtt[d.mqttTopic] << i;
        if (!d.rosTopic.isEmpty())
            m_byRos[d.rosTopic] << i;
        m_byId.insert(d.id(), i);
        if (d.discovered)
            continue; // whose bridge it is, the broker does not say
        std::shared_ptr<Bridge>& b = bridges[d.bridge()];
        if (!b) {
            b = std::make_shared<Bridge>();
            if (const auto old = m_bridges.value(d.bridge())) { // what it knew stays
                b->willDownNs = old->willDownNs;
                b->state = old->state;
            }
        }
        b->links << i;
        if (!d.willTopic.isEmpty() && !m_willTopics.value(d.willTopic).contains(d.bridge()))
            m_willTopics[d.willTopic] << d.bridge();
    }
    m_bridges = bridges;
    indexPipeline();
}

int LinkMonitor::linkCount() const
{
    return int(m_tracks.size());
}

const LinkDef& LinkMonitor::link(int index) const
{
    return m_tracks.at(std::size_t(index))->def;
}

int LinkMonitor::indexOf(const QString& id) const
{
    return m_byId.value(id, -1);
}

LinkFigures LinkMonitor::figures(int index) const
{
    const Track& t = *m_tracks.at(std::size_t(index));
    LinkFigures f = t.figures;
    // Counts are live; rates and percentiles are those of the last refresh.
    f.source.messages = t.src.f.messages;
    f.source.bytes = t.src.f.bytes;
    f.source.lastNs = t.src.f.lastNs;
    f.destination.messages = t.dst.f.messages;
    f.destination.bytes = t.dst.f.bytes;
    f.destination.lastNs = t.dst.f.lastNs;
    f.seqGaps = t.seq.gaps;
    f.duplicates = t.seq.duplicates;
    f.reordered = t.seq.reordered;
    f.latencySamples = t.latencySamples;
    f.stalls = t.stalls;
    return f;
}

LinkLevel LinkMonitor::level(int index) const
{
    return m_tracks.at(std::size_t(index))->level;
}

QStringList LinkMonitor::reasons(int index) const
{
    return m_tracks.at(std::size_t(index))->reasons;
}

std::vector<LinkMonitor::HistoryPoint> LinkMonitor::history(int index) const
{
    const auto& h = m_tracks.at(std::size_t(index))->history;
    return {h.begin(), h.end()};
}

std::vector<double> LinkMonitor::takeNewLatencies(int index)
{
    std::vector<double> out;
    out.swap(m_tracks.at(std::size_t(index))->newLatencies);
    return out;
}

LinkMonitor::BridgeState LinkMonitor::bridgeState(const QString& bridge) const
{
    const auto b = m_bridges.value(bridge);
    return b ? b->state : BridgeState::Unknown;
}

QStringList LinkMonitor::bridges() const
{
    QStringList names = m_bridges.keys();
    names.sort();
    return names;
}

QList<WatchEvent> LinkMonitor::openEvents() const
{
    QList<WatchEvent> out = m_open.values();
    std::sort(out.begin(), out.end(),
              [](const WatchEvent& a, const WatchEvent& b) { return a.startNs < b.startNs; });
    return out;
}

QList<WatchEvent> LinkMonitor::endedEvents() const
{
    return {m_ended.begin(), m_ended.end()};
}

QStringList LinkMonitor::rosTopicsToMonitor(const QStringList& rosTopics) const
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

void LinkMonitor::setRosDefinition(const QString& topic, const QString& type, const QString& definition)
{
    const bool header = headerFirst(type, definition);
    for (int i : m_byRos.value(topic)) {
        Track& t = *m_tracks[std::size_t(i)];
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

void LinkMonitor::addMqttControl(const std::vector<MqttMessage>& batch)
{
    const QString typePrefix = MqttClientWire::typeTopicPrefix();
    for (const MqttMessage& m : batch) {
        if (m.topic.startsWith(typePrefix)) {
            announce(MqttClientWire::dataTopicOf(m.topic), m.payload);
            continue;
        }
        if (const auto it = m_willTopics.constFind(m.topic); it != m_willTopics.cend()) {
            for (const QString& name : *it) {
                auto b = m_bridges.value(name);
                const int first = b && !b->links.isEmpty() ? b->links.first() : -1;
                if (first >= 0 && m.payload == m_tracks[std::size_t(first)]->def.willMessage && !m.retained)
                    b->willDownNs = m.receivedNs;
            }
        }
    }
}

QStringList LinkMonitor::mqttTopics() const
{
    return m_byMqtt.keys();
}

void LinkMonitor::announce(const QString& dataTopic, const QByteArray& payload)
{
    // mqtt_client may announce with every message: each change is decoded once.
    const std::size_t hash = qHash(payload);
    auto known = m_announcementHash.find(dataTopic);
    if (known != m_announcementHash.end() && *known == hash)
        return;
    if (known == m_announcementHash.end()) {
        if (m_announcementHash.size() >= kMaxAnnounced) {
            ++m_droppedAnnouncements; // a broker's worth of made-up topics: bounded
            return;
        }
        known = m_announcementHash.insert(dataTopic, hash);
    }
    *known = hash;
    const auto type = MqttClientWire::decodeType(payload);
    if (!type)
        return;
    const AnnouncedType announced {type->name, type->stamped, headerFirst(type->name, type->definition),
                                   type->dialect == MqttClientWire::Dialect::Ros2};
    m_announced.insert(dataTopic, announced);
    for (int i : m_byMqtt.value(dataTopic))
        applyAnnouncement(*m_tracks[std::size_t(i)], announced);
}

void LinkMonitor::applyAnnouncement(Track& t, const AnnouncedType& type)
{
    t.announcedStamped = type.stamped;
    t.ros2 = type.ros2;
    (t.def.direction == Direction::Ros2Mqtt ? t.dstHeader : t.srcHeader) = type.header;
}

void LinkMonitor::add(const std::vector<SourceHead>& batch)
{
    for (const SourceHead& a : batch) {
        if (a.graph == SourceGraph::Mqtt)
            addMqttHead(a);
        else
            addRosHead(a);
    }
}

void LinkMonitor::addMqttHead(const SourceHead& m)
{
    const auto it = m_byMqtt.constFind(m.topic);
    if (it == m_byMqtt.cend())
        return;
    for (int i : *it) {
        Track& t = *m_tracks[std::size_t(i)];
        // mqtt_client's ROS 2 payloads are CDR: their Header has no seq.
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
            const auto dialect = t.ros2 ? MqttClientWire::Dialect::Ros2 : MqttClientWire::Dialect::Ros1;
            if (const auto s = MqttClientWire::splitStamped(m.head, dialect)) {
                if (!t.pipelineLatency)
                    t.addLatency(m.receivedNs, double(m.receivedNs - s->stampNs) / 1e6, LatencySource::Stamps);
                offset = MqttClientWire::stampBytes(dialect);
            }
        }
        if (t.dstHeader && !t.ros2)
            if (const auto seq = seqOf(m.head, offset))
                t.seq.add(*seq);
    }
}

void LinkMonitor::addRosHead(const SourceHead& a)
{
    if (const auto it = m_byRos.constFind(a.topic); it != m_byRos.cend()) {
        // A ROS 2 Header has no seq: its first bytes are the stamp.
        const bool hasSeq = a.graph == SourceGraph::Ros1;
        for (int i : *it) {
            Track& t = *m_tracks[std::size_t(i)];
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
        Track& t = *m_tracks[std::size_t(*lt)];
        if (const auto ns = StampCodec::decodeFloat64Seconds(a.head.left(8)); ns && !t.pipelineLatency)
            t.addLatency(a.receivedNs, double(*ns) / 1e6, LatencySource::LatencyTopic);
    }
}

void LinkMonitor::setPipeline(const QStringList& stampTopics)
{
    m_pipeline = stampTopics;
    indexPipeline();
}

void LinkMonitor::indexPipeline()
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
        Track& t = *m_tracks[std::size_t(i)];
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

void LinkMonitor::addPipelineSample(const std::vector<qint64>& times, qint64 nowNs)
{
    for (int i : m_pipelineLinks) {
        Track& t = *m_tracks[std::size_t(i)];
        if (std::size_t(std::max(t.pipelineIn, t.pipelineOut)) >= times.size())
            continue; // a sample of another pipeline than the one set
        t.pipelineLatency = true;
        t.addLatency(nowNs,
                     double(times[std::size_t(t.pipelineOut)] - times[std::size_t(t.pipelineIn)]) / 1e6,
                     LatencySource::Pipeline);
    }
}

void LinkMonitor::refreshStatistics(qint64 nowNs)
{
    for (auto& tp : m_tracks) {
        Track& t = *tp;
        t.src.refresh(nowNs);
        t.dst.refresh(nowNs);
        LinkFigures& f = t.figures;
        f.source = t.src.f;
        f.destination = t.dst.f;
        // Loss: what the source sent in a 10 s window that ended a second ago (messages on their
        // way are not lost) against what arrived in as long a window. The edges of two windows can cut one
        // message differently: one missing message is not counted, so a loss shown is a loss.
        // Before the destination's first message nothing is judged: at a start the monitor's
        // subscription at the source is up before that at the destination (a ROS subscriber's
        // connection takes a while), and the first messages would look lost.
        if (!t.beforeDestination && t.dst.firstNs > 0) {
            const quint64 since = t.src.countIn(t.dst.firstNs - 1, std::numeric_limits<qint64>::max());
            const quint64 before = t.src.f.messages - std::min(since, t.src.f.messages);
            t.beforeDestination = before > 0 ? before - 1 : 0; // the one that arrived was sent before
        }
        const quint64 unjudged = t.beforeDestination.value_or(0);
        const quint64 srcThen = t.src.messagesAt(nowNs - kLossLagNs);
        // The destination's window is the source's, shifted by the typical latency where stamps tell it.
        const double p50 = t.figures.latencyP50Ms;
        const qint64 shift = std::isfinite(p50) ? std::clamp<qint64>(qint64(p50 * 1e6), 0, kLossLagNs) : 0;
        qint64 from = nowNs - kLossLagNs - kLossWindowNs;
        if (t.dst.firstNs > 0)
            from = std::max(from, t.dst.firstNs - 1 - shift);
        const quint64 sent = t.src.countIn(from, nowNs - kLossLagNs);
        const quint64 got = t.dst.countIn(from + shift, nowNs - kLossLagNs + shift);
        f.lossPercent
            = sent >= kMinLossSample && sent > got + 1 ? 100.0 * double(sent - got - 1) / double(sent) : 0;
        // Lost for sure: what the source sent a second ago and never arrived, or, once the source
        // pauses, everything it sent that never arrived; Header.seq gaps are losses as well.
        const bool paused = t.src.f.lastNs > 0
            && nowNs - t.src.f.lastNs > std::max<qint64>(3 * t.src.expectedPeriodNs(), kSecond);
        const quint64 sentBy = (paused ? t.src.f.messages : srcThen) - std::min(unjudged, srcThen);
        if (sentBy > t.dst.f.messages)
            t.lostMax = std::max(t.lostMax, sentBy - t.dst.f.messages);
        if (t.seq.gaps > t.srcSeq.gaps) // gaps the bridge made: lost for sure
            t.lostMax = std::max(t.lostMax, t.seq.gaps - t.srcSeq.gaps);
        f.lost = t.lostMax;
        while (!t.latencies.empty() && nowNs - t.latencies.front().first > kLatencyWindowNs)
            t.latencies.pop_front();
        std::vector<double> values;
        values.reserve(t.latencies.size());
        for (const auto& l : t.latencies)
            values.push_back(l.second);
        f.latencyP50Ms = percentile(values, 0.50);
        f.latencyP99Ms = percentile(std::move(values), 0.99);
        t.history.push_back({nowNs, t.dst.f.rateHz, f.latencyP99Ms, t.level});
        if (t.history.size() > kHistoryPoints)
            t.history.pop_front();
    }
}

void LinkMonitor::tick(qint64 nowNs)
{
    const bool refresh = nowNs - m_lastRefreshNs >= kSecond;
    if (refresh) {
        m_lastRefreshNs = nowNs;
        refreshStatistics(nowNs);
    }
    for (int i = 0; i < int(m_tracks.size()); ++i)
        evaluate(i, nowNs);
    for (auto it = m_bridges.begin(); it != m_bridges.end(); ++it)
        evaluateBridge(it.key(), **it, nowNs);
    if (refresh)
        emit refreshed();
}

namespace {
/// The level at which `value` passes `t` (above when `above`, else below).
LinkLevel levelOf(const Threshold& t, double value, bool above)
{
    const auto passes
        = [&](double limit) { return std::isfinite(limit) && (above ? value > limit : value < limit); };
    if (passes(t.alert))
        return LinkLevel::Alert;
    if (passes(t.warning))
        return LinkLevel::Warning;
    return LinkLevel::Ok;
}

/// Silence `silenceNs` against limits in seconds, or in periods of `periodNs` (at least 1 s).
LinkLevel silenceLevel(const Threshold& seconds, const Threshold& periods, qint64 periodNs, qint64 silenceNs)
{
    const auto limitNs = [&](double s, double p) -> double {
        if (std::isfinite(s))
            return s * 1e9;
        if (std::isfinite(p))
            return std::max(p * double(periodNs), 1e9);
        return qInf();
    };
    if (double(silenceNs) > limitNs(seconds.alert, periods.alert))
        return LinkLevel::Alert;
    if (double(silenceNs) > limitNs(seconds.warning, periods.warning))
        return LinkLevel::Warning;
    return LinkLevel::Ok;
}
} // namespace

void LinkMonitor::evaluate(int i, qint64 nowNs)
{
    Track& t = *m_tracks[std::size_t(i)];
    const LinkRules& r = t.rules;
    const LinkFigures f = figures(i);
    const qint64 period = t.src.expectedPeriodNs();
    const qint64 srcSilence = t.src.f.lastNs > 0 ? nowNs - t.src.f.lastNs : -1;
    // Silence at the destination counts from its last message, or from when the source (re)started.
    const qint64 dstSilence = nowNs - std::max({t.dst.f.lastNs, t.startNs, t.src.resumedNs});
    // Shorter than the shortest stall (1 s): a source that stops is never taken for a stall.
    const bool sourcePublishes = srcSilence >= 0 && srcSilence <= std::max<qint64>(2 * period, kSecond / 2);

    LinkLevel level = LinkLevel::Ok;
    QStringList reasons;
    QString detail;
    const auto add = [&](LinkLevel l, const QString& reason, const QString& text) {
        if (l == LinkLevel::Ok)
            return;
        reasons << reason;
        if (l > level || detail.isEmpty())
            detail = text;
        level = std::max(level, l);
    };
    const LinkLevel stopped = srcSilence < 0
        ? LinkLevel::Ok
        : silenceLevel(r[LinkRules::SourceStoppedSeconds], Threshold(), period, srcSilence);
    const LinkLevel stall = sourcePublishes
        ? silenceLevel(r[LinkRules::StallSeconds], r[LinkRules::StallPeriods], period, dstSilence)
        : LinkLevel::Ok;
    add(stopped, u"source_stopped"_s,
        tr("the source %1 has been silent for %2 s")
            .arg(t.def.sourceTopic())
            .arg(double(srcSilence) / 1e9, 0, 'f', 1));
    add(stall, u"stall"_s,
        tr("nothing arrived on %1 for %2 s while %3 publishes")
            .arg(t.def.destinationTopic())
            .arg(double(dstSilence) / 1e9, 0, 'f', 1)
            .arg(t.def.sourceTopic()));
    // Right after a stall, a start or a restart of either end the windows still hold the outage, which has
    // its own event: loss and rates are judged again once the windows are past it. Both ends must have been
    // heard over the whole window (they subscribe at different moments).
    const bool settled = nowNs - std::max({t.stallEndedNs, t.src.resumedNs, t.dst.resumedNs})
        > kLossWindowNs + kLossLagNs + kSecond;
    if (sourcePublishes && stall == LinkLevel::Ok && settled) {
        add(levelOf(r[LinkRules::MaxLossPercent], f.lossPercent, true), u"loss"_s,
            tr("%1 % of the messages lost").arg(f.lossPercent, 0, 'f', 1));
        if (f.source.rateHz > 0) {
            add(levelOf(r[LinkRules::MinRateHz], f.destination.rateHz, false), u"rate"_s,
                tr("%1 Hz at the destination").arg(f.destination.rateHz, 0, 'f', 1));
            add(levelOf(r[LinkRules::MinRatePercent], 100.0 * f.destination.rateHz / f.source.rateHz, false),
                u"rate_share"_s,
                tr("%1 Hz at the destination for %2 Hz at the source")
                    .arg(f.destination.rateHz, 0, 'f', 1)
                    .arg(f.source.rateHz, 0, 'f', 1));
        }
        if (std::isfinite(f.latencyP99Ms))
            add(levelOf(r[LinkRules::LatencyP99Ms], f.latencyP99Ms, true), u"latency"_s,
                tr("latency p99 %1 ms").arg(f.latencyP99Ms, 0, 'f', 1));
    }
    const bool stalled = reasons.contains(u"stall"_s);
    if (stalled && !t.stalled)
        ++t.stalls;
    if (!stalled && t.stalled)
        t.stallEndedNs = nowNs;
    t.stalled = stalled;
    t.reasons = reasons;
    if (level == t.level) {
        // Same level, same event: it gathers every reason it had.
        if (auto it = m_open.find(t.def.id()); it != m_open.end())
            for (const QString& r : std::as_const(reasons))
                if (!it->reasons.contains(r))
                    it->reasons << r;
        return;
    }
    t.level = level;
    change(t.def.id(), &t.def, level, reasons, detail, figures(i), nowNs);
}

void LinkMonitor::evaluateBridge(const QString& name, Bridge& b, qint64 nowNs)
{
    bool carries = false;
    bool stalled = false;
    qint64 lastData = 0;
    for (int i : std::as_const(b.links)) {
        const Track& t = *m_tracks[std::size_t(i)];
        lastData = std::max(lastData, t.dst.f.lastNs);
        const qint64 limit = std::max<qint64>(5 * t.src.expectedPeriodNs(), kSecond);
        carries = carries || (t.dst.f.lastNs > 0 && nowNs - t.dst.f.lastNs <= limit);
        stalled = stalled || t.reasons.contains(u"stall"_s);
    }
    if (b.willDownNs > 0 && lastData > b.willDownNs)
        b.willDownNs = 0; // it carries data again
    BridgeState state = BridgeState::Unknown;
    if (b.willDownNs > 0)
        state = BridgeState::Down;
    else if (carries)
        state = BridgeState::Up;
    else if (stalled)
        state = BridgeState::Down;
    if (state == b.state)
        return;
    b.state = state;
    const bool down = state == BridgeState::Down;
    const QString detail = !down ? QString()
        : b.willDownNs > 0       ? tr("the bridge %1 left its last will").arg(name)
                                 : tr("the bridge %1 carries nothing while its sources publish").arg(name);
    LinkDef bridge;
    if (!b.links.isEmpty())
        bridge = m_tracks[std::size_t(b.links.first())]->def;
    change(u"bridge:"_s + name, &bridge, down ? LinkLevel::Alert : LinkLevel::Ok,
           down ? QStringList {u"bridge_down"_s} : QStringList(), detail, LinkFigures(), nowNs);
}

void LinkMonitor::change(const QString& subject, const LinkDef* link, LinkLevel level,
                         const QStringList& reasons, const QString& detail, const LinkFigures& figures,
                         qint64 nowNs)
{
    if (auto it = m_open.find(subject); it != m_open.end()) {
        WatchEvent ended = *it;
        m_open.erase(it);
        ended.endNs = nowNs;
        ended.atEnd = figures;
        m_ended.push_back(ended);
        if (m_ended.size() > kEndedEvents)
            m_ended.pop_front();
        emit eventEnded(ended);
    }
    if (level == LinkLevel::Ok)
        return;
    WatchEvent e;
    e.subject = subject;
    e.config = link->config;
    e.client = link->client;
    if (!subject.startsWith(u"bridge:"_s)) {
        e.direction = directionName(link->direction);
        e.rosTopic = link->rosTopic;
        e.mqttTopic = link->mqttTopic;
    }
    e.level = level;
    e.reasons = reasons;
    e.detail = detail;
    e.startNs = nowNs;
    e.atStart = figures;
    m_open.insert(subject, e);
    emit eventStarted(e);
}

void LinkMonitor::closeAll(qint64 nowNs)
{
    const QList<QString> subjects = m_open.keys();
    for (const QString& s : subjects) {
        const int i = m_byId.value(s, -1);
        change(s, nullptr, LinkLevel::Ok, {}, QString(), i >= 0 ? figures(i) : LinkFigures(), nowNs);
    }
}
