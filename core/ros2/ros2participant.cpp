// SPDX-License-Identifier: MIT
#include "ros2/ros2participant.h"

#include "base/eventbuffer.h"
#include "base/helperprogram.h"
#include "base/logging.h"
#include "ros2/ros2names.h"

#include <QCoreApplication>
#include <QProcess>
#include <QtGlobal>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

Ros2Options Ros2Options::fromEnvironment(QString* error)
{
    Ros2Options o;
    const QString domain = qEnvironmentVariable("ROS_DOMAIN_ID").trimmed();
    if (!domain.isEmpty()) {
        bool ok = false;
        const int d = domain.toInt(&ok);
        if (ok && d >= 0 && d <= kMaxDomain)
            o.domain = d;
        else if (error)
            *error = QCoreApplication::translate("Ros2Options",
                                                 "ROS_DOMAIN_ID is \"%1\", not a domain from 0 to %2")
                         .arg(domain.left(40))
                         .arg(kMaxDomain);
    }
    o.localhostOnly = qEnvironmentVariable("ROS_LOCALHOST_ONLY").trimmed() == QLatin1String("1");
    return o;
}

namespace {
/// A child that ran this long without failing starts the backoff anew.
constexpr int kStableMs = 60'000;
constexpr int kMaxBackoffMs = 30'000;
} // namespace

Ros2Participant::Ros2Participant(QObject* parent)
    : QObject(parent)
{
    m_watchdog.setInterval(1000);
    connect(&m_watchdog, &QTimer::timeout, this, &Ros2Participant::checkSilence);
    m_restartTimer.setSingleShot(true);
    connect(&m_restartTimer, &QTimer::timeout, this, &Ros2Participant::launch);
}

Ros2Participant::~Ros2Participant()
{
    endChild(true); // what is left of it is killed with this object
    stop();
}

QString Ros2Participant::program()
{
#ifdef BRIDGESCOPE_DDS_BUILD_PATH
    return findHelperProgram(u"bridgescope-dds"_s, "BRIDGESCOPE_DDS", QStringLiteral(BRIDGESCOPE_DDS_BUILD_PATH));
#else
    return findHelperProgram(u"bridgescope-dds"_s, "BRIDGESCOPE_DDS");
#endif
}

int Ros2Participant::backoffMs(int restartsInARow)
{
    int ms = 250;
    for (int i = 1; i < restartsInARow && ms < kMaxBackoffMs; ++i)
        ms *= 2;
    return std::min(ms, kMaxBackoffMs);
}

bool Ros2Participant::isRunning() const
{
    return m_wanted && m_error.isEmpty(); // also while a restart waits for its backoff
}

QString Ros2Participant::omittedText() const
{
    if (m_graph.omitted == 0)
        return {};
    return tr("%n endpoint(s) not listed (over a bound)", nullptr, int(std::min<quint64>(m_graph.omitted, INT_MAX)));
}

QString Ros2Participant::restartText() const
{
    QString text;
    if (m_restarts > 0)
        text = tr("ROS 2 discovery restarted %n time(s), %1 caused by peers (last: %2)", nullptr,
                  int(qMin<quint64>(m_restarts, INT_MAX)))
                   .arg(m_peerRestarts)
                   .arg(m_restartReason);
    if (m_loopsBroken > 0)
        text += u"; "_s + tr("a restart loop broken: the graph limited");
    const QString quarantine = quarantineText();
    if (!quarantine.isEmpty())
        text += (text.isEmpty() ? QString() : u"; "_s) + quarantine;
    return text;
}

QString Ros2Participant::quarantineText() const
{
    if (m_quarantine.isEmpty())
        return {};
    return tr("%n ROS 2 request(s) quarantined (last: %1)", nullptr, int(m_quarantine.size()))
        .arg(m_lastQuarantine);
}

void Ros2Participant::setGraphInterval(int ms)
{
    m_graphInterval = qBound(1, ms, 3'600'000);
    if (m_child)
        send(Kind::GraphInterval, Ros2Protocol::encodeNumber(quint64(m_graphInterval)));
}

