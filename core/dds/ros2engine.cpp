// SPDX-License-Identifier: MIT
#include "dds/ros2engine.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "dds/ros2endpoints.h"
#include "dds/ros2rawreader.h"
#include "ros2/ros2names.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <map>
#include <QHostAddress>
#include <QNetworkInterface>
#include <QtGlobal>
#include <set>

using namespace Qt::StringLiterals;

namespace {

constexpr std::size_t kMaxEndpoints = 200'000;
/// What one participant may have in the graph: a peer announcing more (a raw RTPS socket can
/// announce any number) has the rest counted, not listed (issue 41).
constexpr int kMaxEndpointsPerParticipant = 10'000;
/// ROS 2 names as rcl limits them: a topic name at most 255 characters after the `rt/` prefix
/// (RMW_TOPIC_MAX_NAME_LENGTH), a DDS type name as long (longer ones are not made by rosidl).
constexpr std::size_t kMaxTopicChars = 255;
constexpr std::size_t kMaxTypeChars = 255;
/// Discovery samples taken from each built-in topic a poll: the rest wait for the next one.
constexpr int kMaxDiscoveryPerPoll = 4096;

QByteArray gidBytes(const dds_guid_t& guid)
{
    return QByteArray(reinterpret_cast<const char*>(guid.v), 16);
}

QByteArray prefixBytes(const dds_guid_t& guid)
{
    return QByteArray(reinterpret_cast<const char*>(guid.v), 12);
}

/// What an endpoint announced; where it said nothing, the DDS defaults (writers reliable,
/// readers best effort, both volatile).
Ros2Qos qosOf(const dds_qos_t* qos, bool publisher)
{
    Ros2Qos q;
    dds_reliability_kind_t r = publisher ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT;
    dds_duration_t blocking = 0;
    dds_durability_kind_t d = DDS_DURABILITY_VOLATILE;
    if (qos) {
        dds_qget_reliability(qos, &r, &blocking);
        dds_qget_durability(qos, &d);
    }
    q.reliability = r == DDS_RELIABILITY_RELIABLE ? Ros2Qos::Reliable : Ros2Qos::BestEffort;
    switch (d) {
    case DDS_DURABILITY_VOLATILE:
        q.durability = Ros2Qos::Volatile;
        break;
    case DDS_DURABILITY_TRANSIENT_LOCAL:
        q.durability = Ros2Qos::TransientLocal;
        break;
    case DDS_DURABILITY_TRANSIENT:
        q.durability = Ros2Qos::Transient;
        break;
    case DDS_DURABILITY_PERSISTENT:
        q.durability = Ros2Qos::Persistent;
        break;
    }
    return q;
}

/// Every IPv4 interface that is up and can multicast, and the loopback without multicast (for
/// this host's nodes that talk on 127.0.0.1 only), as Cyclone's <Interfaces>; empty when there is
/// none (Cyclone then picks one itself).
QString allInterfaces(bool withLoopback = true)
{
    QString out;
    for (const QNetworkInterface& i : QNetworkInterface::allInterfaces()) {
        const auto flags = i.flags();
        const auto entries = i.addressEntries();
        const bool ipv4 = std::any_of(entries.begin(), entries.end(), [](const QNetworkAddressEntry& a) {
            return a.ip().protocol() == QAbstractSocket::IPv4Protocol;
        });
        if (!ipv4 || !(flags & QNetworkInterface::IsUp) || !(flags & QNetworkInterface::IsRunning))
            continue;
        if (flags & QNetworkInterface::IsLoopBack) {
            if (withLoopback)
                out += u"<NetworkInterface name=\"%1\" multicast=\"false\"/>"_s.arg(i.name().toHtmlEscaped());
        } else if (flags & QNetworkInterface::CanMulticast)
            out += u"<NetworkInterface name=\"%1\"/>"_s.arg(i.name().toHtmlEscaped());
    }
    return out.isEmpty() ? out : u"<Interfaces>"_s + out + u"</Interfaces>"_s;
}

/// The domain's configuration. On this host only (as rmw_cyclonedds_cpp and tests/ros2peer do
/// it): unicast on 127.0.0.1 to the discovery ports of participant indices 0..30. Else every IPv4
/// interface, multicast discovery, and a participant index too (0..119, the domain's port range),
/// so that this host's localhost-only nodes, which send to those ports on 127.0.0.1, find us. Large
/// samples come as bursts of fragments: the system's default receive buffer (208 KiB on a stock
/// kernel) drops half of a 0.18 MB topic at 100 Hz (docs/BENCHMARKS.md), so 4 MiB are asked for
/// (the kernel caps it at net.core.rmem_max).
std::string domainConfig(bool localhostOnly, const QStringList& staticPeers)
{
    const QString general = localhostOnly
        ? u"<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
          u"<AllowMulticast>false</AllowMulticast>"_s
        : allInterfaces(staticPeers.isEmpty());
    QString peers;
    if (!localhostOnly && !staticPeers.isEmpty()) {
        // Static peers (ROS_STATIC_PEERS): the hosts named (this one's own address among them for its
        // own participants), asked for by unicast at every participant index, over the interfaces
        // that reach them (Cyclone sends a peer's packets through loopback too, where they fail);
        // addresses only (checked as they came in).
        for (const QString& p : staticPeers)
            if (!QHostAddress(p).isNull())
                peers += u"<Peer Address=\"%1\"/>"_s.arg(QHostAddress(p).toString().toHtmlEscaped());
        peers = u"<Peers>"_s + peers + u"</Peers>"_s;
    }
    const QString discovery = localhostOnly ? u"<ParticipantIndex>auto</ParticipantIndex>"
                                              u"<MaxAutoParticipantIndex>30</MaxAutoParticipantIndex>"
                                              u"<Peers><Peer Address=\"127.0.0.1\"/></Peers>"_s
                                            : u"<ParticipantIndex>auto</ParticipantIndex>"
                                              u"<MaxAutoParticipantIndex>119</MaxAutoParticipantIndex>"_s
            + peers;
    const QString xml = u"<CycloneDDS><Domain Id=\"any\"><General>"_s + general + u"</General><Discovery>"_s
        + discovery + u"</Discovery><Internal><SocketReceiveBufferSize min=\"default\" max=\"4MB\"/></Internal>"
                      u"<Tracing><Verbosity>none</Verbosity></Tracing></Domain></CycloneDDS>"_s;
    return xml.toStdString();
}

/// Cyclone's log lines (issue 41): a malformed datagram is an ERROR line of Cyclone's, two for an
/// empty one, and what the child prints the parent forwards to its stderr; so any host of the
/// domain could write the lab's logs. Only fatal lines pass (the child is ending); the others are
/// counted and said at most once a minute, as a count.
std::atomic<quint64> g_cycloneLines {0};
std::atomic<qint64> g_cycloneSaidMs {0};

void cycloneLog(void*, const dds_log_data_t* data)
{
    if (data->priority & DDS_LC_FATAL) {
        std::fwrite(data->message, 1, data->size, stderr);
        std::fputc('\n', stderr);
        return;
    }
    const quint64 lines = ++g_cycloneLines;
    const qint64 nowMs = wallClockNs() / 1'000'000;
    qint64 said = g_cycloneSaidMs.load();
    if (nowMs - said < 60'000 || !g_cycloneSaidMs.compare_exchange_strong(said, nowMs))
        return;
    qCInfo(lcRos2).noquote() << u"Cyclone DDS: %1 log line(s) of its own not shown so far (malformed datagrams "
                                u"from peers, among others)"_s.arg(lines);
}

} // namespace

struct Ros2Engine::Private
{
    // Discovery: the owner thread's only (taken from Cyclone's built-in topics by poll()).
    std::map<QByteArray, Ros2Endpoint> endpoints; ///< ROS topics' writers and readers, by gid
    std::map<QByteArray, QString> services; ///< service endpoints: gid to service name
    std::map<QByteArray, Ros2ParticipantInfo> infos; ///< by the announcing participant's prefix
    std::set<QByteArray> participants; ///< remote participants' prefixes
    std::map<dds_instance_handle_t, QByteArray> handles; ///< built-in topics' instances: their gid or prefix
    std::set<QByteArray> badInfoFrom;
    quint64 badInfo = 0;
    /// Endpoints refused by a bound (their participant's prefix), until they or it are gone; past
    /// kMaxEndpoints only counted (refusedBeyond).
    std::map<dds_instance_handle_t, QByteArray> refused;
    quint64 refusedBeyond = 0;
    std::map<QByteArray, int> perParticipant; ///< endpoints kept, by participant prefix
    /// The bounds: kMaxEndpoints and kMaxEndpointsPerParticipant, or Ros2Options::limitedGraph's.
    std::size_t maxEndpoints = kMaxEndpoints;
    int maxPerParticipant = kMaxEndpointsPerParticipant;
    QByteArray ownPrefix;
    quint64 changes = 1; ///< bumped at every change of the tables

