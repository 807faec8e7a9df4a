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

Ros2StampSource::~Ros2StampSource() = default; // the taps close with it

void Ros2StampSource::unwatch(const QString& topic)
{
    const auto it = m_taps.find(topic);
    if (it == m_taps.end())
        return;
    m_droppedBefore += it->second->dropped();
    m_taps.erase(it);
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
            m_taps[t] = m_participant->openTap(t, kQueued, kQueuedBytes);
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
        const auto tap = m_taps.find(topic);
        if (tap == m_taps.end())
            return;
        for (SourceArrival& s : tap->second->take()) {
            ++m_received;
            s.topic = name;
            s.type = type;
            const StampReading r = SourceMessage::readStamp(s, latency);
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
    for (const auto& [topic, tap] : m_taps)
        n += tap->dropped();
    return n;
}
