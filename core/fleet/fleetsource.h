// SPDX-License-Identifier: MIT
#pragma once

#include "fleet/fleetsnapshot.h"
#include "fleet/prometheusclient.h"

#include <functional>
#include <QObject>

/// A link's history from query_range: the destination's rate and the latency p99.
struct FleetHistory
{
    QList<PrometheusAnswer::Point> destinationRateHz;
    QList<PrometheusAnswer::Point> latencyP99Ms;
    QString error; ///< empty when both series came
};

/// The fleet view's source: every host's links from a Prometheus server, refreshed on request
/// (the page asks every 5 s). Nothing is subscribed on any broker or master: it only asks
/// Prometheus. While the server cannot be reached the last snapshot stays, and error() says why:
/// the window's own outage is not the links going down.
///
/// The counters' totals (the `messages` and `bytes` queries, two series a link) are asked at the
/// first refresh and then once they are kTotalsSeconds old; the refreshes between reuse them. The
/// table shows neither, and the judge only asks whether a side ever counted when it counted
/// nothing over the last minute (kRateWindowSeconds): a side's first message is in the minute's
/// increase for longer than the totals are old, so the verdicts are those of totals asked each time.
/// A snapshot's figures' `messages` and `bytes` are as old as the totals.
class FleetSource : public QObject
{
    Q_OBJECT
public:
    /// How old the totals may be before a refresh asks them again: half the rates' window.
    static constexpr double kTotalsSeconds = FleetSnapshotBuilder::kRateWindowSeconds / 2.0;

    explicit FleetSource(QObject* parent = nullptr);

    void setServer(const QUrl& base, const QString& user = {}, const QString& password = {});
    QUrl server() const { return m_client->server(); }
    void setRules(const WatchRules& rules) { m_rules = rules; }
    /// kTotalsSeconds, for tests (0: the totals at every refresh).
    void setTotalsSeconds(double seconds) { m_totalsSeconds = seconds; }
    /// Whether `name` (of FleetSnapshotBuilder::queries()) is one of the totals asked less often.
    static bool isTotal(const QString& name);
    PrometheusClient* client() const { return m_client; }

    /// Asks the server for a new snapshot; nothing when a refresh is under way.
    void refresh();
    bool refreshing() const { return m_pending > 0; }
    const FleetSnapshot& snapshot() const { return m_snapshot; }
    /// Why the last refresh failed ("cannot reach …"), empty when it succeeded.
    QString error() const { return m_error; }
    quint64 refreshes() const { return m_refreshes; }
    /// The last `minutes` of `link`'s destination rate and p99, one point every `stepSeconds`.
    void history(const FleetLink& link, double now, double minutes, double stepSeconds,
                 std::function<void(const FleetHistory&)> done);

signals:
    /// A refresh ended: snapshot() is new, or error() says why it is not.
    void refreshed();

private:
    /// Every answer of the refresh asked at `now` came (`totals`: the totals among them).
    void answered(double now, bool totals);

    PrometheusClient* m_client;
    WatchRules m_rules;
    FleetSnapshot m_snapshot;
    QString m_error;
    int m_pending = 0;
    quint64 m_generation = 0;
    quint64 m_refreshes = 0;
    QHash<QString, PrometheusAnswer> m_answers;
    QHash<QString, double> m_hostsSeen;
    QHash<QString, PrometheusAnswer> m_totals; ///< the last totals' answers (empty: none yet)
    double m_totalsAt = 0; ///< when they were asked (seconds since the epoch)
    double m_totalsSeconds = kTotalsSeconds;
};
