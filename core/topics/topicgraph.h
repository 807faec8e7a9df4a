// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicfigures.h"

#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>

/// One topic of a ROS graph, ROS 1 (the master's) or ROS 2 (DDS discovery's) alike.
struct TopicInfo
{
    QString name;
    QString type;
    QStringList publishers; ///< node names
    QStringList subscribers;
    bool operator==(const TopicInfo& o) const
    {
        return name == o.name && type == o.type && publishers == o.publishers && subscribers == o.subscribers;
    }
};

/// What a graph knows, whichever graph it is: topics (sorted by name) and nodes. The views show
/// this; each graph's own detail (a ROS 2 endpoint's QoS and gid) stays with its transport.
struct TopicGraph
{
    QList<TopicInfo> topics;
    QStringList nodes;
    bool operator==(const TopicGraph& o) const { return topics == o.topics && nodes == o.nodes; }
    bool operator!=(const TopicGraph& o) const { return !(*this == o); }
    const TopicInfo* topic(const QString& name) const;
};
Q_DECLARE_METATYPE(TopicGraph)

/// The figures of one monitored topic with what its graph adds: ROS 1 gives the md5 and the
/// message definition of the publisher's connection header; ROS 2 gives neither (empty).
struct TopicStats : TopicFigures
{
    QString md5;
    QString definition;
};