    dds_entity_t domain = 0;
    dds_entity_t participant = 0;
    dds_entity_t participantReader = 0; ///< DCPSParticipant
    dds_entity_t publicationReader = 0; ///< DCPSPublication
    dds_entity_t subscriptionReader = 0; ///< DCPSSubscription
    std::unique_ptr<Ros2RawReader> infoReader;
    std::unique_ptr<Ros2Endpoints> own; ///< our writers, readers and node

    ~Private()
    {
        own.reset(); // its readers first: their callbacks write to it
        if (participant > 0)
            dds_delete(participant); // its readers, topics and their listeners with it
        if (domain > 0)
            dds_delete(domain);
    }

    void forgetParticipant(const QByteArray& prefix)
    {
        participants.erase(prefix);
        infos.erase(prefix);
        for (auto it = endpoints.begin(); it != endpoints.end();)
            it = it->first.startsWith(prefix) ? endpoints.erase(it) : std::next(it);
        for (auto it = services.begin(); it != services.end();)
            it = it->first.startsWith(prefix) ? services.erase(it) : std::next(it);
        for (auto it = refused.begin(); it != refused.end();)
            it = it->second == prefix ? refused.erase(it) : std::next(it);
        perParticipant.erase(prefix);
    }

    quint64 refusedCount() const { return quint64(refused.size()) + refusedBeyond; }

