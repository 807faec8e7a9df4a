// SPDX-License-Identifier: MIT
#pragma once

#include "wire/stampevent.h"

#include <QHash>
#include <QString>
#include <vector>

/// Where stamps come from, whatever the graph: ROS 1 (RosStampSource), ROS 2 (Ros2StampSource),
/// MQTT (MqttStampDecoder). The measurement takes them all alike on its drain tick, so that a new
/// graph's stamps are one more source, not a feature of the measurement. Every source decodes
/// through SourceMessage, the one place that picks a decoder for a graph and a type.
class StampSource
{
public:
    virtual ~StampSource() = default;
    /// Appends the stamps and single-stage latencies that arrived since the last call.
    virtual void takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies) = 0;
    /// Messages of stamp topics that did not decode, or came with another type.
    virtual quint64 malformedStamps() const = 0;
    /// The same per topic.
    virtual QHash<QString, quint64> malformedStampsByTopic() const = 0;
    /// The last reason, "TOPIC: why" (empty when none).
    virtual QString lastStampError() const = 0;
};
