// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentplan.h"
#include "experiment/throughputresult.h"

#include <memory>
#include <QList>
#include <QObject>
#include <QString>

/// An experiment's throughput step, which the runner starts after the cells: per payload size of
/// the cells (in their order, each on the settings of the first cell with it), the plan's rates
/// one after another up to the first one not sustained. Each rate is a lab of its own
/// (ExperimentLab), warmed up and then measured for the plan's seconds per rate. DIR/throughput.json
/// holds the results after every rate (written atomically); a size complete there is kept by the
/// next start, one that is not is measured again. Runs on the owner's event loop.
class ThroughputStep : public QObject
{
    Q_OBJECT
public:
    /// `plan` must have a throughput step; `program` runs its bridges and nodes.
    ThroughputStep(ExperimentPlan plan, QString directory, QString program, QObject* parent = nullptr);
    ~ThroughputStep() override;

    /// Measures the rates not measured yet; finished() once every size is complete.
    void start();
    /// Stops: a running rate is dropped without its point (the next start measures it again), and
    /// no further rate starts.
    void stop();
    bool isProbing() const { return m_probe != nullptr; }
    const QList<ThroughputResult>& results() const { return m_results; }

signals:
    void probeStarted(int payloadBytes, double rateHz);
    void probeFinished(const ThroughputPoint& point);
    void finished();

private:
    struct Probe;
    void nextProbe();
    void poll();
    void endProbe(const ThroughputPoint& point);
    bool writeResults() const;

    ExperimentPlan m_plan;
    QString m_dir;
    QString m_program;
    bool m_stopping = false;
    std::unique_ptr<Probe> m_probe;
    QList<ThroughputResult> m_results;
    QList<CellSettings> m_settings; ///< per size: the first cell's settings with that payload
    int m_size = -1; ///< while a probe runs
};
