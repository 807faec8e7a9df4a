// SPDX-License-Identifier: MIT
#include "ros2/ros2endpointlink.h"

#include "ros2/ros2names.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;
using Ros2Protocol::Kind;

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

Ros2EndpointLink::Ros2EndpointLink(DdsChildPipe& pipe, QObject* parent)
    : QObject(parent)
    , m_pipe(pipe)
{ }

void Ros2EndpointLink::replay()
{
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
        m_pipe.send(Kind::SetNode, Ros2Protocol::encodeStrings({m_node.nameSpace, m_node.name}));
}

void Ros2EndpointLink::quarantineUnanswered(const QString& why)
{
    // What it was making when it ended is not asked of the next one (else a type that crashes
    // Cyclone crashes every child after it: a loop of restarts, broken here). The texts are
    // Ros2Participant's: they keep its translation context.
    const QHash<QString, Ros2Protocol::EndpointRequest> unanswered = std::exchange(m_unanswered, {});
    for (auto it = unanswered.cbegin(); it != unanswered.cend(); ++it) {
        const bool advertise = it.key().startsWith(u'A');
        const QString reason
            = QCoreApplication::translate("Ros2Participant",
                                          "the DDS process %1 while making it: quarantined, not asked again")
                  .arg(why);
        m_quarantine.insert(it.key(), reason);
        m_lastQuarantine = it->topic + u": "_s + reason;
        refuseEndpoint(advertise, it->topic, reason);
    }
}

bool Ros2EndpointLink::onReceived(const QByteArray& body)
{
    auto batch = Ros2Protocol::decodeSamples(body);
    if (!batch)
        return false;
    if (!m_subscribed.contains(batch->topic))
        return true; // unsubscribed since the child sent it
    m_receivedDropped.insert(batch->topic, batch->dropped);
    for (const Ros2Sample& s : batch->samples)
        emit received(batch->topic, s);
    return true;
}

bool Ros2EndpointLink::onEndpointDone(const QByteArray& body)
{
    const auto done = Ros2Protocol::decodeEndpointDone(body);
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

void Ros2EndpointLink::setNode(const QString& nameSpace, const QString& name)
{
    m_node = {nameSpace, name};
    m_pipe.send(Kind::SetNode, Ros2Protocol::encodeStrings({nameSpace, name}));
}

bool Ros2EndpointLink::advertise(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return requestEndpoint(true, endpointRequest(topic, type, qos));
}

bool Ros2EndpointLink::subscribe(const QString& topic, const QString& type, const Ros2Qos& qos)
{
    return requestEndpoint(false, endpointRequest(topic, type, qos));
}

QString Ros2EndpointLink::endpointKey(bool advertise, const Ros2Protocol::EndpointRequest& e)
{
    return (advertise ? u"A "_s : u"S "_s) + e.topic + u' ' + e.type;
}

bool Ros2EndpointLink::requestEndpoint(bool advertise, const Ros2Protocol::EndpointRequest& e)
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
    if (m_pipe.childRunning())
        m_unanswered.insert(key, e);
    m_pipe.send(advertise ? Kind::Advertise : Kind::Subscribe, Ros2Protocol::encodeEndpoint(e));
    return true;
}

void Ros2EndpointLink::refuseEndpoint(bool advertise, const QString& topic, const QString& why)
{
    (advertise ? m_advertised : m_subscribed).remove(topic);
    emit endpointRefused(topic, why); // said by the user (the bridge: its mapping), as often as it sees fit
}

void Ros2EndpointLink::unadvertise(const QString& topic)
{
    if (const auto it = m_advertised.constFind(topic); it != m_advertised.cend())
        m_unanswered.remove(endpointKey(true, *it));
    if (m_advertised.remove(topic) > 0)
        m_pipe.send(Kind::Unadvertise, Ros2Protocol::encodeStrings({topic}));
}

bool Ros2EndpointLink::publish(const QString& topic, const QByteArray& cdr)
{
    const qint64 pending = m_pipe.childRunning() ? m_pipe.bytesToWrite() : 0;
    const bool sendable = m_pipe.childRunning() && m_advertised.contains(topic) && cdr.size() >= 4
        && cdr.size() <= qsizetype(Ros2Protocol::kMaxFrameBytes) - 1024
        && (pending == 0 || pending + cdr.size() <= m_publishBound);
    if (!sendable) {
        ++m_publishDropped;
        return false;
    }
    m_pipe.send(Kind::Publish, Ros2Protocol::encodePublish({topic, cdr}));
    return true;
}

void Ros2EndpointLink::unsubscribe(const QString& topic)
{
    if (const auto it = m_subscribed.constFind(topic); it != m_subscribed.cend())
        m_unanswered.remove(endpointKey(false, *it));
    if (m_subscribed.remove(topic) > 0)
        m_pipe.send(Kind::Unsubscribe, Ros2Protocol::encodeStrings({topic}));
    m_receivedDropped.remove(topic);
}

quint64 Ros2EndpointLink::droppedReceived() const
{
    quint64 n = m_receivedDroppedBefore;
    for (const quint64 d : m_receivedDropped)
        n += d;
    return n;
}
