// SPDX-License-Identifier: MIT
#pragma once

#include "watch/bridgeliveness.h"

#include <memory>
#include <QHash>
#include <QStringList>
#include <vector>

struct LinkTrack;
struct MqttMessage;

/// The bridges of the watched links, by name: which links each carries, the topics of their last
/// wills, and each one's liveness (BridgeLiveness). Discovered links have no bridge (the broker
/// does not say whose they are).
class LinkBridges
{
public:
    using Tracks = std::vector<std::unique_ptr<LinkTrack>>;
    using Map = QHash<QString, std::shared_ptr<BridgeLiveness>>;

    /// The links changed: which bridge carries which link; what a bridge that stays knew is kept.
    void index(const Tracks& tracks);
    /// What each bridge's links show (BridgeLiveness::lastDataNs, carriesUntilNs, stalledLinks),
    /// counted anew from all of them: the monitor raises these as it judges links, and counts them
    /// anew once a second, when the refresh may have moved a source's period (a shorter one ends
    /// "carries" sooner).
    void recount(const Tracks& tracks);
    /// A message on an MQTT topic: a bridge's last will (its payload, not retained) marks it down.
    void noteWill(const MqttMessage& message, const Tracks& tracks);

    BridgeState state(const QString& bridge) const;
    /// The bridges' names, sorted.
    QStringList names() const;
    Map& all() { return m_bridges; }
    /// Until when link `t` shows its bridge carries data: its destination's last message and five
    /// periods of its source (at least a second); 0 before its first.
    static qint64 carriesUntilNs(const LinkTrack& t);

private:
    Map m_bridges;
    QHash<QString, QList<QString>> m_willTopics; ///< will topic -> bridges
};
