// SPDX-License-Identifier: MIT
#include "dds/ros2engine.h"

#include "base/eventbuffer.h"
#include "base/logging.h"
#include "base/newestqueue.h"
#include "base/ratewindow.h"
#include "base/wallclock.h"
#include "ros2/ros2names.h"
#include "dds/ros2rawreader.h"

#include <atomic>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/log/Log.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <map>
#include <mutex>
#include <QtGlobal>
#include <set>

using namespace eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

namespace {

constexpr std::size_t kMaxEndpoints = 200'000;

QByteArray gidBytes(const rtps::GUID_t& guid)
{
    QByteArray g(16, '\0');
    std::copy(guid.guidPrefix.value, guid.guidPrefix.value + 12, g.data());
    std::copy(guid.entityId.value, guid.entityId.value + 4, g.data() + 12);
    return g;
}

QByteArray prefixBytes(const rtps::GuidPrefix_t& prefix)
{
    return QByteArray(reinterpret_cast<const char*>(prefix.value), 12);
}

Ros2Qos qosOf(const ReliabilityQosPolicy& r, const DurabilityQosPolicy& d)
{
    Ros2Qos q;
    q.reliability = r.kind == RELIABLE_RELIABILITY_QOS ? Ros2Qos::Reliable : Ros2Qos::BestEffort;
    switch (d.kind) {
    case VOLATILE_DURABILITY_QOS:
        q.durability = Ros2Qos::Volatile;
        break;
    case TRANSIENT_LOCAL_DURABILITY_QOS:
        q.durability = Ros2Qos::TransientLocal;
        break;
    case TRANSIENT_DURABILITY_QOS:
        q.durability = Ros2Qos::Transient;
        break;
    case PERSISTENT_DURABILITY_QOS:
        q.durability = Ros2Qos::Persistent;
        break;
    }
    return q;
}

} // namespace

struct Ros2Engine::Private : public DomainParticipantListener
{
    mutable std::mutex mutex;
    std::map<QByteArray, Ros2Endpoint> endpoints; ///< ROS topics' writers and readers, by gid
    std::map<QByteArray, QString> services; ///< service endpoints: gid to service name
    std::map<QByteArray, Ros2ParticipantInfo> infos; ///< by the announcing participant's prefix
    std::set<QByteArray> participants; ///< remote participants' prefixes
    std::set<QByteArray> badInfoFrom;
    quint64 badInfo = 0;
    quint64 ignoredEndpoints = 0;
    QByteArray ownPrefix;
    std::atomic<quint64> changes {1}; ///< bumped by the listener threads at every change of the tables

    /// A subscribed topic: monitored, watched, or both.
    struct Monitored
    {
        std::unique_ptr<Ros2RawReader> reader;
        Ros2MonitorStats stats;
        RateWindow rates;
        bool monitored = false; ///< asked for by monitor()
        std::unique_ptr<NewestQueue<Ros2Sample>> watched; ///< set while watchMessages() asks
    };
    std::map<QString, Monitored> monitored; ///< under `mutex`
    std::unique_ptr<EventBuffer<Ros2Arrival>> arrivals; ///< set by keepArrivals(), under `mutex`

    DomainParticipant* participant = nullptr;
    Subscriber* subscriber = nullptr;
    std::unique_ptr<Ros2RawReader> infoReader;

    void forgetParticipant(const QByteArray& prefix)
    {
        participants.erase(prefix);
        infos.erase(prefix);
        for (auto* table : {&endpoints})
            for (auto it = table->begin(); it != table->end();)
                it = it->first.startsWith(prefix) ? table->erase(it) : std::next(it);
        for (auto it = services.begin(); it != services.end();)
            it = it->first.startsWith(prefix) ? services.erase(it) : std::next(it);
    }

    bool own(const rtps::GUID_t& guid) const { return prefixBytes(guid.guidPrefix) == ownPrefix; }

