// SPDX-License-Identifier: MIT
#include "ros2/ros2link.h"

#include "base/logging.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

Ros2Link::Ros2Link(DdsChildPipe& pipe, QObject* parent)
    : QObject(parent)
    , m_pipe(pipe)
    , m_endpoints(pipe, this)
{ }

void Ros2Link::replay(const Ros2Options& options)
{
    m_pipe.send(Kind::Start, Ros2Protocol::encodeStart({options, m_graphInterval}));
    if (m_keepArrivals)
        m_pipe.send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(m_keepArrivals));
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it)
        m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(it.key())));
    for (auto it = m_monitorUses.cbegin(); it != m_monitorUses.cend(); ++it)
        m_pipe.send(Kind::Monitor, Ros2Protocol::encodeStrings({it.key()}));
    m_endpoints.replay();
}

bool Ros2Link::causedByPeers(bool ranInto) const
{
    return makingRequests() || (ranInto && m_graph.participants > 0);
}

void Ros2Link::childLost(const QString& why)
{
    m_graph = Ros2Graph();
    m_stats.clear();
    m_endpoints.quarantineUnanswered(why);
}

void Ros2Link::childStopped()
{
    m_graph = Ros2Graph();
    m_stats.clear();
    for (auto it = m_watched.begin(); it != m_watched.end(); ++it) {
        for (Reader& r : it->readers)
            r.queue.reset();
        it->childDropped = 0;
    }
    if (m_arrivals)
        m_arrivals = std::make_unique<EventBuffer<SourceHead>>(m_keepArrivals);
    m_childDroppedArrivals = 0;
}

void Ros2Link::setGraphInterval(int ms)
{
    m_graphInterval = qBound(1, ms, 3'600'000);
    if (m_pipe.hasChild())
        m_pipe.send(Kind::GraphInterval, Ros2Protocol::encodeNumber(quint64(m_graphInterval)));
}

bool Ros2Link::handle(const Ros2Protocol::Frame& f)
{
    switch (f.kind) {
    case Kind::Heartbeat:
        return f.body.isEmpty();
    case Kind::Started:
        if (!f.body.isEmpty())
            return false;
        emit started();
        return true;
    case Kind::StartFailed: {
        const auto why = Ros2Protocol::decodeStrings(f.body, 1);
        if (!why)
            return false;
        qCWarning(lcRos2).noquote() << "ROS 2 participant not made:" << why->first().left(1000);
        emit startFailed(why->first().left(1000));
        return true;
    }
    case Kind::Graph:
        return onGraph(f.body);
    case Kind::Stats:
        return onStats(f.body);
    case Kind::Samples:
        return onSamples(f.body);
    case Kind::Arrivals:
        return onArrivals(f.body);
    case Kind::Received:
        return m_endpoints.onReceived(f.body);
    case Kind::EndpointDone:
        return m_endpoints.onEndpointDone(f.body);
    case Kind::MonitorFailed:
        return onMonitorFailed(f.body);
    default:
        return false; // a request: the child has no business sending it
    }
}

bool Ros2Link::onGraph(const QByteArray& body)
{
    auto g = Ros2Protocol::decodeGraph(body);
    if (!g)
        return false;
    m_graph = std::move(g->graph);
    m_badInfo = g->badDiscoveryInfo;
    emit graphChanged(m_graph);
    return true;
}

