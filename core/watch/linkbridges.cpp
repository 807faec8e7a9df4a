// SPDX-License-Identifier: MIT
#include "linkbridges.h"

#include "mqtt/mqttconnection.h"
#include "watch/linktrack.h"

#include <algorithm>

void LinkBridges::index(const Tracks& tracks)
{
    m_willTopics.clear();
    Map bridges;
    for (int i = 0; i < int(tracks.size()); ++i) {
        LinkTrack& t = *tracks[std::size_t(i)];
        const LinkDef& d = t.def;
        t.bridge = nullptr;
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
        t.bridge = b.get();
        if (!d.willTopic.isEmpty() && !m_willTopics.value(d.willTopic).contains(d.bridge()))
            m_willTopics[d.willTopic] << d.bridge();
    }
    m_bridges = bridges;
    recount(tracks);
}

void LinkBridges::recount(const Tracks& tracks)
{
    for (auto& b : m_bridges) {
        b->lastDataNs = 0;
        b->carriesUntilNs = 0;
        b->stalledLinks = 0;
    }
    for (const auto& tp : tracks) {
        const LinkTrack& t = *tp;
        if (!t.bridge)
            continue;
        t.bridge->lastDataNs = std::max(t.bridge->lastDataNs, t.dst.f.lastNs);
        t.bridge->carriesUntilNs = std::max(t.bridge->carriesUntilNs, carriesUntilNs(t));
        t.bridge->stalledLinks += t.stalled ? 1 : 0;
    }
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

qint64 LinkBridges::carriesUntilNs(const LinkTrack& t)
{
    if (t.dst.f.lastNs == 0)
        return 0;
    return t.dst.f.lastNs + std::max<qint64>(5 * t.src.expectedPeriodNs(), LinkWindows::kSecond);
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