    void on_participant_discovery(DomainParticipant*, rtps::ParticipantDiscoveryInfo&& info) override
    {
        const QByteArray prefix = prefixBytes(info.info.m_guid.guidPrefix);
        std::lock_guard<std::mutex> lock(mutex);
        if (prefix == ownPrefix)
            return;
        switch (info.status) {
        case rtps::ParticipantDiscoveryInfo::DISCOVERED_PARTICIPANT:
        case rtps::ParticipantDiscoveryInfo::CHANGED_QOS_PARTICIPANT:
            participants.insert(prefix);
            break;
        case rtps::ParticipantDiscoveryInfo::REMOVED_PARTICIPANT:
        case rtps::ParticipantDiscoveryInfo::DROPPED_PARTICIPANT:
        default:
            forgetParticipant(prefix);
            break;
        }
        ++changes;
    }

    void endpoint(const rtps::GUID_t& guid, const std::string& ddsTopic, const std::string& ddsType,
                  const Ros2Qos& qos, bool publisher, bool removed)
    {
        if (own(guid))
            return;
        const QByteArray gid = gidBytes(guid);
        std::lock_guard<std::mutex> lock(mutex);
        ++changes;
        if (removed) {
            endpoints.erase(gid);
            services.erase(gid);
            return;
        }
        QString name;
        const auto kind = Ros2Names::classifyDdsTopic(QString::fromStdString(ddsTopic), &name);
        if (kind == Ros2Names::TopicKind::Other)
            return;
        if (endpoints.size() + services.size() >= kMaxEndpoints && !endpoints.count(gid)
            && !services.count(gid)) {
            ++ignoredEndpoints;
            return;
        }
        if (kind != Ros2Names::TopicKind::Topic) {
            services[gid] = name;
            return;
        }
        Ros2Endpoint& e = endpoints[gid];
        e.gid = gid;
        e.topic = name;
        e.type = Ros2Names::rosType(QString::fromStdString(ddsType));
        e.publisher = publisher;
        e.qos = qos;
    }

    void on_publisher_discovery(DomainParticipant*, rtps::WriterDiscoveryInfo&& info) override
    {
        const auto& w = info.info;
        endpoint(w.guid(), w.topicName().to_string(), w.typeName().to_string(),
                 qosOf(w.m_qos.m_reliability, w.m_qos.m_durability), true,
                 info.status == rtps::WriterDiscoveryInfo::REMOVED_WRITER);
    }

    void on_subscriber_discovery(DomainParticipant*, rtps::ReaderDiscoveryInfo&& info) override
    {
        const auto& r = info.info;
        endpoint(r.guid(), r.topicName().to_string(), r.typeName().to_string(),
                 qosOf(r.m_qos.m_reliability, r.m_qos.m_durability), false,
                 info.status == rtps::ReaderDiscoveryInfo::REMOVED_READER);
    }

    void onDiscoveryInfo(const Ros2RawSample& sample, const SampleInfo& info)
    {
        const QByteArray prefix = prefixBytes(info.sample_identity.writer_guid().guidPrefix);
        const QByteArray bytes(reinterpret_cast<const char*>(sample.bytes.data()),
                               qsizetype(sample.bytes.size()));
        QString error;
        auto parsed = Ros2DiscoveryInfo::parse(bytes, &error);
        std::lock_guard<std::mutex> lock(mutex);
        if (prefix == ownPrefix)
            return;
        if (!parsed) {
            ++badInfo;
            ++changes; // the graph is the same, but what is shown with it (the count) is not
            // the first 16 participants are named in the log, once each; the set stays that small
            if (badInfoFrom.size() < 16 && badInfoFrom.insert(prefix).second)
                qCWarning(lcRos2).noquote()
                    << "ros_discovery_info from participant" << prefix.toHex() << "not read:" << error;
            return;
        }
        // a participant speaks for itself only: its announcement is kept under its own prefix
        infos[prefix] = std::move(*parsed);
        ++changes;
    }

