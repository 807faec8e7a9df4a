// SPDX-License-Identifier: MIT
#include "graphstatus.h"

#include "ros/rosgraphpoller.h"
#include "ros2/ros2participant.h"

using namespace Qt::StringLiterals;

GraphStatus::GraphStatus(const RosGraphPoller* ros1, const Ros2Participant* ros2, QObject* parent)
    : QObject(parent)
    , m_ros1(ros1)
    , m_ros2(ros2)
{
    connect(ros1, &RosGraphPoller::reachabilityChanged, this, &GraphStatus::ros1Changed);
    connect(ros1, &RosGraphPoller::graphChanged, this, &GraphStatus::ros1Changed);
    connect(ros2, &Ros2Participant::graphChanged, this, &GraphStatus::ros2Changed);
}

GraphStatus::Line GraphStatus::ros1Line() const
{
    if (m_ros1->polls() == 0)
        return {Level::Idle, tr("asking the master…"), {}};
    if (m_ros1->isReachable())
        return {Level::Ok,
                tr("reachable: %1 topics, %2 nodes").arg(m_ros1->graph().topics.size()).arg(m_ros1->graph().nodes.size()),
                {}};
    return {Level::Failed, tr("unreachable: %1 (retrying every second)").arg(m_ros1->lastError()), {}};
}

bool GraphStatus::ros1Reachable() const
{
    return m_ros1->isReachable();
}

GraphStatus::Line GraphStatus::ros2Line() const
{
    if (!m_ros2->lastError().isEmpty())
        return {Level::Failed, m_ros2->lastError(), {}};
    // A restart of the DDS process (a hostile datagram, a runaway) is said, never hidden.
    const QString restarts = m_ros2->restartText();
    const Ros2Graph& g = m_ros2->graph();
    const int domain = m_ros2->options().domain;
    QString text;
    if (g.participants == 0) {
        text = tr("listening on domain %1: no participant yet").arg(domain);
    } else {
        text = tr("domain %1: participants %2, topics %3, nodes %4")
                   .arg(domain)
                   .arg(g.participants)
                   .arg(g.topics.size())
                   .arg(g.nodes.size());
        if (const quint64 bad = m_ros2->badDiscoveryInfo())
            text += u", "_s + tr("unreadable node announcements %1").arg(bad);
        if (g.omitted)
            text += u", "_s + m_ros2->graph().omittedText();
    }
    if (!restarts.isEmpty())
        text += u" · "_s + restarts;
    const Level quiet = g.participants == 0 ? Level::Idle : Level::Ok;
    return {restarts.isEmpty() ? quiet : Level::Troubled, text, m_ros2->restartCount().lastReason()};
}

bool GraphStatus::ros2Running() const
{
    return m_ros2->isRunning();
}

Ros2Options GraphStatus::ros2Options() const
{
    return m_ros2->options();
}

const Ros2Graph& GraphStatus::ros2Graph() const
{
    return m_ros2->graph();
}

QString GraphStatus::ros2EndpointsText(const QString& topic) const
{
    const Ros2Topic* t = m_ros2->graph().topic(topic);
    if (!t)
        return {};
    auto endpoints = [](const QList<Ros2Endpoint>& list) {
        QStringList parts;
        for (const Ros2Endpoint& e : list)
            parts << u"%1 (%2)"_s.arg(e.node.isEmpty() ? tr("no node") : e.node, e.qos.text());
        return parts.isEmpty() ? tr("none") : parts.join(u", "_s);
    };
    return tr("%1; publishers: %2; subscribers: %3")
        .arg(t->types.join(u" / "_s), endpoints(t->publishers), endpoints(t->subscribers));
}