bool Ros2Participant::start(const Ros2Options& options, QString* error)
{
    stop();
    if (options.domain < 0 || options.domain > Ros2Options::kMaxDomain) {
        if (error)
            *error = tr("domain %1 is out of range: ROS 2 domains are 0 to %2")
                         .arg(options.domain)
                         .arg(Ros2Options::kMaxDomain);
        return false;
    }
    if (program().isEmpty()) {
        if (error)
            *error = tr("cannot see ROS 2: the helper program bridgescope-dds is not installed");
        return false;
    }
    m_options = options;
    m_wanted = true;
    m_restarts = 0;
    m_restartsInARow = 0;
    m_unexplainedInARow = 0;
    m_peerRestarts = 0;
    m_limitedGraph = false;
    m_restartReason.clear();
    m_badInfo = 0;
    launch();
    if (!m_child) {
        if (error)
            *error = m_error;
        m_wanted = false;
        return false;
    }
    m_watchdog.start();
    return true;
}

void Ros2Participant::launch()
{
    if (!m_wanted || m_child)
        return;
    m_reader = {};
    m_failure.clear();
    m_error.clear();
    auto* child = new QProcess(this);
    // what the child logs goes where ours goes, without passing through this process's memory
    child->setProcessChannelMode(QProcess::ForwardedErrorChannel);
#if defined(__SANITIZE_ADDRESS__)
    // The child's address space is not limited under ASan (the shadow needs terabytes): ASan's own
    // RSS limit ends a runaway instead.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(u"ASAN_OPTIONS"_s, env.value(u"ASAN_OPTIONS"_s) + u":hard_rss_limit_mb=1536"_s);
    child->setProcessEnvironment(env);
#endif
    connect(child, &QProcess::readyReadStandardOutput, this, &Ros2Participant::onOutput);
    connect(child, &QProcess::finished, this, &Ros2Participant::onFinished);
    connect(child, &QProcess::errorOccurred, this, [this, child](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart && child == m_child)
            onFinished();
    });
    const QString helper = program();
    qCDebug(lcRos2).noquote() << "starting" << helper << "for domain" << m_options.domain;
    child->start(helper, {});
    if (!child->waitForStarted(10000)) {
        m_error = tr("cannot start %1: %2").arg(helper, child->errorString());
        child->disconnect(this);
        child->deleteLater();
        if (m_restarts > 0)
            emit graphChanged(m_graph); // a restart that failed: lastError() says why
        return;
    }
    m_child = child;
    m_up.start();
    m_lastFrame.start();
    Ros2Options options = m_options;
    options.limitedGraph = m_limitedGraph;
    send(Kind::Start, Ros2Protocol::encodeStart({options, m_graphInterval}));
    if (m_keepArrivals)
        send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(m_keepArrivals));
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it)
        send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(it.key())));
    for (auto it = m_monitorUses.cbegin(); it != m_monitorUses.cend(); ++it)
        send(Kind::Monitor, Ros2Protocol::encodeStrings({it.key()}));
    for (const quint64 n : std::as_const(m_receivedDropped))
        m_receivedDroppedBefore += n; // the new child counts from 0
    m_receivedDropped.clear();
    m_unanswered.clear();
    const QHash<QString, Ros2Protocol::EndpointRequest> advertised = m_advertised, subscribed = m_subscribed;
    for (const Ros2Protocol::EndpointRequest& e : advertised)
        requestEndpoint(true, e);
    for (const Ros2Protocol::EndpointRequest& e : subscribed)
        requestEndpoint(false, e);
    if (!m_node.name.isEmpty())
        send(Kind::SetNode, Ros2Protocol::encodeStrings({m_node.nameSpace, m_node.name}));
}

void Ros2Participant::send(Kind kind, const QByteArray& body)
{
    if (m_child && m_child->state() == QProcess::Running)
        m_child->write(Ros2Protocol::frame(kind, body));
}

void Ros2Participant::endChild(bool wait)
{
    if (!m_child)
        return;
    QProcess* child = m_child;
    m_child = nullptr;
    child->disconnect(this);
    // The child ends when its input does, and its participant says goodbye on the domain. Without
    // waiting for it (a domain change must not stall the window): it is killed if it takes long.
    child->closeWriteChannel();
    if (wait) {
        if (!child->waitForFinished(1000)) {
            child->kill();
            child->waitForFinished(1000);
        }
        delete child;
        return;
    }
    connect(child, &QProcess::finished, child, &QObject::deleteLater);
    QTimer::singleShot(3000, child, [child] { child->kill(); });
}

void Ros2Participant::stop()
{
    m_wanted = false;
    m_watchdog.stop();
    m_restartTimer.stop();
    endChild();
    m_graph = Ros2Graph();
    m_stats.clear();
    m_error.clear();
    for (auto it = m_watched.begin(); it != m_watched.end(); ++it) {
        for (Reader& r : it->readers)
            r.queue.reset();
        it->childDropped = 0;
    }
    if (m_arrivals)
        m_arrivals = std::make_unique<EventBuffer<SourceHead>>(m_keepArrivals);
    m_childDroppedArrivals = 0;
}