    void onSample(const QString& topic, const Ros2RawSample& sample)
    {
        const qint64 now = wallClockNs();
        std::lock_guard<std::mutex> lock(mutex);
        const auto it = monitored.find(topic);
        if (it == monitored.end())
            return;
        Ros2MonitorStats& s = it->second.stats;
        ++s.messages;
        s.bytes += sample.bytes.size();
        s.lastSize = int(sample.bytes.size());
        s.lastNs = now;
        s.lastMessage
            = QByteArray(reinterpret_cast<const char*>(sample.bytes.data()), qsizetype(sample.bytes.size()));
        it->second.rates.add(now, s.lastSize);
        if (it->second.watched)
            it->second.watched->push({now, s.lastMessage}, s.lastSize); // shares the bytes
        if (arrivals && it->second.monitored) // as keepArrivals() says: not those only watched
            arrivals->push(
                Ros2Arrival {topic, now, s.lastSize, s.lastMessage.mid(4, Ros2Arrival::kHeadBytes)});
    }

    Topic* topicFor(const std::string& ddsTopic, const std::string& ddsType)
    {
        if (!participant->find_type(ddsType).empty()
            || TypeSupport(new Ros2RawType(ddsType)).register_type(participant) == ReturnCode_t::RETCODE_OK) {
            if (auto* desc = participant->lookup_topicdescription(ddsTopic)) {
                auto* t = dynamic_cast<Topic*>(desc);
                return t && t->get_type_name() == ddsType ? t : nullptr;
            }
            return participant->create_topic(ddsTopic, ddsType, TOPIC_QOS_DEFAULT);
        }
        return nullptr;
    }

    /// Ends a use of a topic's subscription (monitor() or watchMessages()), and the subscription
    /// with the last one.
    void release(const QString& topic, bool monitorUse)
    {
        std::unique_ptr<Ros2RawReader> reader;
        {
            std::lock_guard<std::mutex> lock(mutex);
            const auto it = monitored.find(topic);
            if (it == monitored.end())
                return;
            if (monitorUse)
                it->second.monitored = false;
            else
                it->second.watched.reset();
            if (it->second.monitored || it->second.watched)
                return;
            reader = std::move(it->second.reader);
            monitored.erase(it);
        }
        if (reader)
            deleteReader(*reader); // waits for a callback in flight; onSample then finds no entry
    }

    void deleteReader(Ros2RawReader& r)
    {
        if (r.reader)
            subscriber->delete_datareader(r.reader);
        if (r.topic)
            participant->delete_topic(r.topic);
        r.reader = nullptr;
        r.topic = nullptr;
    }
};

Ros2Engine::Ros2Engine(QObject* parent)
    : QObject(parent)
{
    m_timer.setInterval(kPollMs);
    connect(&m_timer, &QTimer::timeout, this, &Ros2Engine::refresh);
}

Ros2Engine::~Ros2Engine()
{
    stop();
}

bool Ros2Engine::isRunning() const
{
    return d && d->participant;
}

