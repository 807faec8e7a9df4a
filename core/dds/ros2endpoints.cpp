// SPDX-License-Identifier: MIT
#include "dds/ros2endpoints.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "dds/ros2rawreader.h"
#include "ros2/ros2names.h"

#include <cstring>
#include <QtEndian>

namespace {

/// rmw_cyclonedds_cpp's create_readwrite_qos for keep last `depth`: reliable (blocking time
/// infinite) or best effort, volatile or transient local (with a durability service of the same
/// history), automatic liveliness with infinite lease, no autodispose; readers do not ignore
/// local writers (rclcpp's default).
dds_qos_t* readwriteQos(const Ros2Qos& q)
{
    const int depth = q.depth > 0 ? q.depth : 10;
    dds_qos_t* qos = dds_create_qos();
    dds_qset_writer_data_lifecycle(qos, false);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
    if (q.reliability == Ros2Qos::Reliable)
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
    else
        dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
    if (q.durability == Ros2Qos::TransientLocal) {
        dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
        dds_qset_durability_service(qos, 0, DDS_HISTORY_KEEP_LAST, depth, DDS_LENGTH_UNLIMITED,
                                    DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    } else {
        dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    }
    dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
    return qos;
}

QByteArray guidOf(dds_entity_t e)
{
    dds_guid_t guid;
    if (dds_get_guid(e, &guid) != DDS_RETCODE_OK)
        return {};
    return QByteArray(reinterpret_cast<const char*>(guid.v), 16);
}

dds_entity_t createTopic(dds_entity_t participant, const QString& topic, const QString& type)
{
    QString ddsType = Ros2Names::ddsType(type);
    if (ddsType.isEmpty())
        ddsType = type;
    return Ros2RawType::createTopic(participant, Ros2Names::ddsTopic(topic).toStdString(), ddsType.toStdString());
}

/// CDR (little endian) after a 4-byte encapsulation header: alignment counts from the body.
class CdrWriter
{
public:
    CdrWriter()
        : m_bytes(QByteArray::fromRawData("\x00\x01\x00\x00", 4))
    { }
    void u32(quint32 v)
    {
        align(4);
        char b[4];
        qToLittleEndian(v, b);
        m_bytes.append(b, 4);
    }
    void string(const QString& s)
    {
        const QByteArray utf8 = s.toUtf8();
        u32(quint32(utf8.size() + 1));
        m_bytes += utf8;
        m_bytes.append('\0');
    }
    void gid(const QByteArray& guid) { m_bytes += guid.left(16).leftJustified(24, '\0'); }
    QByteArray data() const { return m_bytes; }

private:
    void align(int n)
    {
        while ((m_bytes.size() - 4) % n)
            m_bytes.append('\0');
    }
    QByteArray m_bytes;
};

} // namespace

Ros2Endpoints::Ros2Endpoints(dds_entity_t participant, std::function<void()> wake)
    : m_participant(participant)
    , m_wake(std::move(wake))
    , m_gid(guidOf(participant))
{ }

Ros2Endpoints::~Ros2Endpoints()
{
    std::vector<std::unique_ptr<Ros2RawReader>> readers;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        for (auto& [topic, s] : m_subscriptions)
            readers.push_back(std::move(s->reader));
    }
    for (auto& r : readers)
        r->close(); // waits for a callback in flight
    for (auto& [topic, w] : m_writers) {
        dds_delete(w.writer);
        dds_delete(w.topic);
    }
    if (m_infoWriter > 0)
        dds_delete(m_infoWriter);
    if (m_infoTopic > 0)
        dds_delete(m_infoTopic);
}

QByteArray Ros2Endpoints::encodeInfo(const QByteArray& participantGid, const QString& nameSpace,
                                     const QString& name, const QList<QByteArray>& readers,
                                     const QList<QByteArray>& writers)
{
    CdrWriter w;
    w.gid(participantGid);
    const bool withNode = !name.isEmpty();
    w.u32(withNode ? 1 : 0);
    if (withNode) {
        w.string(nameSpace.isEmpty() ? QStringLiteral("/") : nameSpace);
        w.string(name);
        for (const QList<QByteArray>* list : {&readers, &writers}) {
            w.u32(quint32(list->size()));
            for (const QByteArray& g : *list)
                w.gid(g);
        }
    }
    return w.data();
}

