// SPDX-License-Identifier: MIT
#pragma once

#include "demo/demolab.h"
#include "experiment/experimentplan.h"

#include <memory>
#include <QElapsedTimer>
#include <QString>

class LinkRelay;
class LiveSession;
class MeasureSession;

/// What one cell of an experiment, or one rate of its throughput step, runs on: the lab (the
/// plan's servers or its own, bridges, nodes), relays for the cell's link profile, and a live
/// session measuring the plan's pipeline. Destroyed in reverse: the measurement, the live session,
/// the relays, then the lab (which stops its processes).
struct ExperimentLab
{
    /// How often a running cell or probe is looked at.
    static constexpr int kPollMs = 100;

    ExperimentLab();
    ~ExperimentLab();
    ExperimentLab(const ExperimentLab&) = delete;
    ExperimentLab& operator=(const ExperimentLab&) = delete;

    /// Starts everything for `settings` of `plan`, whose folder is `directory` (its TLS files) and
    /// whose bridges and nodes are run by `program`; `seed` makes the relays' randomness. The error
    /// when a part does not start; what did start stays until this is destroyed.
    Status start(const ExperimentPlan& plan, const CellSettings& settings, int seed, const QString& directory,
                 const QString& program);

    DemoLab lab;
    std::unique_ptr<LinkRelay> vehicleRelay;
    std::unique_ptr<LinkRelay> cloudRelay;
    std::unique_ptr<LiveSession> live;
    std::unique_ptr<MeasureSession> measure;
    QElapsedTimer clock; ///< since start()
};