bool Ros2Engine::start(const Ros2Options& options, QString* error)
{
    stop();
    if (options.domain < 0 || options.domain > Ros2Options::kMaxDomain) {
        if (error)
            *error = tr("domain %1 is out of range: ROS 2 domains are 0 to %2")
                         .arg(options.domain)
                         .arg(Ros2Options::kMaxDomain);
        return false;
    }
    static std::once_flag quiet;
    std::call_once(quiet, [] { Log::SetVerbosity(Log::Error); });

    m_options = options;
    d = std::make_shared<Private>();
    DomainParticipantQos qos = PARTICIPANT_QOS_DEFAULT;
    qos.name("bridgescope");
    // as rmw does, so that ROS 2 tools show what we are
    const std::string enclave = "enclave=/;";
    qos.user_data().data_vec(std::vector<rtps::octet>(enclave.begin(), enclave.end()));
    // Large samples come as bursts of fragments: the system's default receive buffer (208 KiB on a
    // stock kernel) drops half of a 0.18 MB topic at 100 Hz (docs/BENCHMARKS.md). The kernel caps
    // this at net.core.rmem_max.
    constexpr uint32_t kReceiveBuffer = 4 * 1024 * 1024;
    qos.transport().listen_socket_buffer_size = kReceiveBuffer;
    if (options.localhostOnly) {
        auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
        udp->interfaceWhiteList.emplace_back("127.0.0.1");
        udp->maxInitialPeersRange = 32; // participants on this host, found by unicast
        udp->receiveBufferSize = kReceiveBuffer;
        qos.transport().use_builtin_transports = false;
        qos.transport().user_transports.push_back(udp);
        rtps::Locator_t peer;
        peer.kind = LOCATOR_KIND_UDPv4;
        eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, 127, 0, 0, 1);
        qos.wire_protocol().builtin.initialPeersList.push_back(peer);
    }
    d->participant = DomainParticipantFactory::get_instance()->create_participant(
        options.domain, qos, d.get(), StatusMask::none());
    if (!d->participant) {
        d.reset();
        if (error)
            *error = tr("Fast DDS could not create a participant on domain %1 (no usable network interface "
                        "or ports?)")
                         .arg(options.domain);
        return false;
    }
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        d->ownPrefix = prefixBytes(d->participant->guid().guidPrefix);
        if (m_keepArrivals)
            d->arrivals = std::make_unique<EventBuffer<Ros2Arrival>>(m_keepArrivals);
    }
    d->subscriber = d->participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);

    // node names: every participant's ros_discovery_info, kept (transient local) by its writer
    d->infoReader = std::make_unique<Ros2RawReader>();
    Private* p = d.get();
    d->infoReader->onSample = [p](const Ros2RawSample& s, const SampleInfo& i) { p->onDiscoveryInfo(s, i); };
    d->infoReader->topic
        = d->topicFor("ros_discovery_info", "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");
    if (d->infoReader->topic && d->subscriber) {
        DataReaderQos rq = DATAREADER_QOS_DEFAULT;
        rq.reliability().kind = RELIABLE_RELIABILITY_QOS;
        rq.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
        rq.history().kind = KEEP_ALL_HISTORY_QOS;
        rq.resource_limits().max_samples = 1000;
        rq.endpoint().history_memory_policy = rtps::DYNAMIC_REUSABLE_MEMORY_MODE;
        d->infoReader->reader
            = d->subscriber->create_datareader(d->infoReader->topic, rq, d->infoReader.get());
    }
    if (!d->infoReader->reader)
        qCWarning(lcRos2) << "no reader for ros_discovery_info: topics show without node names";
    m_pending.invalidate(); // a new Private counts its changes from 1
    m_builtChanges = 0;
    m_polledChanges = 0;
    m_shownBadInfo = 0;
    m_timer.start();
    return true;
}

void Ros2Engine::stop()
{
    m_timer.stop();
    if (!d)
        return;
    if (d->participant) {
        // readers first, while their listeners still live; then everything else
        {
            std::lock_guard<std::mutex> lock(d->mutex);
            for (auto& [topic, m] : d->monitored)
                m.reader->onSample = nullptr;
        }
        d->participant->delete_contained_entities();
        DomainParticipantFactory::get_instance()->delete_participant(d->participant);
        d->participant = nullptr;
    }
    d.reset();
    m_graph = Ros2Graph();
}

quint64 Ros2Engine::badDiscoveryInfo() const
{
    if (!d)
        return 0;
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->badInfo;
}

