// SPDX-License-Identifier: MIT
#pragma once

#include "latency/headhub.h"
#include "latency/messagesource.h"
#include "latency/taphub.h"
#include "mqtt/mqttconnection.h"

#include <memory>
#include <QHash>
#include <vector>

class MqttTopics;

/// The broker's topics as a MessageSource, for the views that take any graph (field plots, Watch,
/// Map health): what RosMonitor is to ROS 1 and Ros2Participant to ROS 2.
///
/// The connection's discovery subscription already takes every topic, so monitoring subscribes to
/// nothing: it marks the topics whose figures (figures()) and message heads (openHeadTap()) a user
/// wants. The live session hands it each drain's batch (add()) on the GUI thread, where every call
/// runs; work per message is a hash lookup, and what it keeps is bounded by the callers' limits.
/// Figures are the topic tree's (rates, the last stamped payload's latency); the type of an arrival
/// is the ROS type mqtt_client announced for its topic, empty without an announcement.
class MqttSource : public MessageSource
{
public:
    explicit MqttSource(const MqttTopics* topics);
    ~MqttSource() override;

    /// One drain's messages, oldest first.
    void add(const std::vector<MqttMessage>& batch);

    SourceGraph sourceGraph() const override { return SourceGraph::Mqtt; }
    void monitor(const QString& topic) override;
    void unmonitor(const QString& topic) override;
    bool isMonitored(const QString& topic) const override;
    QHash<QString, TopicFigures> figures(qint64 nowNs) const override;
    std::unique_ptr<HeadTap> openHeadTap(std::size_t maxHeads) override;
    /// Subscribes to nothing (the connection takes every topic); arrivals carry the type
    /// mqtt_client announced for the topic.
    std::unique_ptr<Tap> openTap(const QString& topic, std::size_t maxMessages, qint64 maxBytes) override;

private:
    const MqttTopics* m_topics;
    QHash<QString, int> m_monitored; ///< topic → monitor() calls not yet balanced
    HeadHub m_heads;
    TapHub m_taps;
};
