// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicgraph.h"

#include <QObject>
#include <QString>

class RosGraphPoller;
class Ros2Participant;
struct Ros2Graph;
struct Ros2Options;

/// What the window says of each ROS graph, whichever transport holds it: a level and a line for
/// a status bar ("reachable: 19 topics, 12 nodes", "domain 7: participants 3, …", the restarts of
/// the DDS child never hidden), and what the views read of a graph without knowing its transport.
/// The pages take this instead of the ROS 1 poller and the ROS 2 participant, so no widget
/// includes a transport layer.
class GraphStatus : public QObject
{
    Q_OBJECT
public:
    enum class Level { Idle, Ok, Troubled, Failed }; ///< grey, green, orange, red
    struct Line
    {
        Level level = Level::Idle;
        QString text;
        QString toolTip;
    };

    GraphStatus(const RosGraphPoller* ros1, const Ros2Participant* ros2, QObject* parent = nullptr);

    /// The ROS 1 master: asking, reachable with its counts, or unreachable with the reason.
    Line ros1Line() const;
    bool ros1Reachable() const;
    /// The ROS 2 domain joined: why not, no participant yet, or its counts; restarts of the DDS
    /// child, unreadable node announcements and endpoints past a bound are said in it.
    Line ros2Line() const;
    bool ros2Running() const;
    /// The domain joined (or last asked for).
    Ros2Options ros2Options() const;
    /// The ROS 2 graph with its QoS and gids, for the checks that need them (mapping health).
    const Ros2Graph& ros2Graph() const;
    /// A ROS 2 topic's types and each endpoint's node and QoS ("std_msgs/msg/String; publishers:
    /// /talker (reliable, volatile, keep last 10); subscribers: none"), or empty when the graph
    /// does not have it.
    QString ros2EndpointsText(const QString& topic) const;

signals:
    void ros1Changed();
    void ros2Changed();

private:
    const RosGraphPoller* m_ros1;
    const Ros2Participant* m_ros2;
};