void Ros2Participant::onOutput()
{
    if (!m_child)
        return;
    // Read in slices, each cut into frames at once: what is held stays within one frame and a
    // slice, whatever the child writes.
    constexpr qint64 kSlice = 1024 * 1024;
    QProcess* child = m_child;
    while (child == m_child && child->bytesAvailable() > 0) {
        m_reader.append(child->read(kSlice));
        while (auto f = m_reader.next()) {
            m_lastFrame.restart();
            if (!handle(*f)) {
                childFailed(tr("sent a frame of kind %1 that does not read").arg(int(f->kind)));
                return;
            }
        }
        if (m_reader.failed()) {
            childFailed(tr("sent %1").arg(m_reader.error()));
            return;
        }
    }
}

bool Ros2Participant::handle(const Ros2Protocol::Frame& f)
{
    switch (f.kind) {
    case Kind::Heartbeat:
        return f.body.isEmpty();
    case Kind::Started:
        if (!f.body.isEmpty())
            return false;
        emit joined(true);
        return true;
    case Kind::StartFailed: {
        const auto why = Ros2Protocol::decodeStrings(f.body, 1);
        if (!why)
            return false;
        m_error = why->first().left(1000);
        qCWarning(lcRos2).noquote() << "ROS 2 participant not made:" << m_error;
        emit graphChanged(m_graph);
        emit joined(false);
        return true;
    }
    case Kind::Graph: {
        auto g = Ros2Protocol::decodeGraph(f.body);
        if (!g)
            return false;
        m_graph = std::move(g->graph);
        m_badInfo = g->badDiscoveryInfo;
        emit graphChanged(m_graph);
        return true;
    }
    case Kind::Stats: {
        auto stats = Ros2Protocol::decodeStats(f.body);
        if (!stats)
            return false;
        for (Ros2Protocol::TopicStats& t : *stats) {
            if (!m_monitorUses.contains(t.topic))
                continue; // unmonitored since the child sent it
            if (!t.withMessage)
                t.stats.lastMessage = m_stats.value(t.topic).lastMessage;
            m_stats.insert(t.topic, std::move(t.stats));
        }
        return true;
    }
    case Kind::Samples: {
        auto batch = Ros2Protocol::decodeSamples(f.body);
        if (!batch)
            return false;
        const auto it = m_watched.find(batch->topic);
        if (it == m_watched.end())
            return true; // unwatched since the child sent it
        it->childDropped = batch->dropped;
        for (Reader& r : it->readers) {
            if (!r.queue)
                r.queue = std::make_shared<NewestQueue<Ros2Sample>>(r.maxMessages, r.maxBytes);
            for (const Ros2Sample& s : batch->samples)
                r.queue->push(Ros2Sample(s), s.bytes.size()); // shared bytes (QByteArray), no copy
        }
        return true;
    }
    case Kind::Arrivals: {
        auto batch = Ros2Protocol::decodeArrivals(f.body);
        if (!batch)
            return false;
        m_childDroppedArrivals = batch->dropped;
        static_assert(Ros2Arrival::kHeadBytes <= SourceHead::kHeadBytes);
        if (m_arrivals)
            for (Ros2Arrival& a : batch->arrivals)
                if (m_monitorUses.contains(a.topic))
                    m_arrivals->push(SourceHead {SourceGraph::Ros2, std::move(a.topic), a.receivedNs, a.size,
                                                 std::move(a.head)});
        return true;
    }
    case Kind::Received: {
        auto batch = Ros2Protocol::decodeSamples(f.body);
        if (!batch)
            return false;
        if (!m_subscribed.contains(batch->topic))
            return true; // unsubscribed since the child sent it
        m_receivedDropped.insert(batch->topic, batch->dropped);
        for (const Ros2Sample& s : batch->samples)
            emit received(batch->topic, s);
        return true;
    }
    case Kind::EndpointDone: {
        const auto done = Ros2Protocol::decodeEndpointDone(f.body);
        if (!done)
            return false;
        m_unanswered.remove(endpointKey(done->advertise, {done->topic, done->type, {}}));
        const QHash<QString, Ros2Protocol::EndpointRequest>& made = done->advertise ? m_advertised : m_subscribed;
        const auto it = made.constFind(done->topic);
        // refused by the child (or Cyclone), and still wanted as it was asked
        if (!done->why.isEmpty() && it != made.cend() && it->type == done->type)
            refuseEndpoint(done->advertise, done->topic, done->why.left(1000));
        return true;
    }
    case Kind::MonitorFailed: {
        const auto said = Ros2Protocol::decodeStrings(f.body, 2);
        if (!said)
            return false;
        const QString topic = said->at(0);
        if (m_monitorUses.remove(topic) > 0) {
            m_stats.remove(topic);
            emit monitorFailed(topic, said->at(1).left(1000));
        }
        return true;
    }
    default:
        return false; // a request: the child has no business sending it
    }
}

