// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>

/// Whether a bridge is up, down, or unknown (no traffic to judge by).
enum class BridgeState { Unknown, Up, Down };

/// One bridge's liveness: its links' traffic and its last will decide whether it is up.
struct BridgeLiveness
{
    // Its sentences were LinkMonitor's and keep their translations.
    Q_DECLARE_TR_FUNCTIONS(LinkMonitor)
public:
    /// What the bridge's links show at one moment.
    struct Input
    {
        bool carries = false; ///< a link's destination got a message within five periods
        bool stalled = false; ///< a link stalls
        qint64 lastDataNs = 0; ///< the last message at any of its destinations
        qint64 nowNs = 0;
        /// The watch's own broker connection is down: nothing can be told of the bridge.
        bool blind = false;
    };
    /// How long the watch's own connection must outlive a last will before the will is believed:
    /// a broker that shuts down sends the wills of every client it drops, the watch's among the last.
    static constexpr qint64 kWillGraceNs = 1'000'000'000LL;

    QList<int> links; ///< the monitor's indexes of its links
    /// What its links showed when the judge last saw each (LinkMonitor keeps these as it judges
    /// them, so that a bridge of 10,000 links is judged without a pass over them every tick).
    qint64 lastDataNs = 0; ///< the last message at any of its destinations
    qint64 carriesUntilNs = 0; ///< a destination got a message within five of its source's periods until then
    int stalledLinks = 0; ///< links that stall
    qint64 willDownNs = 0; ///< when its last will arrived (0: not since it last carried data)
    BridgeState state = BridgeState::Unknown;

    /// Takes the links' traffic in; true when the state changed.
    bool update(const Input& input);
    /// The sentence of a bridge that is down (empty when it is not).
    QString detail(const QString& name) const;
};