void Ros2Endpoints::setNode(const QString& nameSpace, const QString& name)
{
    m_nameSpace = nameSpace;
    m_name = name;
    ++m_changes;
    announce();
}

/// Publishes our node with its endpoints on ros_discovery_info (reliable, transient local, keep
/// last 1, as rmw_dds_common's writer), once a node is set; a node set to nothing is announced
/// without nodes.
void Ros2Endpoints::announce()
{
    if (m_name.isEmpty() && m_infoWriter <= 0)
        return;
    if (m_infoWriter <= 0) {
        m_infoTopic = Ros2RawType::createTopic(m_participant, "ros_discovery_info",
                                               "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");
        Ros2Qos q;
        q.durability = Ros2Qos::TransientLocal;
        q.depth = 1;
        dds_qos_t* qos = readwriteQos(q);
        m_infoWriter = m_infoTopic > 0 ? dds_create_writer(m_participant, m_infoTopic, qos, nullptr) : 0;
        dds_delete_qos(qos);
        if (m_infoWriter <= 0) {
            qCWarning(lcRos2) << "no writer for ros_discovery_info: our node is not announced";
            return;
        }
    }
    QList<QByteArray> readers, writers;
    for (const Ros2Endpoint& e : ownEndpoints())
        (e.publisher ? writers : readers).append(e.gid);
    const QByteArray info = encodeInfo(m_gid, m_nameSpace, m_name, readers, writers);
    const Ros2RawSample sample {reinterpret_cast<const unsigned char*>(info.constData()), std::size_t(info.size())};
    dds_write(m_infoWriter, &sample);
}

Status Ros2Endpoints::advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    unadvertise(topic);
    Writer w;
    w.topic = createTopic(m_participant, topic, type);
    dds_qos_t* q = readwriteQos(qos);
    w.writer = w.topic > 0 ? dds_create_writer(m_participant, w.topic, q, nullptr) : 0;
    dds_delete_qos(q);
    if (w.writer <= 0) {
        if (w.topic > 0)
            dds_delete(w.topic);
        return LocatedError {QStringLiteral("Cyclone DDS could not make a writer of %1 as %2").arg(topic, type)};
    }
    w.endpoint = {guidOf(w.writer), topic, type, true, qos, {}};
    m_writers[topic] = w;
    ++m_changes;
    announce();
    return {};
}

void Ros2Endpoints::unadvertise(const QString& topic)
{
    const auto it = m_writers.find(topic);
    if (it == m_writers.end())
        return;
    dds_delete(it->second.writer);
    dds_delete(it->second.topic);
    m_writers.erase(it);
    ++m_changes;
    announce();
}

bool Ros2Endpoints::publish(const QString& topic, const QByteArray& cdr)
{
    const auto it = m_writers.find(topic);
    if (it == m_writers.end() || cdr.size() < 4 || std::size_t(cdr.size()) > Ros2RawType::kMaxSampleBytes)
        return false;
    const Ros2RawSample sample {reinterpret_cast<const unsigned char*>(cdr.constData()), std::size_t(cdr.size())};
    return dds_write(it->second.writer, &sample) == DDS_RETCODE_OK;
}