void Ros2Participant::childFailed(const QString& why)
{
    if (!m_child)
        return;
    m_failure = why;
    m_child->kill(); // onFinished() follows
}

void Ros2Participant::checkSilence()
{
    if (m_child && m_lastFrame.isValid() && m_lastFrame.elapsed() > kSilenceMs)
        childFailed(tr("sent nothing for %1 s").arg(kSilenceMs / 1000));
}

void Ros2Participant::onFinished()
{
    QProcess* child = m_child;
    if (!child)
        return;
    onOutput(); // what it said before it ended
    if (m_child != child)
        return;
    QString why = m_failure;
    if (why.isEmpty()) {
        if (child->error() == QProcess::FailedToStart)
            why = tr("did not start: %1").arg(child->errorString());
        else if (child->exitStatus() == QProcess::CrashExit)
            why = tr("crashed (signal %1)").arg(child->exitCode()); // Qt gives the signal as the code
        else
            why = tr("ended with exit code %1").arg(child->exitCode());
    }
    m_child = nullptr;
    child->disconnect(this);
    child->deleteLater();
    if (!m_wanted)
        return;
    // A child that ran for a while failed anew; one that keeps failing waits longer each time.
    if (m_up.isValid() && m_up.elapsed() > kStableMs)
        m_restartsInARow = m_unexplainedInARow = 0;
    ++m_restartsInARow;
    ++m_restarts;
    m_restartReason = why;
    // What it was making when it ended is not asked of the next one (else a type that crashes
    // Cyclone crashes every child after it: a loop of restarts, broken here).
    const QHash<QString, Ros2Protocol::EndpointRequest> unanswered = std::exchange(m_unanswered, {});
    const bool ranInto = child->error() != QProcess::FailedToStart
        && (!m_failure.isEmpty() || child->exitStatus() == QProcess::CrashExit);
    if (!unanswered.isEmpty() || (ranInto && m_graph.participants > 0))
        ++m_peerRestarts;
    m_graph = Ros2Graph();
    m_stats.clear();
    for (auto it = unanswered.cbegin(); it != unanswered.cend(); ++it) {
        const bool advertise = it.key().startsWith(u'A');
        const QString reason = tr("the DDS process %1 while making it: quarantined, not asked again").arg(why);
        m_quarantine.insert(it.key(), reason);
        m_lastQuarantine = it->topic + u": "_s + reason;
        refuseEndpoint(advertise, it->topic, reason);
    }
    // A loop no quarantine explains (discovery, a peer's samples): the next children get a graph
    // of a tenth of the bounds, at once, instead of the same death after every backoff.
    m_unexplainedInARow = unanswered.isEmpty() ? m_unexplainedInARow + 1 : 0;
    QString loop;
    if (m_unexplainedInARow >= kLoopRestarts && !m_limitedGraph) {
        m_limitedGraph = true;
        ++m_loopsBroken;
        m_restartsInARow = 0;
        loop = tr("a restart loop: %1 restarts in a row, none explained by a request; the DDS process is "
                  "started again with the graph limited (%2 endpoints a participant, %3 in all)")
                   .arg(m_unexplainedInARow)
                   .arg(Ros2Options::kLimitedEndpointsPerParticipant)
                   .arg(Ros2Options::kLimitedEndpoints);
    }
    const int delay = backoffMs(std::max(m_restartsInARow, 1));
    qCWarning(lcRos2).noquote() << u"ROS 2 discovery restarted (%1): the DDS process %2; started again in %3 ms"_s
                                       .arg(m_restarts)
                                       .arg(why)
                                       .arg(delay);
    m_restartTimer.start(delay);
    emit restarted(why);
    if (!loop.isEmpty()) {
        qCWarning(lcRos2).noquote() << loop;
        emit restartLoopBroken(loop);
    }
    emit graphChanged(m_graph);
}

