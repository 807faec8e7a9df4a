// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentplan.h"

#include <memory>
#include <QDateTime>
#include <QObject>
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
    static QString stateName(State s);
};

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
    /// needs them. False with `error` when the folder holds another plan or cannot be written.
    bool prepare(QString* error);
    /// Runs the cells that are not complete; finished() at the end or after stop().
    void start();
    /// Stops after cleaning up: the running cell goes back to pending (resume redoes it).
    void stop();

    const ExperimentPlan& plan() const { return m_plan; }
    const QList<CellStatus>& statuses() const { return m_statuses; }
    int runningCell() const { return m_current; }
    /// Of the running cell: samples recorded so far (0 in its warm-up).
    qint64 runningSamples() const;
    /// Seconds the cells not yet complete are expected to take (the running one's rest included).
    double remainingSeconds() const;
    QString directory() const { return m_dir; }

    static QString stateFileName() { return QStringLiteral("experiment.json"); }
    static QString planFileName() { return QStringLiteral("plan.yaml"); }
    /// The statuses DIR/experiment.json holds, in the plan's order of cells (ids matched).
    static std::optional<QList<CellStatus>> readState(const QString& directory, const ExperimentPlan& plan,
                                                      QString* error);

signals:
    void cellStarted(int index);
    void cellFinished(int index); ///< complete or failed; see statuses()
    void progress(int index, qint64 samples, bool warmingUp);
    void finished(bool allComplete);

private:
    struct Cell;
    void nextCell();
    void beginCell(int index);
    void poll();
    void endCell(CellStatus::State state, const QString& reason);
    bool writeState(QString* error = nullptr) const;

    ExperimentPlan m_plan;
    QByteArray m_planText;
    QString m_dir;
    Options m_options;
    QList<CellStatus> m_statuses;
    int m_current = -1;
    bool m_stopping = false;
    std::unique_ptr<Cell> m_cell;
};
