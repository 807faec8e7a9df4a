// SPDX-License-Identifier: MIT
#pragma once

#include "session/fieldplotter.h"
#include "session/measuresession.h"

class LiveSession;

/// The parts of a live session its consumers in core take, built where they are composed (the
/// window, the commands, an experiment, tests), so that the consumers never see the session.
namespace LiveParts {
/// What a measurement reads: the drain, the master's graph, the ROS 2 participant and the broker.
MeasureSession::Parts measure(LiveSession* live);
/// What a field plotter reads: the sources and where the topics' types are known.
FieldPlotter::Parts plotter(LiveSession* live);
} // namespace LiveParts