void Ros2Engine::refresh()
{
    // Rebuilt once the changes pause for a poll (a node that starts, the whole burst of a large
    // graph's discovery), and at least once a graph interval while they go on.
    if (!d)
        return;
    const quint64 changes = d->changes.load();
    if (changes == m_builtChanges)
        return;
    const bool quiet = changes == m_polledChanges;
    m_polledChanges = changes;
    if (!m_pending.isValid())
        m_pending.start();
    if (!quiet && m_pending.elapsed() < m_graphInterval)
        return;
    m_pending.invalidate();
    m_builtChanges = changes;
    QList<Ros2Endpoint> endpoints;
    QList<Ros2ParticipantInfo> infos;
    QStringList services;
    int participants = 0;
    quint64 bad = 0;
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        bad = d->badInfo;
        endpoints.reserve(qsizetype(d->endpoints.size()));
        for (const auto& [gid, e] : d->endpoints)
            endpoints.append(e);
        for (const auto& [prefix, info] : d->infos)
            if (d->participants.count(prefix))
                infos.append(info);
        for (const auto& [gid, name] : d->services)
            services.append(name);
        participants = int(d->participants.size());
    }
    Ros2Graph graph = Ros2Graph::build(endpoints, infos, participants, services);
    if (graph == m_graph && bad == m_shownBadInfo)
        return;
    m_graph = std::move(graph);
    m_shownBadInfo = bad;
    // watched or monitored topics whose type the graph did not know before (or since start())
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it)
        if (!isSubscribed(it.key()) && m_graph.topic(it.key()))
            subscribe(it.key(), m_monitorUses.contains(it.key()), nullptr);
    for (auto it = m_monitorUses.cbegin(); it != m_monitorUses.cend(); ++it)
        if (!isSubscribed(it.key()) && m_graph.topic(it.key()))
            subscribe(it.key(), true, nullptr);
    emit graphChanged(m_graph);
}

void Ros2Engine::monitor(const QString& topic, bool waitForType)
{
    if (!d || !d->participant || (waitForType && !m_graph.topic(topic) && !m_monitorUses.contains(topic))) {
        ++m_monitorUses[topic]; // subscribed after start(), once the graph has the topic
        return;
    }
    if (const auto uses = m_monitorUses.find(topic); uses != m_monitorUses.end()) {
        ++uses.value(); // subscribed already for another user (the Links page, Discover's Mon)
        return;
    }
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (const auto it = d->monitored.find(topic); it != d->monitored.end()) {
            it->second.monitored = true; // subscribed already (watched)
            m_monitorUses.insert(topic, 1);
            return;
        }
    }
    QString why;
    if (subscribe(topic, true, &why))
        m_monitorUses.insert(topic, 1);
    else
        emit monitorFailed(topic, why);
}

bool Ros2Engine::subscribe(const QString& topic, bool monitored, QString* why)
{
    const Ros2Topic* t = m_graph.topic(topic);
    if (!t || t->types.isEmpty()) {
        if (why)
            *why = tr("%1 has no publisher or subscriber yet, so its type is not known").arg(topic);
        return false;
    }
    const QString type = t->type();
    QString ddsType = Ros2Names::ddsType(type);
    if (ddsType.isEmpty())
        ddsType = type;
    auto reader = std::make_unique<Ros2RawReader>();
    Private* p = d.get();
    reader->onSample = [p, topic](const Ros2RawSample& s, const SampleInfo&) { p->onSample(topic, s); };
    reader->topic = d->topicFor(Ros2Names::ddsTopic(topic).toStdString(), ddsType.toStdString());
    if (reader->topic && d->subscriber) {
        DataReaderQos rq = DATAREADER_QOS_DEFAULT;
        // best effort and volatile match every publisher
        rq.reliability().kind = BEST_EFFORT_RELIABILITY_QOS;
        rq.durability().kind = VOLATILE_DURABILITY_QOS;
        rq.history().kind = KEEP_LAST_HISTORY_QOS;
        rq.history().depth = 10;
        rq.endpoint().history_memory_policy = rtps::DYNAMIC_REUSABLE_MEMORY_MODE;
        {
            std::lock_guard<std::mutex> lock(d->mutex);
            auto& m = d->monitored[topic];
            m.stats.type = type;
            m.monitored = monitored;
            if (const auto w = m_watched.constFind(topic); w != m_watched.cend())
                m.watched = std::make_unique<NewestQueue<Ros2Sample>>(w->maxMessages, w->maxBytes);
        }
        reader->reader = d->subscriber->create_datareader(reader->topic, rq, reader.get());
    }
    if (!reader->reader) {
        d->deleteReader(*reader);
        std::lock_guard<std::mutex> lock(d->mutex);
        d->monitored.erase(topic);
        if (why)
            *why = tr("Fast DDS could not subscribe to %1 as %2").arg(topic, type);
        return false;
    }
    std::lock_guard<std::mutex> lock(d->mutex);
    d->monitored[topic].reader = std::move(reader);
    return true;
}

