// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkdef.h"
#include "watch/watchrules.h"

#include <QCoreApplication>
#include <QList>

/// Why a link or a bridge is not ok. Named (reasonName()) only where events, the JSON and the
/// metrics are written: "stall", "source_stopped", ...
enum class LinkReason { SourceStopped, Stall, Loss, Rate, RateShare, Latency, BridgeDown };

/// The judge: a link's figures and silences against its rules give a level and the reasons.
///
/// Pure: no state, no clock of its own; LinkMonitor hands in what the traffic measured.
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
    };
    struct Verdict
    {
        LinkLevel level = LinkLevel::Ok;
        QList<LinkReason> reasons; ///< in the order the rules are checked
        QString detail; ///< the sentence of the worst reason
    };

    static Verdict judge(const LinkRules& rules, const LinkDef& link, const Input& input);
    /// Whether the source publishes now: silent for less than two periods (and half a second).
    static bool sourcePublishes(const Input& input);

    static QString reasonName(LinkReason reason);
    static QStringList reasonNames(const QList<LinkReason>& reasons);
};
