// SPDX-License-Identifier: MIT
#include "ros2/ros2link.h"

#include "base/logging.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

Ros2Link::Ros2Link(DdsChildPipe& pipe, QObject* parent)
    : QObject(parent)
    , m_pipe(pipe)
    , m_watches(pipe)
    , m_endpoints(pipe, this)
    , m_heads([this](std::size_t largestBound) { keepHeads(largestBound); })
{ }

void Ros2Link::replay(const Ros2Options& options)
{
    m_pipe.send(Kind::Start, Ros2Protocol::encodeStart({options, m_graphInterval}));
    if (m_keepArrivals)
        m_pipe.send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(m_keepArrivals));
    m_watches.replay();
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
    m_watches.childStopped();
    m_childDroppedHeads = 0;
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
        return m_watches.onSamples(f.body);
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

bool Ros2Link::onArrivals(const QByteArray& body)
{
    auto batch = Ros2Protocol::decodeArrivals(body);
    if (!batch)
        return false;
    // The child counts its drops from the last KeepArrivals or its start.
    const quint64 before = batch->dropped >= m_childDroppedHeads ? m_childDroppedHeads : 0;
    m_heads.addDroppedUpstream(batch->dropped - before);
    m_childDroppedHeads = batch->dropped;
    if (m_heads.active())
        for (SourceHead& a : batch->arrivals)
            if (m_monitorUses.contains(a.topic))
                m_heads.deliver(std::move(a));
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

std::unique_ptr<HeadTap> Ros2Link::openHeadTap(std::size_t maxHeads)
{
    return m_heads.open(maxHeads);
}

void Ros2Link::keepHeads(std::size_t maxHeads)
{
    m_keepArrivals = maxHeads;
    m_childDroppedHeads = 0;
    m_pipe.send(Kind::KeepArrivals, Ros2Protocol::encodeNumber(maxHeads));
}