    void refuse(dds_instance_handle_t handle, const QByteArray& prefix)
    {
        if (refused.size() < maxEndpoints)
            refused[handle] = prefix;
        else
            ++refusedBeyond;
        ++changes; // the count is shown with the graph
    }

    /// An endpoint (or service endpoint) of `gid` gone from the tables.
    void forget(const QByteArray& gid)
    {
        if (endpoints.erase(gid) + services.erase(gid) == 0)
            return;
        const auto n = perParticipant.find(gid.left(12));
        if (n != perParticipant.end() && --n->second <= 0)
            perParticipant.erase(n);
    }

    /// What the built-in topics and ros_discovery_info brought since the last poll.
    void poll()
    {
        pollBuiltin(participantReader, [this](const void* s, bool alive, dds_instance_handle_t h) {
            onParticipant(static_cast<const dds_builtintopic_participant_t*>(s), alive, h);
        });
        pollBuiltin(publicationReader, [this](const void* s, bool alive, dds_instance_handle_t h) {
            onEndpoint(static_cast<const dds_builtintopic_endpoint_t*>(s), true, alive, h);
        });
        pollBuiltin(subscriptionReader, [this](const void* s, bool alive, dds_instance_handle_t h) {
            onEndpoint(static_cast<const dds_builtintopic_endpoint_t*>(s), false, alive, h);
        });
        if (infoReader && infoReader->reader > 0)
            infoReader->take(kMaxDiscoveryPerPoll);
    }

