// SPDX-License-Identifier: MIT
#pragma once

#include "record/runfile.h"

#include <memory>
#include <QObject>

/// Records a run while it is measured: the GUI thread hands over every drain tick's raw events,
/// a worker thread commits them to the run file at least every 200 ms.
///
/// Disk writes never run on the GUI thread. A failed write stops the recording and says why;
/// what was committed stays readable.
class RunRecorder : public QObject
{
    Q_OBJECT
public:
    static constexpr int kCommitIntervalMs = 200;

    explicit RunRecorder(QObject* parent = nullptr);
    ~RunRecorder() override;

    /// Creates the run file (refusing to overwrite one) and starts the worker.
    Result<void> start(const QString& path, const RunInfo& info);
    /// Queues one drain tick's events (GUI thread; cheap).
    void add(const std::vector<StampEvent>& stamps, const std::vector<LatencyValue>& latencies,
             qint64 drainedNs);
    /// Queues a watch event's start or end (GUI thread; cheap). Written with the next commit.
    void addEvent(const RecordedEvent& event);
    /// A host's clock as measured, holding after the drain tick `drainedNs`.
    void addClock(const ClockEstimate& estimate, qint64 drainedNs);
    /// Commits what is queued, records the stop time and closes the file (waits for the worker).
    Result<void> stop();

    bool isRecording() const;
    QString path() const;
    /// Stamps committed so far.
    qint64 committedStamps() const;
    qint64 queuedStamps() const;

signals:
    /// After a commit (on this object's thread).
    void committed(qint64 stamps);
    void failed(const QString& why);

private:
    struct Private;
    std::shared_ptr<Private> d;
};
