// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicfigures.h"
#include "wire/sourcemessage.h"

#include <cstddef>
#include <memory>
#include <QHash>
#include <QSet>
#include <QString>
#include <vector>

/// The topics of a graph as monitors, views and plots use them, whatever the graph: ROS 1 through
/// the master (RosMonitor), ROS 2 through DDS (Ros2Participant), MQTT through the broker
/// (MqttSource). Subscriptions are counted (each user holds its own Subscriptions):
/// the last unmonitor() that balances a monitor() ends one, so that two users (the Discover page's
/// Mon, the Links page) do not end each other's. Whole messages come through a Tap per consumer as
/// SourceArrival, which SourceMessage decodes as their graph serializes; every monitored message's
/// first bytes come through a HeadTap per consumer as SourceHead (Watch).
/// One consumer's queue of a topic's whole messages (MessageSource::openTap()). Destroying it
/// ends what it asked of its source (the last tap of a topic ends the subscription made for it);
/// it may outlive its source, and then takes what was kept and nothing more.
class Tap
{
public:
    virtual ~Tap() = default;
    /// The messages since the last call, oldest first.
    virtual std::vector<SourceArrival> take() = 0;
    /// Messages dropped because more came between two takes than the tap keeps.
    virtual quint64 dropped() const = 0;
};

/// One consumer's buffer of every monitored message's head (MessageSource::openHeadTap()).
/// Destroying it ends what it asked of its source; it may outlive its source.
class HeadTap
{
public:
    virtual ~HeadTap() = default;
    /// The heads since the last call, oldest first.
    virtual std::vector<SourceHead> take() = 0;
    /// Heads dropped because more came between two takes than the tap keeps (on ROS 2 also those
    /// the DDS child dropped).
    virtual quint64 dropped() const = 0;
};

class MessageSource
{
public:
    virtual ~MessageSource() = default;
    virtual SourceGraph sourceGraph() const = 0;
    virtual void monitor(const QString& topic) = 0;
    virtual void unmonitor(const QString& topic) = 0;
    virtual bool isMonitored(const QString& topic) const = 0;
    /// Current figures of every monitored topic (rates computed for `nowNs`), whatever the graph:
    /// what Map health and other graph-neutral views read.
    virtual QHash<QString, TopicFigures> figures(qint64 nowNs) const = 0;
    /// From now on, and as long as the tap is open, the head of every message of a monitored topic
    /// is kept for this consumer, up to `maxHeads` between two HeadTap::take() (more are dropped
    /// and counted in the tap). Every tap gets every head.
    virtual std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads) = 0;
    /// A queue of this topic's whole messages for one consumer: the newest `maxMessages` within
    /// `maxBytes` between two Tap::take() (older ones dropped and counted in the tap). The topic is
    /// subscribed for it, monitored or not, as long as a tap of it is open; every tap gets every
    /// message, so two consumers never take each other's.
    virtual std::unique_ptr<Tap> openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes) = 0;
};