    /// Takes (loaned) samples of a built-in topic: `sample` null when the instance is gone.
    template<typename F>
    void pollBuiltin(dds_entity_t reader, F&& on)
    {
        constexpr int kBatch = 64;
        for (int taken = 0; reader > 0 && taken < kMaxDiscoveryPerPoll;) {
            void* samples[kBatch] = {};
            dds_sample_info_t infos[kBatch];
            const dds_return_t n = dds_take(reader, samples, infos, kBatch, kBatch);
            if (n <= 0)
                return;
            for (dds_return_t i = 0; i < n; ++i) {
                const bool alive = infos[i].instance_state == DDS_IST_ALIVE;
                on(alive && infos[i].valid_data ? samples[i] : nullptr, alive, infos[i].instance_handle);
            }
            dds_return_loan(reader, samples, n);
            taken += n;
        }
    }

    void onParticipant(const dds_builtintopic_participant_t* p, bool alive, dds_instance_handle_t handle)
    {
        if (alive && !p)
            return; // nothing new said
        const auto known = handles.find(handle);
        const QByteArray prefix = p ? prefixBytes(p->key) : known != handles.end() ? known->second : QByteArray();
        if (p && prefix != ownPrefix && alive)
            handles[handle] = prefix;
        if (prefix.isEmpty() || prefix == ownPrefix)
            return;
        if (alive) {
            participants.insert(prefix);
        } else {
            forgetParticipant(prefix);
            handles.erase(handle);
        }
        ++changes;
    }

    void onEndpoint(const dds_builtintopic_endpoint_t* e, bool publisher, bool alive, dds_instance_handle_t handle)
    {
        if (!alive) {
            if (refused.erase(handle) > 0)
                ++changes;
            const auto h = handles.find(handle);
            if (h == handles.end())
                return;
            forget(h->second);
            handles.erase(h);
            ++changes;
            return;
        }
        if (!e || prefixBytes(e->participant_key) == ownPrefix || prefixBytes(e->key) == ownPrefix)
            return;
        endpoint(gidBytes(e->key), handle, e->topic_name, e->type_name, qosOf(e->qos, publisher), publisher);
    }

    void endpoint(const QByteArray& gid, dds_instance_handle_t handle, const char* ddsTopic, const char* ddsType,
                  const Ros2Qos& qos, bool publisher)
    {
        // Lengths first, read at most one past the bound: a peer's 60,000-character names never
        // become strings here.
        const std::size_t topicChars = ddsTopic ? strnlen(ddsTopic, kMaxTopicChars + 4) : 0;
        const std::size_t typeChars = ddsType ? strnlen(ddsType, kMaxTypeChars + 1) : 0;
        const bool tooLong = topicChars > kMaxTopicChars + 3 || typeChars > kMaxTypeChars;
        QString name;
        const auto kind = Ros2Names::classifyDdsTopic(
            tooLong ? QString::fromUtf8(ddsTopic, 4) : QString::fromUtf8(ddsTopic ? ddsTopic : ""), &name);
        if (kind == Ros2Names::TopicKind::Other)
            return; // not in the graph anyway
        const QByteArray prefix = gid.left(12);
        const bool known = endpoints.count(gid) || services.count(gid);
        if (tooLong && known) { // it was announced with names within the bounds before
            forget(gid);
            handles.erase(handle);
        }
        if (tooLong
            || (!known
                && (endpoints.size() + services.size() >= maxEndpoints
                    || perParticipant[prefix] >= maxPerParticipant))) {
            if (!refused.count(handle))
                refuse(handle, prefix);
            return;
        }
        if (!known)
            ++perParticipant[prefix];
        ++changes;
        handles[handle] = gid;
        if (kind != Ros2Names::TopicKind::Topic) {
            services[gid] = name;
            return;
        }
        Ros2Endpoint& e = endpoints[gid];
        e.gid = gid;
        e.topic = name;
        e.type = Ros2Names::rosType(QString::fromUtf8(ddsType ? ddsType : ""));
        e.publisher = publisher;
        e.qos = qos;
    }