void Ros2Participant::monitor(const QString& topic)
{
    if (const auto uses = m_monitorUses.find(topic); uses != m_monitorUses.end()) {
        ++uses.value(); // subscribed already for another user (the Links page, Discover's Mon)
        return;
    }
    if (m_child) { // as the participant would say at once: a topic it does not know has no type
        const Ros2Topic* t = m_graph.topic(topic);
        if (!t || t->types.isEmpty()) {
            emit monitorFailed(topic, tr("%1 has no publisher or subscriber yet, so its type is not known").arg(topic));
            return;
        }
    }
    m_monitorUses.insert(topic, 1); // before start(): subscribed once the graph has the topic
    send(Kind::Monitor, Ros2Protocol::encodeStrings({topic}));
}

void Ros2Participant::unmonitor(const QString& topic)
{
    const auto uses = m_monitorUses.find(topic);
    if (uses == m_monitorUses.end() || --uses.value() > 0)
        return; // not monitored, or still wanted by another user
    m_monitorUses.erase(uses);
    m_stats.remove(topic);
    send(Kind::Unmonitor, Ros2Protocol::encodeStrings({topic}));
}

bool Ros2Participant::isMonitored(const QString& topic) const
{
    return m_child && m_monitorUses.contains(topic) && m_graph.topic(topic);
}

QHash<QString, Ros2MonitorStats> Ros2Participant::snapshot(qint64) const
{
    return m_stats;
}

QHash<QString, TopicFigures> Ros2Participant::figures(qint64 nowNs) const
{
    return topicFiguresOf(snapshot(nowNs));
}

Ros2Protocol::WatchRequest Ros2Participant::Watched::limits(const QString& topic) const
{
    Ros2Protocol::WatchRequest w {topic, 0, 0};
    for (const Reader& r : readers) {
        w.maxMessages = std::max<quint64>(w.maxMessages, r.maxMessages);
        w.maxBytes = std::max(w.maxBytes, r.maxBytes);
    }
    return w;
}

void Ros2Participant::watchMessages(const QString& topic, std::size_t maxMessages, qint64 maxBytes,
                                    const void* owner)
{
    Watched& w = m_watched[topic];
    Reader& r = w.readers[owner];
    r.maxMessages = maxMessages;
    r.maxBytes = maxBytes;
    if (r.queue)
        r.queue->setLimits(maxMessages, maxBytes);
    else if (m_child)
        r.queue = std::make_shared<NewestQueue<Ros2Sample>>(maxMessages, maxBytes);
    send(Kind::Watch, Ros2Protocol::encodeWatch(w.limits(topic)));
}

void Ros2Participant::unwatchMessages(const QString& topic, const void* owner)
{
    const auto it = m_watched.find(topic);
    if (it == m_watched.end() || it->readers.remove(owner) == 0)
        return;
    if (it->readers.isEmpty()) {
        m_watched.erase(it);
        send(Kind::Unwatch, Ros2Protocol::encodeStrings({topic}));
    } else {
        send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(topic)));
    }
}

const Ros2Participant::Reader* Ros2Participant::reader(const QString& topic, const void* owner) const
{
    const auto it = m_watched.constFind(topic);
    if (it == m_watched.cend())
        return nullptr;
    const auto r = it->readers.constFind(owner);
    return r != it->readers.cend() && r->queue ? &*r : nullptr;
}

void Ros2Participant::watch(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    watchMessages(topic, maxMessages, maxBytes);
}

void Ros2Participant::unwatch(const QString& topic)
{
    unwatchMessages(topic);
}

std::vector<SourceArrival> Ros2Participant::takeWatched(const QString& topic)
{
    const Ros2Topic* t = m_graph.topic(topic);
    const QString type = t ? t->type() : QString();
    std::vector<SourceArrival> out;
    for (Ros2Sample& s : takeMessages(topic))
        out.push_back({SourceGraph::Ros2, topic, type, s.receivedNs, std::move(s.bytes)});
    return out;
}

std::vector<Ros2Sample> Ros2Participant::takeMessages(const QString& topic, const void* owner)
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->take() : std::vector<Ros2Sample>();
}

quint64 Ros2Participant::droppedMessages(const QString& topic, const void* owner) const
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->dropped() + m_watched.value(topic).childDropped : 0;
}

