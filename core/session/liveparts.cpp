// SPDX-License-Identifier: MIT
#include "liveparts.h"

#include "session/livesession.h"

namespace LiveParts {
MeasureSession::Parts measure(LiveSession* live)
{
    return {live->sources(), live->rosGraph(), live->ros2(), live->mqtt()};
}

FieldPlotter::Parts plotter(LiveSession* live)
{
    return {live->sources(), live->mqttTopics(), live->ros2(), live->rosTopics(),
            [live]() -> const RosTypeRegistry& { return live->ros2Types(); }};
}
} // namespace LiveParts
