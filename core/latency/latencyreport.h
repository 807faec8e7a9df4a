// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencystats.h"

#include <QJsonObject>
#include <QJsonValue>

class LatencyEngine;
class PipelineSeries;
struct ClockEstimate;

/// The measurement report as JSON (docs/formats.md, "Report JSON"): samples, drops, every stage
/// with its crossing flag, the total, the derived communication figures and the clock offset,
/// all statistics in ms at full double precision (NaN, where a statistic is undefined, as null),
/// and the figures that contradict the pipeline (`warnings`, LatencyWarnings). With measured
/// clocks: each crossing's `corrected` statistics and the communication's `asymmetry`, each with its
/// `uncertainty_ms`, and the estimates themselves (`clocks`).
class LatencyReport
{
public:
    static QJsonObject statsJson(const LatencyStats& stats);
    /// `extraDropped`: samples lost before the engine saw them (incomplete CSV rows).
    static QJsonObject json(const LatencyEngine& engine, qint64 extraDropped = 0);
    static QJsonValue number(double value);
    /// A Corrected or Asymmetry series: its statistics and `uncertainty_ms`.
    static QJsonObject measuredJson(const PipelineSeries& series, int index);
    static QJsonObject clockJson(const ClockEstimate& clock);
};
