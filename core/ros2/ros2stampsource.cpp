// SPDX-License-Identifier: MIT
#include "ros2stampsource.h"

#include "ros2/ros2participant.h"
#include "wire/sourcemessage.h"

using namespace Qt::StringLiterals;

Ros2StampSource::Ros2StampSource(Ros2Participant* participant, QObject* parent)
    : QObject(parent)
    , m_participant(participant)
{
}

Ros2StampSource::~Ros2StampSource()
{
    for (auto it = m_stamps.cbegin(); it != m_stamps.cend(); ++it)
        unwatch(it.key());
    for (const QString& t : std::as_const(m_latencies))
        unwatch(t);
}

void Ros2StampSource::unwatch(const QString& topic)
{
    if (!m_participant)
        return;
    m_droppedBefore += m_participant->droppedMessages(topic, this);
    m_participant->unwatchMessages(topic, this);
}

void Ros2StampSource::setTopics(const QHash<QString, QString>& stampTopics, const QSet<QString>& latencyTopics)
{
    if (!m_participant || (stampTopics == m_stamps && latencyTopics == m_latencies))
        return;
    const auto wanted = [&](const QString& t) { return stampTopics.contains(t) || latencyTopics.contains(t); };
    const auto had = [this](const QString& t) { return m_stamps.contains(t) || m_latencies.contains(t); };
    QSet<QString> before(m_latencies);
    for (auto it = m_stamps.cbegin(); it != m_stamps.cend(); ++it)
        before.insert(it.key());
    for (const QString& t : std::as_const(before))
        if (!wanted(t))
            unwatch(t);
    QSet<QString> after(latencyTopics);
    for (auto it = stampTopics.cbegin(); it != stampTopics.cend(); ++it)
        after.insert(it.key());
    for (const QString& t : std::as_const(after))
        if (!had(t))
            m_participant->watchMessages(t, kQueued, kQueuedBytes, this);
    m_stamps = stampTopics;
    m_latencies = latencyTopics;
}

void Ros2StampSource::fail(const QString& topic, const QString& why)
{
    ++m_malformed;
    ++m_malformedByTopic[topic];
    m_lastError = topic + u": "_s + why;
}

void Ros2StampSource::takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies)
{
    if (!m_participant)
        return;
    // Stamps carry the name the pipeline knows them by; latencies their topic's.
    const auto read = [&](const QString& topic, const QString& name, bool latency) {
        const QString type = SourceMessage::stampType(SourceGraph::Ros2);
        for (Ros2Sample& s : m_participant->takeMessages(topic, this)) {
            ++m_received;
            const StampReading r
                = SourceMessage::readStamp({SourceGraph::Ros2, name, type, s.receivedNs, std::move(s.bytes)}, latency);
            if (r.stamp)
                stamps.push_back(*r.stamp);
            else if (r.latency)
                latencies.push_back(*r.latency);
            else
                fail(topic, r.error);
        }
    };
    for (auto it = m_stamps.cbegin(); it != m_stamps.cend(); ++it)
        read(it.key(), it.value(), false);
    for (const QString& topic : std::as_const(m_latencies))
        read(topic, topic, true);
}

quint64 Ros2StampSource::dropped() const
{
    quint64 n = m_droppedBefore;
    if (m_participant) {
        for (auto it = m_stamps.cbegin(); it != m_stamps.cend(); ++it)
            n += m_participant->droppedMessages(it.key(), this);
        for (const QString& t : m_latencies)
            n += m_participant->droppedMessages(t, this);
    }
    return n;
}
