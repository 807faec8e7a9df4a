// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QString>
#include <QtGlobal>

/// How many probes the clock service answers: token buckets per peer (a UDP address, an MQTT
/// reply topic) and for all of them together, over a bounded number of tracked peers. A probe
/// beyond any of them is dropped; the caller counts it.
class ClockBudget
{
public:
    static constexpr double kPerPeerHz = 20;
    static constexpr double kTotalHz = 500;
    static constexpr int kMaxPeers = 1024;

    ClockBudget(double perPeerHz = kPerPeerHz, double totalHz = kTotalHz, int maxPeers = kMaxPeers);

    /// Whether a probe from `peer` arriving at `nowNs` (any monotonic ns) may be answered; takes its token.
    bool allow(const QString& peer, qint64 nowNs);
    int peers() const { return int(m_peers.size()); }

private:
    struct Bucket
    {
        double tokens = 0;
        qint64 lastNs = 0;
    };
    /// Adds what `rateHz` gave since the bucket's last refill, up to one second's worth.
    static void refill(Bucket& b, double rateHz, qint64 nowNs);
    /// Forgets peers whose bucket has refilled completely (idle for a second or more).
    void forgetIdle(qint64 nowNs);

    double m_perPeerHz;
    double m_totalHz;
    int m_maxPeers;
    Bucket m_total;
    QHash<QString, Bucket> m_peers;
};
