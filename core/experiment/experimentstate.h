// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "experiment/experimentplan.h"

#include <optional>
#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

/// Where a cell stands, as DIR/experiment.json keeps it.
struct CellStatus
{
    enum State { Pending, Running, Complete, Failed };
    State state = Pending;
    QString reason; ///< why it failed (or was cut)
    QString run; ///< the run file, relative to the experiment's folder
    qint64 samples = 0; ///< recorded
    QDateTime started;
    QDateTime finished;
    /// The link profile's relays, summed (all zero without one): bytes relayed, bursts "lost"
    /// (delivered late), and how often reading paused because the relays held their memory bound.
    struct Link
    {
        quint64 bytes = 0;
        quint64 lostBursts = 0;
        quint64 readPauses = 0;
    } link;
    static QString stateName(State s);
};

/// DIR/experiment.json as read back: a file is input (bounded, and fuzzed by fuzz_experimentstate).
class ExperimentState
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentRunner)
public:
    /// The most of a state file that is read.
    static constexpr qsizetype kMaxBytes = 16 * 1024 * 1024;
    static constexpr qsizetype kMaxReason = 2000;
    /// A cell's run file, relative to the experiment's folder (never what the state file says).
    static QString runPathOf(const ExperimentCell& cell)
    {
        return QStringLiteral("runs/%1.bsrun").arg(cell.id());
    }
    /// The statuses `json` holds, in the plan's order of cells (matched by id; a cell it does not
    /// name is pending). An error when it is not an experiment's state.
    static Result<QList<CellStatus>> parse(const QByteArray& json, const ExperimentPlan& plan);
};
