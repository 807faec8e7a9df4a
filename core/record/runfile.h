// SPDX-License-Identifier: MIT
#pragma once

#include "latency/pipeline.h"
#include "latency/stampevent.h"

#include <functional>
#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QStringList>
#include <vector>

class LatencyEngine;

/// What a run says about itself.
struct RunInfo
{
    QString name;
    QString notes;
    qint64 startedNs = 0;
    qint64 stoppedNs = 0; ///< 0: never stopped (recording, or the recorder died)
    QString host; ///< machine name and OS
    QString version; ///< Bridgescope and Qt versions
    QString rosMaster;
    QString broker;
    QString source; ///< for imports: the file it came from
    Pipeline pipeline;
    qint64 window = Pipeline::kDefaultWindow; ///< the live page's window while recording
    qint64 timeoutNs = 5'000'000'000LL;
    QString bridgeConfigPath;
    QByteArray bridgeConfig;
};

/// One stamp as recorded: which topic, which sample, when it was stamped, when Bridgescope got it,
/// and the drain tick that handed it to the engine (so a replay joins exactly as live did).
struct RecordedStamp
{
    int topic = 0; ///< index into RunData::topics
    qint64 sampleNs = 0;
    qint64 timeNs = 0;
    qint64 receivedNs = 0;
    qint64 drainedNs = 0;
};

struct RecordedLatency
{
    int series = 0; ///< index into RunData::series
    qint64 valueNs = 0;
    qint64 receivedNs = 0;
    qint64 drainedNs = 0;
};

/// A run in memory: its info and every raw event, in the order they arrived.
struct RunData
{
    RunInfo info;
    QStringList topics;
    std::vector<RecordedStamp> stamps;
    QStringList series;
    std::vector<RecordedLatency> latencies;
    qint64 droppedBeforeImport = 0; ///< e.g. incomplete rows of a suite CSV

    /// Feeds every event to `engine` (set to the run's pipeline before) tick by tick, as live.
    /// `keepGoing` is polled now and then; false from it stops (and replay() returns false).
    bool replay(LatencyEngine& engine, const std::function<bool()>& keepGoing = {}) const;
    /// A file with complete samples only (suite CSV): one stamp per cell, joined at once.
    /// `sharedFirstStamps`: rows whose first stamp an earlier row has too; each still counts as
    /// a sample (keyed by the next free value), but cannot be joined with another file's row.
    static RunData fromSamples(const Pipeline& pipeline, const std::vector<std::vector<qint64>>& samples,
                               qint64* sharedFirstStamps = nullptr);
};

/// Progress of long work: called with 0..100; return false to cancel.
using Progress = std::function<bool(int percent)>;

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

    static std::optional<RunData> read(const QString& path, QString* error = nullptr,
                                       const Progress& progress = {});
    /// Writes a whole run (an import) atomically: to a temporary file, renamed when complete.
    static bool write(const QString& path, const RunData& run, QString* error = nullptr,
                      const Progress& progress = {});
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
    bool create(const QString& path, const RunInfo& info, QString* error = nullptr);
    /// Opens a run file made by create() to append to it (on another thread than the one that created it).
    bool open(const QString& path, QString* error = nullptr);
    /// Appends events in one transaction (committed before it returns).
    bool append(const std::vector<StampEvent>& stamps, const std::vector<LatencyValue>& latencies,
                qint64 drainedNs, QString* error = nullptr);
    bool setMeta(const QString& key, const QVariant& value, QString* error = nullptr);
    /// Records the stop time and makes the file self-contained.
    bool finish(qint64 stoppedNs, QString* error = nullptr);
    qint64 stampCount() const { return m_stamps; }

private:
    struct Private;
    std::unique_ptr<Private> d;
    qint64 m_stamps = 0;
};
