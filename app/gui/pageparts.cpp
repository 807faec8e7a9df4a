// SPDX-License-Identifier: MIT
#include "pageparts.h"

#include "session/liveparts.h"
#include "session/livesession.h"

namespace PageParts {
DetailPane::Parts detail(LiveSession* live)
{
    return {LiveParts::plotter(live), live->ros2Topics(), live->graphStatus()};
}

DiscoverPage::Parts discover(LiveSession* live)
{
    return {live,         live->rosTopics(),   live->ros2Topics(), live->mqttTopics(),
            live->mqtt(), live->graphStatus(), detail(live)};
}

MapPage::Parts map(LiveSession* live)
{
    return {live->sources(),    live->rosTopics(),   live->ros2Topics(),
            live->mqttTopics(), live->graphStatus(), live->mqtt()};
}
} // namespace PageParts
