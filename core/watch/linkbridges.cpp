// SPDX-License-Identifier: MIT
#include "linkbridges.h"

#include "mqtt/mqttconnection.h"
#include "watch/linktrack.h"

void LinkBridges::index(const Tracks& tracks)
{
    m_willTopics.clear();
    Map bridges;
    for (int i = 0; i < int(tracks.size()); ++i) {
        const LinkDef& d = tracks[std::size_t(i)]->def;
        if (d.discovered)
            continue; // whose bridge it is, the broker does not say
        std::shared_ptr<BridgeLiveness>& b = bridges[d.bridge()];
        if (!b) {
            b = std::make_shared<BridgeLiveness>();
            if (const auto old = m_bridges.value(d.bridge())) { // what it knew stays
                b->willDownNs = old->willDownNs;
                b->state = old->state;
            }
        }
        b->links << i;
        if (!d.willTopic.isEmpty() && !m_willTopics.value(d.willTopic).contains(d.bridge()))
            m_willTopics[d.willTopic] << d.bridge();
    }
    m_bridges = bridges;
}

void LinkBridges::noteWill(const MqttMessage& m, const Tracks& tracks)
{
    const auto it = m_willTopics.constFind(m.topic);
    if (it == m_willTopics.cend())
        return;
    for (const QString& name : *it) {
        auto b = m_bridges.value(name);
        const int first = b && !b->links.isEmpty() ? b->links.first() : -1;
        if (first >= 0 && m.payload == tracks[std::size_t(first)]->def.willMessage && !m.retained)
            b->willDownNs = m.receivedNs;
    }
}

BridgeState LinkBridges::state(const QString& bridge) const
{
    const auto b = m_bridges.value(bridge);
    return b ? b->state : BridgeState::Unknown;
}

QStringList LinkBridges::names() const
{
    QStringList names = m_bridges.keys();
    names.sort();
    return names;
}
