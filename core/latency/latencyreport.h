// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencystats.h"

#include <QJsonObject>
#include <QJsonValue>

class LatencyEngine;

/// The measurement report as JSON (docs/formats.md, "Report JSON"): samples, drops, every stage
/// with its crossing flag, the total, the derived communication figures and the clock offset,
/// all statistics in ms at full double precision (NaN, where a statistic is undefined, as null),
/// and the figures that contradict the pipeline (`warnings`, LatencyWarnings).
class LatencyReport
{
public:
    static QJsonObject statsJson(const LatencyStats& stats);
    /// `extraDropped`: samples lost before the engine saw them (incomplete CSV rows).
    static QJsonObject json(const LatencyEngine& engine, qint64 extraDropped = 0);
    static QJsonValue number(double value);
};
