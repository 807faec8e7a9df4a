// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicgraph.h"
#include "wire/sourcemessage.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringList>
#include <QtGlobal>

/// Figures of one monitored ROS 2 topic.
struct Ros2MonitorStats : TopicFigures
{
    int matchedPublishers = 0;
};

/// ROS 2 monitor figures as every view takes them (no md5 or definition in ROS 2).
inline QHash<QString, TopicStats> topicStatsOf(const QHash<QString, Ros2MonitorStats>& ros2)
{
    QHash<QString, TopicStats> stats;
    stats.reserve(ros2.size());
    for (auto it = ros2.cbegin(); it != ros2.cend(); ++it)
        static_cast<TopicFigures&>(stats[it.key()]) = *it;
    return stats;
}

/// One whole sample of a watched topic (for plots of its fields).
struct Ros2Sample
{
    qint64 receivedNs = 0; ///< wall clock
    QByteArray bytes; ///< CDR with its encapsulation header
};

/// How the participant reaches the graph.
struct Ros2Options
{
    int domain = 0; ///< 0..232, as ROS_DOMAIN_ID
    /// UDP on 127.0.0.1 only, with unicast discovery of the participants on this host (as
    /// ROS_LOCALHOST_ONLY=1 does); otherwise every interface, multicast discovery and shared memory.
    bool localhostOnly = false;
    /// Hosts whose participants are asked for by unicast (ROS_STATIC_PEERS, IP literals), beside
    /// this host's own: how a lab's sides on two hosts find each other where multicast does not
    /// pass. Without localhostOnly only; at most kMaxStaticPeers.
    QStringList staticPeers {};
    static constexpr int kMaxStaticPeers = 8;
    /// The child's graph within a tenth of its bounds: set by Ros2Participant after a loop of
    /// restarts no quarantine explains (issue 41), never by a user.
    bool limitedGraph = false;
    static constexpr int kLimitedEndpointsPerParticipant = 1'000;
    static constexpr int kLimitedEndpoints = 20'000;

    /// ROS_DOMAIN_ID, ROS_LOCALHOST_ONLY and ROS_STATIC_PEERS (addresses separated by ';') from the
    /// environment; `error` says why a set value was not taken (then the default stays).
    static Ros2Options fromEnvironment(QString* error = nullptr);
    static constexpr int kMaxDomain = 232;
};
