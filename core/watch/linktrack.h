// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"
#include "watch/linkjudge.h"
#include "watch/linktraffic.h"
#include "watch/watchrules.h"
#include "wire/mqttclientwire.h"

#include <algorithm>
#include <deque>
#include <optional>

/// Destination rate and latency p99 of a link at one refresh.
struct LinkHistoryPoint
{
    qint64 ns = 0;
    double rateHz = 0;
    double p99Ms = qQNaN();
    LinkLevel level = LinkLevel::Ok;
};

/// A watched link: its definition and rules, its traffic, how its messages are read (LinkReader),
/// and what the judge last said of it (LinkMonitor).
struct LinkTrack : LinkTraffic
{
    LinkDef def;
    LinkRules rules;
    qint64 startNs = 0;
    bool dstHeader = false; ///< the destination's messages start with a Header
    bool srcHeader = false;
    std::optional<bool> announcedStamped;
    bool ros2 = false; ///< announced by mqtt_client for ROS 2: CDR, a 12-byte stamp
    LinkLevel level = LinkLevel::Ok;
    QList<LinkReason> reasons;
    std::deque<LinkHistoryPoint> history;
    quint64 stalls = 0;
    bool stalled = false;
    LinkLevel stallLevel = LinkLevel::Ok;
    qint64 stallEndedNs = 0;
    qint64 silentNs = 0; ///< the last check that found the destination silent past the stall threshold
    bool onRos2 = false; ///< its ROS topic is watched on the ROS 2 domain
    LinkBlindness blindness = LinkBlindness::None;
    QString unknown; ///< the judge's sentence while it cannot see a side

    bool stamped() const { return announcedStamped.value_or(def.stamped); }
    MqttClientWire::Dialect dialect() const
    {
        return ros2 ? MqttClientWire::Dialect::Ros2 : MqttClientWire::Dialect::Ros1;
    }
    /// The injected stamp before its MQTT payloads' message (0: not stamped).
    qsizetype stampBytes() const { return stamped() ? MqttClientWire::stampBytes(dialect()) : 0; }
    /// Nothing has arrived at either end yet: no silence counts and no figure moves, so the judge's
    /// verdict cannot change while the watcher sees what it saw (see LinkMonitor::tick()).
    bool dormant() const
    {
        return src.f.lastNs == 0 && dst.f.lastNs == 0 && latencySamples == 0 && !stalled && level == LinkLevel::Ok;
    }
    bool judgedDormant = false; ///< dormant() when the judge last saw the link
    LinkBlindness judgedBlindness = LinkBlindness::None; ///< and its blindness then
    qint64 judgedNs = 0; ///< when the judge last saw it
    /// When a silence may change its verdict next (LinkJudge::quietNs; 0: not before a message).
    qint64 judgeAtNs = 0;
    qint64 queuedNs = 0; ///< the time of its entry in the monitor's deadlines (0: none)
    bool heard = false; ///< in the reader's list of links heard since the judge last saw them
    bool moved = false; ///< in the reader's list of links moved since the metrics last took them
    bool observedNew = false; ///< in the reader's list of links with matched messages to hand over
    struct BridgeLiveness* bridge = nullptr; ///< the bridge that carries it (none: discovered)

    /// How long after the last thing a link heard its figures stop moving: past every window.
    static constexpr qint64 kStillNs = LinkWindows::kLatencyWindowNs + 2 * LinkWindows::kSecond;
    /// Nothing arrived for longer than every window (both ends, latency, the watcher's sight and
    /// a stall's end): a refresh would give the same figures again (LinkMonitor skips it).
    bool still(qint64 nowNs) const
    {
        const qint64 last
            = std::max({src.f.lastNs, dst.f.lastNs, latencies.empty() ? 0 : latencies.back().first,
                        sightNs > 0 ? sightNs + LinkWindows::kSightMarginNs : 0, stallEndedNs});
        return last > 0 && nowNs - last > kStillNs && !blind;
    }

    int pipelineIn = -1; ///< index of PREFIX/in in the pipeline
    int pipelineOut = -1;
    bool pipelineLatency = false; ///< a pipeline sample arrived: other latency sources are ignored
};
