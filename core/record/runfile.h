// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "latency/rundata.h"
#include "wire/stampevent.h"

#include <functional>
#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QStringList>
#include <vector>

/// The run file: an SQLite database (format documented in docs/formats.md, "Run files").
///
/// Written with WAL journaling and a commit at least every 200 ms while recording, so a killed
/// recorder loses at most the last commit interval and the file still opens; finished runs are
/// checkpointed into one self-contained file.
class RunFile
{
    Q_DECLARE_TR_FUNCTIONS(RunFile)
public:
    static constexpr int kFormatVersion = 1;
    static QString suffix() { return QStringLiteral("bsrun"); }
    /// Whether the file starts like an SQLite database.
    static bool looksLikeRun(const QString& path);

    static Result<RunData> read(const QString& path, const Progress& progress = {});
    /// Deletes a run file and its SQLite side files (-wal, -shm, -journal).
    static void remove(const QString& path);
    /// Writes a whole run (an import) atomically: to a temporary file, renamed when complete.
    static Result<void> write(const QString& path, const RunData& run, const Progress& progress = {});
};

/// Appends to a run file as it is recorded (one thread: the recorder's worker).
class RunWriter
{
    Q_DECLARE_TR_FUNCTIONS(RunWriter)
public:
    RunWriter();
    ~RunWriter();
    RunWriter(const RunWriter&) = delete;
    RunWriter& operator=(const RunWriter&) = delete;

    /// Creates a new run file; refuses to overwrite one.
    Result<void> create(const QString& path, const RunInfo& info);
    /// Opens a run file made by create() to append to it (on another thread than the one that created it).
    Result<void> open(const QString& path);
    /// Appends events in one transaction (committed before it returns).
    Result<void> append(const std::vector<StampEvent>& stamps, const std::vector<LatencyValue>& latencies,
                        qint64 drainedNs);
    /// Writes watch events in one transaction: a new one is added, one seen before (same subject
    /// and start) gets its end. So an event is in the file from its start, and a killed recorder
    /// leaves it open rather than lost.
    Result<void> putEvents(const std::vector<RecordedEvent>& events);
    /// Writes the hosts' clocks as measured (each with the drain tick after which it held).
    Result<void> putClocks(const std::vector<RecordedClock>& clocks);
    Result<void> setMeta(const QString& key, const QVariant& value);
    /// Records the stop time and makes the file self-contained.
    Result<void> finish(qint64 stoppedNs);
    qint64 stampCount() const { return m_stamps; }

private:
    struct Private;
    std::unique_ptr<Private> d;
    qint64 m_stamps = 0;
};
