// SPDX-License-Identifier: MIT
#pragma once

#include "wire/sourcemessage.h"

#include <memory>
#include <vector>

struct LinkTrack;

/// What the watcher can see: its own broker connection, the ROS master, the ROS 2 domain. A link
/// with a side on an unseen graph is unknown (LinkBlindness): not stalled, nothing lost, and its
/// traffic counts again from when the watcher sees it again.
class WatcherSight
{
public:
    void setSeeing(SourceGraph graph, bool seeing) { m_blind[std::size_t(graph)] = !seeing; }
    bool sees(SourceGraph graph) const { return !m_blind[std::size_t(graph)]; }
    /// The graphs it cannot see, one bit each (by SourceGraph): update() needs a pass over the links
    /// only when this, the links or their graphs changed.
    unsigned blindMask() const
    {
        return (m_blind[0] ? 1U : 0U) | (m_blind[1] ? 2U : 0U) | (m_blind[2] ? 4U : 0U);
    }
    /// Each link's blindness at `nowNs`, from the graphs its sides are on: a link that loses sight
    /// forgets its windows, one that regains it counts from `nowNs`.
    /// Returns how many links' blindness changed.
    int update(const std::vector<std::unique_ptr<LinkTrack>>& tracks, qint64 nowNs) const;

private:
    bool m_blind[3] = {false, false, false}; ///< by SourceGraph
};
