// SPDX-License-Identifier: MIT
#include "topicgraph.h"

#include <algorithm>

const TopicInfo* TopicGraph::topic(const QString& name) const
{
    const auto it = std::lower_bound(topics.cbegin(), topics.cend(), name,
                                     [](const TopicInfo& t, const QString& n) { return t.name < n; });
    return it != topics.cend() && it->name == name ? &*it : nullptr;
}
