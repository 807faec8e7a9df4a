// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentstate.h"

#include <optional>
#include <QCoreApplication>
#include <QList>
#include <QString>

struct ThroughputResult;

/// An experiment's folder and its layout, in one place: the copy of its plan (plan.yaml), the
/// state of its cells (experiment.json), the throughput step (throughput.json) and a run per cell
/// (runs/ID.bsrun). The runner writes it, the report and the Experiments page read it.
class ExperimentFolder
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentRunner)
public:
    explicit ExperimentFolder(QString path)
        : m_path(std::move(path))
    { }

    static QString planFileName() { return QStringLiteral("plan.yaml"); }
    static QString stateFileName() { return QStringLiteral("experiment.json"); }
    static QString throughputFileName() { return QStringLiteral("throughput.json"); }
    /// A cell's run file, relative to the folder (never what the state file says).
    static QString runPathOf(const ExperimentCell& cell) { return ExperimentState::runPathOf(cell); }
    /// Whether `path` is an experiment's folder (it holds a state file).
    static bool isExperiment(const QString& path);

    const QString& path() const { return m_path; }
    QString planPath() const { return filePath(planFileName()); }
    QString statePath() const { return filePath(stateFileName()); }
    QString throughputPath() const { return filePath(throughputFileName()); }
    /// `relative` (a run of runPathOf(), say) inside the folder.
    QString filePath(const QString& relative) const;

    /// The statuses the state file holds, in the plan's order of cells (ids matched).
    /// An error names the state file.
    Result<QList<CellStatus>> readState(const ExperimentPlan& plan) const;
    /// What the throughput file holds (empty when the plan has no throughput step or it has not run).
    QList<ThroughputResult> readThroughput() const;

private:
    QString m_path;
};
