// SPDX-License-Identifier: MIT
#include "ros2stampsource.h"

#include "ros2/ros2participant.h"
#include "wire/sourcemessage.h"

#include <QCoreApplication>

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
    for (auto it = m_stamps.cbegin(); it != m_stamps.cend(); ++it) {
        for (const Ros2Sample& s : m_participant->takeMessages(it.key(), this)) {
            ++m_received;
            QString why;
            const std::optional<StampCodec::Decoded> d = SourceMessage::decodeStamp(SourceGraph::Ros2, s.bytes, &why);
            if (d)
                stamps.push_back(StampEvent {it.value(), d->sampleNs, d->timeNs, s.receivedNs});
            else
                fail(it.key(), why);
        }
    }
    for (const QString& topic : std::as_const(m_latencies)) {
        for (const Ros2Sample& s : m_participant->takeMessages(topic, this)) {
            ++m_received;
            if (const std::optional<qint64> ns = SourceMessage::decodeLatency(SourceGraph::Ros2, s.bytes))
                latencies.push_back(LatencyValue {topic, *ns, s.receivedNs});
            else
                fail(topic, QCoreApplication::translate("RosStampSource", "a latency that is no finite number of seconds"));
        }
    }
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
