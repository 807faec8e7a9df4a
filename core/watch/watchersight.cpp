// SPDX-License-Identifier: MIT
#include "watchersight.h"

#include "watch/linktrack.h"

int WatcherSight::update(const std::vector<std::unique_ptr<LinkTrack>>& tracks, qint64 nowNs) const
{
    int changed = 0;
    const auto blind = [this](SourceGraph g) { return m_blind[std::size_t(g)]; };
    for (const auto& tp : tracks) {
        LinkTrack& t = *tp;
        LinkBlindness b = LinkBlindness::None;
        if (blind(SourceGraph::Mqtt))
            b = LinkBlindness::Broker;
        else if (!t.def.rosTopic.isEmpty() && t.onRos2 && blind(SourceGraph::Ros2))
            b = LinkBlindness::Ros2Domain;
        else if (!t.def.rosTopic.isEmpty() && !t.onRos2 && blind(SourceGraph::Ros1))
            b = LinkBlindness::RosMaster;
        changed += t.blindness != b ? 1 : 0;
        t.blindness = b;
        if (b != LinkBlindness::None && !t.blind)
            t.loseSight();
        else if (b == LinkBlindness::None && t.blind)
            t.regainSight(nowNs);
    }
    return changed;
}
