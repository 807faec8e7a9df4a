// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <QStringList>

class LiveSession;
class Ros2Participant;

/// Says on stderr, as it happens, every restart of the participant's DDS process and a loop of
/// them broken (`record`, `watch` and `discover` alike: a restart is news, not only a count at the end).
void sayRos2Restarts(Ros2Participant* participant);

/// What `record`, `watch` and `demo`-like commands say when their sources stay silent: within
/// kGraceMs of the start, on stderr, that the broker or the ROS master cannot be reached (and why)
/// or that nothing has arrived yet, and later that a source answers again. The session keeps
/// trying meanwhile (the connection and the poller retry by themselves); the command decides at
/// the end what an empty result means.
class SourceCheck
{
    Q_DECLARE_TR_FUNCTIONS(SourceCheck)
public:
    static constexpr qint64 kGraceMs = 5000;

    /// `arrived` counts what the command keeps (stamps, events); `what` names it for the message.
    /// `needsMaster` false: the master's state is not the command's business (an MQTT-only pipeline).
    SourceCheck(const LiveSession& live, bool needsMaster, std::function<qint64()> arrived, QString what);

    /// The topics the command waits on, named when nothing arrives (the pipeline's, the links').
    void setTopics(QStringList topics) { m_topics = std::move(topics); }
    /// Once a second or so, with the milliseconds since the start; prints what changed.
    void check(qint64 elapsedMs);

    bool brokerEverReached() const { return m_brokerEver; }
    bool masterEverReached() const { return m_masterEver; }
    /// Whether another participant was ever seen on the ROS 2 domain joined (false without one).
    bool ros2EverHeard() const { return m_ros2Ever; }
    /// Empty when a graph the command listens to was heard (the broker or, with `ros1`, the
    /// master reached; on ROS 2 another participant seen); else what was waited for in vain:
    /// "neither the broker nor the master was reached", on ROS 2 "the broker was not reached and
    /// nobody was heard on ROS 2 domain 7".
    QString nothingHeard(bool ros1, bool ros2) const;

private:
    const LiveSession& m_live;
    bool m_needsMaster;
    std::function<qint64()> m_arrived;
    QString m_what;
    QStringList m_topics;
    QDateTime m_since = QDateTime::currentDateTime();
    bool m_brokerSaid = false; ///< the broker was said to be unreachable (and is still)
    bool m_masterSaid = false;
    bool m_silenceSaid = false;
    bool m_brokerEver = false;
    bool m_masterEver = false;
    bool m_ros2Ever = false;
};
