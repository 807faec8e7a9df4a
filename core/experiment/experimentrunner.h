// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentfolder.h"
#include "experiment/experimentplan.h"
#include "experiment/experimentstate.h"
#include "experiment/throughputstep.h"

#include <memory>
#include <QDateTime>
#include <QJsonObject>
#include <QObject>
#include <QString>

/// Runs an experiment plan cell after cell into a folder: each cell its own lab (servers or the
/// given ones, bridges, relays for its link profile, nodes), the warm-up, then the samples recorded
/// as DIR/runs/<cell>.bsrun with the cell's levels in the run's metadata. DIR/experiment.json says
/// where every cell stands after every change (written atomically), so `resume` after Ctrl+C, a
/// kill -9 or a power cut skips the complete cells and redoes the one that was cut. A cell that
/// fails (a bridge that will not run, no samples in time) is marked failed with the reason and the
/// rest go on. Runs on the owner's event loop; starting a cell's servers blocks for a second or two.
class ExperimentRunner : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        QString program; ///< the bridgescope binary for bridges and nodes (default: this program)
        bool resume = false;
    };

    ExperimentRunner(ExperimentPlan plan, QByteArray planText, QString directory, Options options,
                     QObject* parent = nullptr);
    ~ExperimentRunner() override;

    /// Makes (or, resuming, checks) the folder: the plan's copy, the state, TLS files when a cell
    /// needs them. An error when the folder holds another plan or cannot be written.
    /// Resuming, a complete cell's run is checked (see resumeNotes()).
    Status prepare();
    /// What prepare() found resuming: each complete cell whose run could not be kept (a symlink,
    /// not a regular file, not a run of the cell, fewer samples than the plan's), done again.
    const QStringList& resumeNotes() const { return m_resumeNotes; }
    /// Runs the cells that are not complete; finished() at the end or after stop().
    void start();
    /// Stops after cleaning up: the running cell goes back to pending (resume redoes it).
    void stop();

    const ExperimentPlan& plan() const { return m_plan; }
    const QList<CellStatus>& statuses() const { return m_statuses; }
    int runningCell() const { return m_current; }
    /// Of the running cell: samples recorded so far (0 in its warm-up); of one that has just
    /// ended, what it recorded.
    qint64 runningSamples() const;
    /// Seconds the cells not yet complete are expected to take (the running one's rest included).
    double remainingSeconds() const;
    QString directory() const { return m_dir; }

    /// The throughput step's results so far (none when the plan has no such step).
    const QList<ThroughputResult>& throughput() const;

signals:
    void cellStarted(int index);
    void cellFinished(int index); ///< complete or failed; see statuses()
    void progress(int index, qint64 samples, bool warmingUp);
    /// Once per cell, a few seconds in, when its broker or master cannot be reached or no stamp
    /// has come; the cell goes on trying until its timeout.
    void warning(int index, const QString& text);
    /// The running cell's samples recorded since the last call: their totals, in ms.
    void totals(int index, const QList<double>& totalMs);
    void probeStarted(int payloadBytes, double rateHz); ///< a rate of the throughput step (ThroughputStep)
    void probeFinished(const ThroughputPoint& point);
    void finished(bool allComplete);

private:
    struct Cell;
    void nextCell();
    void finish(); ///< finished(), whether every cell is complete
    void beginCell(int index);
    void poll();
    void saySilence(Cell& c);
    void endCell(CellStatus::State state, const QString& reason);
    void sendTotals();
    /// Writes the state file; a failure is logged too.
    Status writeState() const;

    ExperimentPlan m_plan;
    QByteArray m_planText;
    QString m_dir;
    Options m_options;
    QList<CellStatus> m_statuses;
    QStringList m_resumeNotes;
    int m_current = -1;
    bool m_stopping = false;
    std::unique_ptr<Cell> m_cell;
    std::unique_ptr<ThroughputStep> m_throughputStep; ///< after the cells, when the plan has one
    bool m_throughputDone = false;
};
