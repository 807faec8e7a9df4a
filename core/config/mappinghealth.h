// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

/// Whether a mapping carries data, from what discovery sees on both sides.
struct MappingHealth
{
    enum State {
        Unknown, ///< a side cannot be seen (master unreachable, broker not connected)
        Healthy, ///< traffic on the source and on the destination
        Idle, ///< nothing is sent on the source
        Missing, ///< the source topic does not exist on its side
        NoBridge, ///< the source publishes, the destination stays silent
        TypeMismatch, ///< the broker announces another type than the ROS graph has
        QosMismatch, ///< ROS 2: the bridge's QoS and the topic's endpoints cannot match
    };
    State state = Unknown;
    QString summary; ///< a few words for the table
    QString detail; ///< what was seen and what to do
    double latencyMs = -1; ///< stamped mappings: last one-way latency seen on the broker
};
