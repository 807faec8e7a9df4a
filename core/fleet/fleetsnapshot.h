// SPDX-License-Identifier: MIT
#pragma once

#include "fleet/prometheusanswer.h"
#include "watch/linkdef.h"
#include "watch/linkjudge.h"
#include "watch/watchrules.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

/// A host whose `bridgescope watch` Prometheus scrapes (its `host` label).
struct FleetHost
{
    QString name;
    QString version; ///< Bridgescope's, from bridgescope_watch_info
    bool reporting = false; ///< its bridgescope_watch_info is in Prometheus now
    double lastSeen = 0; ///< seconds since the epoch of its last bridgescope_watch_info (0: not known)
};

/// One link of one host as Prometheus has it, with the figures the local watch would hold and the
/// verdict of the same judge.
struct FleetLink
{
    QString host, bridge, link, direction; ///< the labels
    LinkDef def; ///< what the labels tell of the link (topics, direction, the bridge as config and client)
    LinkFigures figures;
    LinkJudge::Verdict verdict;
    bool hostReporting = true;
    int reportedState = -1; ///< the watch's own bridgescope_link_state (-1: not now)
    bool bridgeDown = false;
    QString key() const { return host + u'|' + bridge + u'|' + link + u'|' + direction; }
};

/// Every host's links at one refresh.
struct FleetSnapshot
{
    QList<FleetLink> links; ///< ordered by host, bridge, link, direction
    QList<FleetHost> hosts; ///< by name
    double time = 0; ///< when it was taken (seconds since the epoch)
    qsizetype droppedSeries = 0; ///< series past the bound of an answer
    qsizetype badSamples = 0; ///< series or samples of the wrong form
    QStringList warnings; ///< the server's
};

/// Builds a FleetSnapshot from the answers of a few instant queries (queries()), and judges each
/// link with LinkJudge and the WatchRules the local watch uses. Pure: no network, no clock.
///
/// Prometheus does not keep the times of a link's last messages; its silences are estimated from
/// the watch's 5-second rates and the counters' increase over the last minute (see build()).
/// The rates a link shows are its counters' mean over kRateWindowSeconds, the window of the
/// history's chart too: a link slower than one message in 5 s is not shown as 0 Hz beside a chart
/// that draws it.
class FleetSnapshotBuilder
{
    Q_DECLARE_TR_FUNCTIONS(FleetSnapshotBuilder)
public:
    /// The window of the rates shown, in the table and in the history's chart.
    static constexpr int kRateWindowSeconds = 60;
    /// kRateWindowSeconds as a PromQL range: "[60s]".
    static QString rateRange();
    /// A name and its PromQL, asked together at each refresh.
    static QList<std::pair<QString, QString>> queries();
    /// `hostsSeen`: each host's last sighting from earlier refreshes, updated. A host seen before
    /// (or within the last hour, as Prometheus keeps it) and absent now is not reporting: its links
    /// are unknown, "host stopped reporting since HH:MM", never ok.
    static FleetSnapshot build(const QHash<QString, PrometheusAnswer>& answers, const WatchRules& rules,
                               double now, QHash<QString, double>* hostsSeen);
    /// The link named by the labels of a link's series: topics split at " → " in the data's direction.
    static LinkDef linkDef(const QString& bridge, const QString& link, const QString& direction);
    /// "host stopped reporting since HH:MM" (local time of `lastSeen`).
    static QString stoppedText(double lastSeen);
};