bool Ros2Link::onStats(const QByteArray& body)
{
    auto stats = Ros2Protocol::decodeStats(body);
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

bool Ros2Link::onSamples(const QByteArray& body)
{
    auto batch = Ros2Protocol::decodeSamples(body);
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

bool Ros2Link::onArrivals(const QByteArray& body)
{
    auto batch = Ros2Protocol::decodeArrivals(body);
    if (!batch)
        return false;
    m_childDroppedArrivals = batch->dropped;
    if (m_arrivals)
        for (SourceHead& a : batch->arrivals)
            if (m_monitorUses.contains(a.topic))
                m_arrivals->push(std::move(a));
    return true;
}

bool Ros2Link::onMonitorFailed(const QByteArray& body)
{
    const auto said = Ros2Protocol::decodeStrings(body, 2);
    if (!said)
        return false;
    const QString topic = said->at(0);
    if (m_monitorUses.remove(topic) > 0) {
        m_stats.remove(topic);
        emit monitorFailed(topic, said->at(1).left(1000));
    }
    return true;
}

void Ros2Link::monitor(const QString& topic)
{
    if (const auto uses = m_monitorUses.find(topic); uses != m_monitorUses.end()) {
        ++uses.value(); // subscribed already for another user (the Links page, Discover's Mon)
        return;
    }
    if (m_pipe.hasChild()) { // as the participant would say at once: a topic it does not know has no type
        const Ros2Topic* t = m_graph.topic(topic);
        if (!t || t->types.isEmpty()) {
            // the text is Ros2Participant's: it keeps its translation context
            emit monitorFailed(
                topic,
                QCoreApplication::translate("Ros2Participant",
                                            "%1 has no publisher or subscriber yet, so its type is not known")
                    .arg(topic));
            return;
        }
    }
    m_monitorUses.insert(topic, 1); // before start(): subscribed once the graph has the topic
    m_pipe.send(Kind::Monitor, Ros2Protocol::encodeStrings({topic}));
}

void Ros2Link::unmonitor(const QString& topic)
{
    const auto uses = m_monitorUses.find(topic);
    if (uses == m_monitorUses.end() || --uses.value() > 0)
        return; // not monitored, or still wanted by another user
    m_monitorUses.erase(uses);
    m_stats.remove(topic);
    m_pipe.send(Kind::Unmonitor, Ros2Protocol::encodeStrings({topic}));
}

bool Ros2Link::isMonitored(const QString& topic) const
{
    return m_pipe.hasChild() && m_monitorUses.contains(topic) && m_graph.topic(topic);
}

Ros2Protocol::WatchRequest Ros2Link::Watched::limits(const QString& topic) const
{
    Ros2Protocol::WatchRequest w {topic, 0, 0};
    for (const Reader& r : readers) {
        w.maxMessages = std::max<quint64>(w.maxMessages, r.maxMessages);
        w.maxBytes = std::max(w.maxBytes, r.maxBytes);
    }
    return w;
}

void Ros2Link::openQueue(const QString& topic, std::size_t maxMessages, qint64 maxBytes,
                             const void* owner)
{
    Watched& w = m_watched[topic];
    Reader& r = w.readers[owner];
    r.maxMessages = maxMessages;
    r.maxBytes = maxBytes;
    if (r.queue)
        r.queue->setLimits(maxMessages, maxBytes);
    else if (m_pipe.hasChild())
        r.queue = std::make_shared<NewestQueue<Ros2Sample>>(maxMessages, maxBytes);
    m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(w.limits(topic)));
}

void Ros2Link::closeQueue(const QString& topic, const void* owner)
{
    const auto it = m_watched.find(topic);
    if (it == m_watched.end() || it->readers.remove(owner) == 0)
        return;
    if (it->readers.isEmpty()) {
        m_watched.erase(it);
        m_pipe.send(Kind::Unwatch, Ros2Protocol::encodeStrings({topic}));
    } else {
        m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(topic)));
    }
}

const Ros2Link::Reader* Ros2Link::reader(const QString& topic, const void* owner) const
{
    const auto it = m_watched.constFind(topic);
    if (it == m_watched.cend())
        return nullptr;
    const auto r = it->readers.constFind(owner);
    return r != it->readers.cend() && r->queue ? &*r : nullptr;
}

std::vector<Ros2Sample> Ros2Link::takeQueued(const QString& topic, const void* owner)
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->take() : std::vector<Ros2Sample>();
}

quint64 Ros2Link::droppedQueued(const QString& topic, const void* owner) const
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->dropped() + m_watched.value(topic).childDropped : 0;
}

void Ros2Link::keepArrivals(std::size_t maxArrivals)
{
    m_keepArrivals = maxArrivals;
    if (maxArrivals == 0)
        m_arrivals.reset();
    else
        m_arrivals = std::make_unique<EventBuffer<SourceHead>>(maxArrivals);
    m_childDroppedArrivals = 0;
    m_pipe.send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(maxArrivals));
}

std::vector<SourceHead> Ros2Link::takeArrivals()
{
    return m_arrivals ? m_arrivals->take() : std::vector<SourceHead>();
}

quint64 Ros2Link::droppedArrivals() const
{
    return m_arrivals ? m_arrivals->dropped() + m_childDroppedArrivals : 0;
}