void Ros2Participant::keepArrivals(std::size_t maxArrivals)
{
    m_keepArrivals = maxArrivals;
    if (maxArrivals == 0)
        m_arrivals.reset();
    else
        m_arrivals = std::make_unique<EventBuffer<SourceHead>>(maxArrivals);
    m_childDroppedArrivals = 0;
    send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(maxArrivals));
}

std::vector<SourceHead> Ros2Participant::takeArrivals()
{
    return m_arrivals ? m_arrivals->take() : std::vector<SourceHead>();
}

quint64 Ros2Participant::droppedArrivals() const
{
    return m_arrivals ? m_arrivals->dropped() + m_childDroppedArrivals : 0;
}

void Ros2Participant::setNode(const QString& nameSpace, const QString& name)
{
    m_node = {nameSpace, name};
    send(Kind::SetNode, Ros2Protocol::encodeStrings({nameSpace, name}));
}

namespace {
Ros2Protocol::EndpointRequest endpointRequest(const QString& topic, const QString& type, Ros2Qos qos)
{
    if (qos.depth < 1)
        qos.depth = 10; // rclcpp's default
    qos.depth = std::min(qos.depth, Ros2Protocol::kMaxDepth);
    if (qos.durability != Ros2Qos::Volatile)
        qos.durability = Ros2Qos::TransientLocal; // what a ROS 2 node can ask for of the two others
    return {topic, type, qos};
}
} // namespace

QString Ros2Participant::endpointKey(bool advertise, const Ros2Protocol::EndpointRequest& e)
{
    return (advertise ? u"A "_s : u"S "_s) + e.topic + u' ' + e.type;
}

bool Ros2Participant::requestEndpoint(bool advertise, const Ros2Protocol::EndpointRequest& e)
{
    QString why;
    const QString key = endpointKey(advertise, e);
    const bool valid = Ros2Names::isValidTopic(e.topic, &why) && Ros2Names::isValidType(e.type, &why);
    if (const auto q = m_quarantine.constFind(key); valid && q != m_quarantine.cend())
        why = *q;
    if (!why.isEmpty()) {
        // what was made of the topic before stays made
        emit endpointRefused(e.topic, why);
        return false;
    }
    (advertise ? m_advertised : m_subscribed).insert(e.topic, e);
    if (m_child && m_child->state() == QProcess::Running)
        m_unanswered.insert(key, e);
    send(advertise ? Kind::Advertise : Kind::Subscribe, Ros2Protocol::encodeEndpoint(e));
    return true;
}

void Ros2Participant::refuseEndpoint(bool advertise, const QString& topic, const QString& why)
{
    (advertise ? m_advertised : m_subscribed).remove(topic);
    emit endpointRefused(topic, why); // said by the user (the bridge: its mapping), as often as it sees fit
}

bool Ros2Participant::advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return requestEndpoint(true, endpointRequest(topic, type, qos));
}

void Ros2Participant::unadvertise(const QString& topic)
{
    if (const auto it = m_advertised.constFind(topic); it != m_advertised.cend())
        m_unanswered.remove(endpointKey(true, *it));
    if (m_advertised.remove(topic) > 0)
        send(Kind::Unadvertise, Ros2Protocol::encodeStrings({topic}));
}

bool Ros2Participant::publish(const QString& topic, const QByteArray& cdr)
{
    const bool sendable = m_child && m_child->state() == QProcess::Running && m_advertised.contains(topic)
        && cdr.size() >= 4 && cdr.size() <= qsizetype(Ros2Protocol::kMaxFrameBytes) - 1024
        && (m_child->bytesToWrite() == 0 || m_child->bytesToWrite() + cdr.size() <= m_publishBound);
    if (!sendable) {
        ++m_publishDropped;
        return false;
    }
    send(Kind::Publish, Ros2Protocol::encodePublish({topic, cdr}));
    return true;
}

bool Ros2Participant::subscribe(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return requestEndpoint(false, endpointRequest(topic, type, qos));
}

void Ros2Participant::unsubscribe(const QString& topic)
{
    if (const auto it = m_subscribed.constFind(topic); it != m_subscribed.cend())
        m_unanswered.remove(endpointKey(false, *it));
    if (m_subscribed.remove(topic) > 0)
        send(Kind::Unsubscribe, Ros2Protocol::encodeStrings({topic}));
    m_receivedDropped.remove(topic);
}

quint64 Ros2Participant::droppedReceived() const
{
    quint64 n = m_receivedDroppedBefore;
    for (const quint64 d : m_receivedDropped)
        n += d;
    return n;
}