    /// On the owner thread (taken by poll()).
    void onDiscoveryInfo(const Ros2RawSample& sample, const dds_sample_info_t& info)
    {
        const QByteArray prefix = writerPrefix(info.publication_handle);
        if (prefix.isEmpty() || prefix == ownPrefix)
            return;
        const QByteArray bytes(reinterpret_cast<const char*>(sample.data), qsizetype(sample.size));
        Result<Ros2ParticipantInfo> parsed = Ros2DiscoveryInfo::parse(bytes);
        ++changes; // when not read: the graph is the same, but what is shown with it (the count) is not
        if (!parsed) {
            ++badInfo;
            // the first 16 participants are named in the log, once each; the set stays that small
            if (badInfoFrom.size() < 16 && badInfoFrom.insert(prefix).second)
                qCWarning(lcRos2).noquote()
                    << "ros_discovery_info from participant" << prefix.toHex() << "not read:" << parsed.error().toString();
            return;
        }
        // a participant speaks for itself only: its announcement is kept under its own prefix
        infos[prefix] = std::move(*parsed);
    }

    /// The participant of the writer of a ros_discovery_info sample, by what discovery said of it.
    QByteArray writerPrefix(dds_instance_handle_t writer) const
    {
        dds_builtintopic_endpoint_t* w = dds_get_matched_publication_data(infoReader->reader, writer);
        if (!w)
            return {};
        const QByteArray prefix = prefixBytes(w->participant_key);
        dds_builtintopic_free_endpoint(w);
        return prefix;
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
    return d && d->participant > 0;
}

/// Our participant, as rmw makes one: named, with the enclave in its user data so that ROS 2 tools
/// show what we are.
static dds_entity_t createParticipant(dds_domainid_t domain)
{
    dds_qos_t* qos = dds_create_qos();
    dds_qset_entity_name(qos, "bridgescope");
    const char enclave[] = "enclave=/;";
    dds_qset_userdata(qos, enclave, sizeof enclave - 1);
    const dds_entity_t participant = dds_create_participant(domain, qos, nullptr);
    dds_delete_qos(qos);
    return participant;
}

Status Ros2Engine::start(const Ros2Options& options)
{
    stop();
    if (options.domain < 0 || options.domain > Ros2Options::kMaxDomain)
        return LocatedError {tr("domain %1 is out of range: ROS 2 domains are 0 to %2")
                                 .arg(options.domain)
                                 .arg(Ros2Options::kMaxDomain)};
    // Fatal lines only, through our sink (cycloneLog): every malformed datagram would be a line on
    // stderr, and the parent forwards what we print (a flood of hostile datagrams would flood its
    // terminal). The trace goes nowhere.
    dds_set_log_mask(DDS_LC_FATAL);
    dds_set_log_sink(&cycloneLog, nullptr);
    dds_set_trace_sink([](void*, const dds_log_data_t*) {}, nullptr);
    m_options = options;
    d = std::make_shared<Private>();
    if (options.limitedGraph) { // after a loop of restarts (Ros2Participant)
        d->maxEndpoints = std::size_t(Ros2Options::kLimitedEndpoints);
        d->maxPerParticipant = Ros2Options::kLimitedEndpointsPerParticipant;
    }
    d->domain = dds_create_domain(dds_domainid_t(options.domain),
                                  domainConfig(options.localhostOnly, options.staticPeers).c_str());
    if (d->domain > 0)
        d->participant = createParticipant(dds_domainid_t(options.domain));
    if (d->participant <= 0) {
        const QString why = QString::fromUtf8(dds_strretcode(d->domain > 0 ? d->participant : d->domain));
        d.reset();
        return LocatedError {tr("Cyclone DDS could not create a participant on domain %1 (%2: no usable network "
                                "interface or ports?)")
                                 .arg(options.domain)
                                 .arg(why)};
    }
    dds_guid_t own;
    if (dds_get_guid(d->participant, &own) == DDS_RETCODE_OK)
        d->ownPrefix = prefixBytes(own);
    d->participantReader = dds_create_reader(d->participant, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr);
    d->publicationReader = dds_create_reader(d->participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
    d->subscriptionReader = dds_create_reader(d->participant, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr);
    m_readers.keepArrivals(m_keepArrivals);
    openDiscoveryInfo();
    d->own = std::make_unique<Ros2Endpoints>(d->participant, [this] {
        QMetaObject::invokeMethod(this, [this] { emit samplesReceived(); }, Qt::QueuedConnection);
    });
    m_pending.invalidate(); // a new Private counts its changes from 1
    m_builtChanges = 0;
    m_polledChanges = 0;
    m_shownBadInfo = 0;
    m_timer.start();
    return {};
}

/// Node names: every participant's ros_discovery_info, kept (transient local) by its writer and
/// taken by the poll, on this thread.
void Ros2Engine::openDiscoveryInfo()
{
    d->infoReader = std::make_unique<Ros2RawReader>();
    Private* p = d.get();
    d->infoReader->onSample = [p](const Ros2RawSample& s, const dds_sample_info_t& i) { p->onDiscoveryInfo(s, i); };
    d->infoReader->topic = Ros2RawType::createTopic(d->participant, "ros_discovery_info",
                                                    "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
    dds_qset_resource_limits(qos, 1000, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    if (d->infoReader->topic <= 0 || !d->infoReader->open(d->participant, qos, false))
        qCWarning(lcRos2) << "no reader for ros_discovery_info: topics show without node names";
    dds_delete_qos(qos);
}

void Ros2Engine::stop()
{
    m_timer.stop();
    // The participant with everything in it, then the domain (Private's destructor): deleting a
    // reader waits for its listener in flight, which still finds the tables it writes to.
    d.reset();
    m_readers.clear();
    m_graph = Ros2Graph();
}

quint64 Ros2Engine::badDiscoveryInfo() const
{
    if (!d)
        return 0;
    return d->badInfo;
}

void Ros2Engine::refresh()
{
    // Rebuilt once the changes pause for a poll (a node that starts, the whole burst of a large
    // graph's discovery), and at least once a graph interval while they go on.
    if (!d)
        return;
    d->poll();
    const quint64 changes = d->changes + d->own->changes(); // both only grow
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
        endpoints += d->own->ownEndpoints(); // discovery does not show us our own
        infos += d->own->ownInfo();
    }
    Ros2Graph graph = Ros2Graph::build(endpoints, infos, participants, services);
    graph.omitted += d->refusedCount();
    if (graph == m_graph && bad == m_shownBadInfo)
        return;
    m_graph = std::move(graph);
    m_shownBadInfo = bad;
    // watched or monitored topics whose type the graph did not know before (or since start())
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it)
        if (!m_readers.isSubscribed(it.key()) && m_graph.topic(it.key()))
            static_cast<void>(subscribe(it.key(), m_monitorUses.contains(it.key()))); // failing: asked again at the next refresh
    for (auto it = m_monitorUses.cbegin(); it != m_monitorUses.cend(); ++it)
        if (!m_readers.isSubscribed(it.key()) && m_graph.topic(it.key()))
            static_cast<void>(subscribe(it.key(), true)); // failing: asked again at the next refresh
    emit graphChanged(m_graph);
}

void Ros2Engine::monitor(const QString& topic, bool waitForType)
{
    if (!d || d->participant <= 0 || (waitForType && !m_graph.topic(topic) && !m_monitorUses.contains(topic))) {
        ++m_monitorUses[topic]; // subscribed after start(), once the graph has the topic
        return;
    }
    if (const auto uses = m_monitorUses.find(topic); uses != m_monitorUses.end()) {
        ++uses.value(); // subscribed already for another user (the Links page, Discover's Mon)
        return;
    }
    if (m_readers.markMonitored(topic)) { // subscribed already (watched)
        m_monitorUses.insert(topic, 1);
        return;
    }
    if (const Status subscribed = subscribe(topic, true))
        m_monitorUses.insert(topic, 1);
    else
        emit monitorFailed(topic, subscribed.error().message);
}

Status Ros2Engine::subscribe(const QString& topic, bool monitored)
{
    const Ros2Topic* t = m_graph.topic(topic);
    if (!t || t->types.isEmpty())
        return LocatedError {tr("%1 has no publisher or subscriber yet, so its type is not known").arg(topic)};
    const QString type = t->type();
    QString ddsType = Ros2Names::ddsType(type);
    if (ddsType.isEmpty())
        ddsType = type;
    auto reader = std::make_unique<Ros2RawReader>();
    Ros2TopicReaders* readers = &m_readers;
    reader->onSample = [readers, topic](const Ros2RawSample& s, const dds_sample_info_t& info) {
        // Cyclone gives each sample its writer's source timestamp (DDS_TIME_INVALID: none), but no
        // sequence number (dds_sample_info_t has none in 0.10): loss is its sample-lost status.
        readers->onSample(topic, s.data, s.size,
                          info.source_timestamp == DDS_TIME_INVALID ? 0 : info.source_timestamp);
    };
    reader->topic = Ros2RawType::createTopic(d->participant, Ros2Names::ddsTopic(topic).toStdString(),
                                             ddsType.toStdString());
    bool opened = false;
    if (reader->topic > 0) {
        m_readers.add(topic, type, monitored);
        if (const auto w = m_watched.constFind(topic); w != m_watched.cend())
            m_readers.watch(topic, w->maxMessages, w->maxBytes);
        // best effort and volatile match every publisher
        dds_qos_t* qos = dds_create_qos();
        dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
        dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
        dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 10);
        const dds_data_representation_id_t any[] = {DDS_DATA_REPRESENTATION_XCDR1, DDS_DATA_REPRESENTATION_XCDR2};
        dds_qset_data_representation(qos, 2, any);
        opened = reader->open(d->participant, qos, true);
        dds_delete_qos(qos);
    }
    if (!opened) {
        reader->close();
        m_readers.remove(topic);
        return LocatedError {tr("Cyclone DDS could not subscribe to %1 as %2").arg(topic, type)};
    }
    m_readers.setReader(topic, std::move(reader));
    return {};
}

void Ros2Engine::unmonitor(const QString& topic)
{
    const auto uses = m_monitorUses.find(topic);
    if (uses == m_monitorUses.end() || --uses.value() > 0)
        return; // not monitored, or still wanted by another user
    m_monitorUses.erase(uses);
    if (d && d->participant > 0)
        m_readers.release(topic, true);
}

void Ros2Engine::watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    m_watched.insert(topic, {maxMessages, maxBytes});
    if (!d || d->participant <= 0)
        return; // start() and the graph bring the subscription
    if (!m_readers.watch(topic, maxMessages, maxBytes))
        static_cast<void>(subscribe(topic, false)); // else when the graph knows its type (refresh())
}

void Ros2Engine::unwatchMessages(const QString& topic)
{
    m_watched.remove(topic);
    if (d && d->participant > 0)
        m_readers.release(topic, false);
}

void Ros2Engine::keepArrivals(std::size_t maxArrivals)
{
    m_keepArrivals = maxArrivals;
    if (d)
        m_readers.keepArrivals(maxArrivals);
}

void Ros2Engine::setNode(const QString& nameSpace, const QString& name)
{
    if (d)
        d->own->setNode(nameSpace, name);
}

Status Ros2Engine::advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    if (!d)
        return LocatedError {tr("not on a domain")};
    return d->own->advertise(topic, type, qos);
}

void Ros2Engine::unadvertise(const QString& topic)
{
    if (d)
        d->own->unadvertise(topic);
}

bool Ros2Engine::publish(const QString& topic, const QByteArray& cdr)
{
    return d && d->own->publish(topic, cdr);
}

Status Ros2Engine::subscribeSamples(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    if (!d)
        return LocatedError {tr("not on a domain")};
    return d->own->subscribe(topic, type, qos);
}

void Ros2Engine::unsubscribeSamples(const QString& topic)
{
    if (d)
        d->own->unsubscribe(topic);
}

std::vector<Ros2Engine::Received> Ros2Engine::takeReceived(qint64 maxBytes)
{
    return d ? d->own->takeReceived(maxBytes) : std::vector<Received>();
}
