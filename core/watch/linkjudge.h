// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"
#include "watch/watchrules.h"

#include <QCoreApplication>
#include <QList>

/// Why a link or a bridge is not ok. Named (reasonName()) only where events, the JSON and the
/// metrics are written: "stall", "source_stopped", ...
enum class LinkReason { SourceStopped, Stall, Loss, Rate, RateShare, Latency, BridgeDown };

/// What keeps the watcher from seeing a side of a link: its own connection, not the bridge.
enum class LinkBlindness { None, Broker, RosMaster, Ros2Domain };

/// The judge: a link's figures and silences against its rules give a level and the reasons.
///
/// Pure: no state, no clock of its own; LinkMonitor hands in what the traffic measured, whether
/// it can see both sides, and the stall it is in (a stall ends only after kStallRecoveryNs of
/// steady messages, so that a destination fed in bursts does not end and restart it every second).
class LinkJudge
{
    // Its sentences were LinkMonitor's and keep their translations.
    Q_DECLARE_TR_FUNCTIONS(LinkMonitor)
public:
    /// What a link looks like at one moment.
    struct Input
    {
        LinkFigures figures;
        qint64 periodNs = 0; ///< the source's expected period
        qint64 sourceSilenceNs = -1; ///< since the source's last message (-1: none yet)
        qint64 destinationSilenceNs = 0; ///< since the destination's last message or the source's (re)start
        /// The windows are past any stall, start or restart: loss and rates can be judged.
        bool settled = false;
        /// Until then (0 once settled): the moment the verdict may change without a message.
        qint64 settlesInNs = 0;
        /// The watcher cannot see a side (its broker connection is down, the master unreachable):
        /// nothing can be told of the link, and the bridge is not blamed.
        LinkBlindness blindness = LinkBlindness::None;
        /// The level of the stall the link is in (Ok: none).
        LinkLevel stallLevel = LinkLevel::Ok;
        /// How long the destination has not been silent past the stall threshold (see Verdict::silent).
        qint64 destinationSteadyNs = 0;
    };
    /// How long a stalled destination must carry messages steadily before the stall ends.
    static constexpr qint64 kStallRecoveryNs = 2'000'000'000LL;
    struct Verdict
    {
        LinkLevel level = LinkLevel::Ok;
        QList<LinkReason> reasons; ///< in the order the rules are checked
        QString detail; ///< the sentence of the worst reason
        /// The watcher cannot tell (its own connection): `detail` says why, the level is Ok.
        bool unknown = false;
        /// The destination is silent past the stall threshold while the source publishes (a stall,
        /// or one starting); the monitor counts steadiness from the last moment it was.
        bool silent = false;
    };

    static Verdict judge(const LinkRules& rules, const LinkDef& link, const Input& input);
    /// How long the verdict on `input` stays the same if no message arrives and the figures stay:
    /// until the first silence crosses a limit, a stall's recovery ends or the windows settle
    /// (0: never, or not while the watcher is blind). The monitor judges a link again then, not on
    /// every tick.
    static qint64 quietNs(const LinkRules& rules, const Input& input);
    /// Whether the source publishes now: silent for less than two periods (and half a second).
    static bool sourcePublishes(const Input& input);
    /// "broker unreachable", "ROS master unreachable", ... (empty for None).
    static QString blindnessText(LinkBlindness blindness);

    static QString reasonName(LinkReason reason);
    static QStringList reasonNames(const QList<LinkReason>& reasons);
};