Status Ros2Endpoints::subscribe(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    unsubscribe(topic);
    auto s = std::make_unique<Subscription>();
    s->reader = std::make_unique<Ros2RawReader>();
    s->reader->onSample = [this, topic](const Ros2RawSample& sample, const dds_sample_info_t&) {
        onSample(topic, sample.data, sample.size);
    };
    s->reader->topic = createTopic(m_participant, topic, type);
    {
        std::lock_guard<std::mutex> lock(m_mutex); // the listener may call before open() returns
        s->endpoint = {{}, topic, type, false, qos, {}};
        m_subscriptions[topic] = std::move(s);
    }
    Ros2RawReader* reader = m_subscriptions[topic]->reader.get();
    dds_qos_t* q = readwriteQos(qos);
    const bool opened = reader->topic > 0 && reader->open(m_participant, q, true);
    dds_delete_qos(q);
    if (!opened) {
        reader->close();
        std::lock_guard<std::mutex> lock(m_mutex);
        m_subscriptions.erase(topic);
        return LocatedError {QStringLiteral("Cyclone DDS could not make a reader of %1 as %2").arg(topic, type)};
    }
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_subscriptions[topic]->endpoint.gid = guidOf(reader->reader);
    }
    ++m_changes;
    announce();
    return {};
}

void Ros2Endpoints::unsubscribe(const QString& topic)
{
    std::unique_ptr<Subscription> s;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const auto it = m_subscriptions.find(topic);
        if (it == m_subscriptions.end())
            return;
        s = std::move(it->second);
        m_subscriptions.erase(it);
        for (const Ros2Sample& x : s->queue)
            m_queuedBytes -= x.bytes.size();
        m_queuedSamples -= s->queue.size();
    }
    s->reader->close(); // waits for a callback in flight, which then finds no entry
    ++m_changes;
    announce();
}

/// On Cyclone's listener thread.
void Ros2Endpoints::onSample(const QString& topic, const unsigned char* data, std::size_t size)
{
    const qint64 now = wallClockNs();
    bool wake = false;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const auto it = m_subscriptions.find(topic);
        if (it == m_subscriptions.end())
            return;
        Subscription& s = *it->second;
        if (m_queuedBytes + qint64(size) > kMaxQueuedBytes || m_queuedSamples >= kMaxQueuedSamples) {
            ++s.dropped;
            return;
        }
        s.queue.push_back({now, QByteArray(reinterpret_cast<const char*>(data), qsizetype(size))});
        m_queuedBytes += qint64(size);
        ++m_queuedSamples;
        wake = !m_woken.exchange(true);
    }
    if (wake && m_wake)
        m_wake();
}

std::vector<Ros2Engine::Received> Ros2Endpoints::takeReceived(qint64 maxBytes)
{
    std::vector<Ros2Engine::Received> out;
    std::lock_guard<std::mutex> lock(m_mutex);
    qint64 taken = 0;
    for (auto& [topic, s] : m_subscriptions) {
        if (s->queue.empty() || taken >= maxBytes)
            continue;
        Ros2Engine::Received r {topic, s->dropped, {}};
        auto end = s->queue.begin();
        while (end != s->queue.end() && (taken == 0 || taken + end->bytes.size() <= maxBytes)) {
            taken += end->bytes.size();
            ++end;
        }
        r.samples.assign(std::make_move_iterator(s->queue.begin()), std::make_move_iterator(end));
        s->queue.erase(s->queue.begin(), end);
        m_queuedSamples -= r.samples.size();
        out.push_back(std::move(r));
    }
    m_queuedBytes -= taken;
    if (m_queuedSamples == 0)
        m_woken = false; // the next sample wakes the owner again
    return out;
}

QList<Ros2Endpoint> Ros2Endpoints::ownEndpoints() const
{
    QList<Ros2Endpoint> out;
    for (const auto& [topic, w] : m_writers)
        out.append(w.endpoint);
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const auto& [topic, s] : m_subscriptions)
        if (!s->endpoint.gid.isEmpty())
            out.append(s->endpoint);
    return out;
}

QList<Ros2ParticipantInfo> Ros2Endpoints::ownInfo() const
{
    if (m_name.isEmpty())
        return {};
    Ros2NodeInfo node;
    node.nameSpace = m_nameSpace.isEmpty() ? QStringLiteral("/") : m_nameSpace;
    node.name = m_name;
    for (const Ros2Endpoint& e : ownEndpoints())
        (e.publisher ? node.writers : node.readers).append(e.gid);
    return {Ros2ParticipantInfo {m_gid, {node}}};
}
