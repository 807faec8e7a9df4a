// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencyengine.h"
#include "record/runfile.h"

#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <vector>

/// One measured run as a report shows it: where it came from and its statistics.
struct ReportRun
{
    QString name;
    QString path;
    QString kind; ///< "run", "ROS bag", "suite CSV"
    RunInfo info;
    std::unique_ptr<LatencyEngine> engine;
    qint64 droppedBeforeImport = 0;
    std::vector<std::vector<qint64>> samples; ///< complete samples in pipeline order (for CSV)
    QHash<QString, int> stageByLabel; ///< the engine's stage series by label (first of each)
    std::vector<RecordedEvent> events; ///< the watch events recorded with the run, by start

    qint64 dropped() const { return qint64(engine->counters().dropped()) + droppedBeforeImport; }
};

/// The runs a report covers: one, several joined, or several side by side.
class Report
{
    Q_DECLARE_TR_FUNCTIONS(Report)
public:
    struct Options
    {
        qint64 window = 0; ///< statistics over the last N samples; 0: the whole run
        bool join = false; ///< several inputs as one run instead of side by side
        bool skipBadRows = false;
        QString title;
        bool oneClock = false; ///< every run's stamps share one clock (see Pipeline::oneClock())
    };

    /// Reads and computes every input. `warnings` gets skipped rows; `progress` can cancel.
    static Result<Report> build(const QStringList& inputs, const std::optional<Pipeline>& pipeline,
                                const Options& options, QStringList* warnings = nullptr,
                                const Progress& progress = {});
    /// A report of runs already in memory (the Reports page's live measurement, tests).
    static Report fromRuns(std::vector<RunData> runs, const std::optional<Pipeline>& pipeline,
                           const Options& options);

    const std::vector<std::unique_ptr<ReportRun>>& runs() const { return m_runs; }
    bool isComparison() const { return m_runs.size() > 1; }
    QString title() const;
    const Options& options() const { return m_options; }
    /// Whether any run has a pipeline to measure (a run of `watch` may hold events only).
    bool hasPipeline() const;
    /// Whether any run has latencies: a pipeline, or single-stage series (mqtt_client's own, the
    /// watch's observed hop latencies).
    bool hasLatency() const;
    /// Whether any run recorded watch events.
    bool hasEvents() const;

    /// The rows of the stage table: stage labels in order over all runs, then total and derived,
    /// then the single-stage series (observed hop latencies, mqtt_client's), by name.
    struct Row
    {
        QString label;
        QString seriesId; ///< per run: look up by label (stages) or by id (total, derived)
        bool crossing = false;
        bool emphasized = false; ///< the total
        bool derived = false;
    };
    QList<Row> rows() const;
    /// The statistics of `row` in `run`, or nullopt when the run has no such series.
    std::optional<LatencyStats> stats(const ReportRun& run, const Row& row) const;
    /// How far the figures of `row` in `run` can be off: a crossing corrected by measured clocks,
    /// or the asymmetry; nullopt for other rows.
    std::optional<double> uncertaintyMs(const ReportRun& run, const Row& row) const;

private:
    /// nullptr when `progress` cancelled it.
    static std::unique_ptr<ReportRun> compute(RunData&& data, const std::optional<Pipeline>& pipeline,
                                              const Options& options, const Progress& progress = {},
                                              int percent = 0);
    std::vector<std::unique_ptr<ReportRun>> m_runs;
    Options m_options;
};