void Ros2Engine::unmonitor(const QString& topic)
{
    const auto uses = m_monitorUses.find(topic);
    if (uses == m_monitorUses.end() || --uses.value() > 0)
        return; // not monitored, or still wanted by another user
    m_monitorUses.erase(uses);
    if (d && d->participant)
        d->release(topic, true);
}

bool Ros2Engine::isMonitored(const QString& topic) const
{
    if (!d)
        return false;
    std::lock_guard<std::mutex> lock(d->mutex);
    const auto it = d->monitored.find(topic);
    return it != d->monitored.end() && it->second.monitored;
}

bool Ros2Engine::isSubscribed(const QString& topic) const
{
    if (!d)
        return false;
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->monitored.count(topic) > 0;
}

void Ros2Engine::watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    m_watched.insert(topic, {maxMessages, maxBytes});
    if (!d || !d->participant)
        return; // start() and the graph bring the subscription
    {
        std::lock_guard<std::mutex> lock(d->mutex);
        if (const auto it = d->monitored.find(topic); it != d->monitored.end()) {
            if (it->second.watched)
                it->second.watched->setLimits(maxMessages, maxBytes);
            else
                it->second.watched = std::make_unique<NewestQueue<Ros2Sample>>(maxMessages, maxBytes);
            return;
        }
    }
    subscribe(topic, false, nullptr); // else when the graph knows its type (refresh())
}

void Ros2Engine::unwatchMessages(const QString& topic)
{
    m_watched.remove(topic);
    if (d && d->participant)
        d->release(topic, false);
}

std::vector<Ros2Sample> Ros2Engine::takeMessages(const QString& topic)
{
    if (!d)
        return {};
    std::lock_guard<std::mutex> lock(d->mutex);
    const auto it = d->monitored.find(topic);
    return it != d->monitored.end() && it->second.watched ? it->second.watched->take()
                                                          : std::vector<Ros2Sample>();
}

quint64 Ros2Engine::droppedMessages(const QString& topic) const
{
    if (!d)
        return 0;
    std::lock_guard<std::mutex> lock(d->mutex);
    const auto it = d->monitored.find(topic);
    return it != d->monitored.end() && it->second.watched ? it->second.watched->dropped() : 0;
}

QHash<QString, Ros2MonitorStats> Ros2Engine::snapshot(qint64 nowNs) const
{
    QHash<QString, Ros2MonitorStats> out;
    if (!d)
        return out;
    std::lock_guard<std::mutex> lock(d->mutex);
    for (const auto& [topic, m] : d->monitored) {
        if (!m.monitored)
            continue; // only watched
        Ros2MonitorStats s = m.stats;
        std::tie(s.rateHz, s.bytesPerSecond) = m.rates.rates(nowNs);
        s.matchedPublishers = m.reader ? m.reader->matched.load() : 0;
        s.lost = m.reader ? m.reader->lost.load() : 0;
        out.insert(topic, s);
    }
    return out;
}

void Ros2Engine::keepArrivals(std::size_t maxArrivals)
{
    m_keepArrivals = maxArrivals;
    if (!d)
        return;
    std::lock_guard<std::mutex> lock(d->mutex);
    if (maxArrivals == 0)
        d->arrivals.reset();
    else
        d->arrivals = std::make_unique<EventBuffer<Ros2Arrival>>(maxArrivals);
}

std::vector<Ros2Arrival> Ros2Engine::takeArrivals()
{
    if (!d)
        return {};
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->arrivals ? d->arrivals->take() : std::vector<Ros2Arrival>();
}

quint64 Ros2Engine::droppedArrivals() const
{
    if (!d)
        return 0;
    std::lock_guard<std::mutex> lock(d->mutex);
    return d->arrivals ? d->arrivals->dropped() : 0;
}
