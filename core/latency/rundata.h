// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockestimate.h"
#include "latency/pipeline.h"

#include <functional>
#include <QJsonArray>
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
    QString rosMaster; ///< empty when no stamp came from a ROS 1 master
    /// The ROS 2 domain stamps came from ("domain 7, this host only"), empty when none did.
    QString ros2Domain;
    QString broker;
    QString source; ///< for imports: the file it came from
    Pipeline pipeline;
    qint64 window = Pipeline::kDefaultWindow; ///< the live page's window while recording
    qint64 timeoutNs = 5'000'000'000LL;
    QString bridgeConfigPath;
    QByteArray bridgeConfig;
    /// A cell of an experiment: the plan's name, the cell's id and its levels (factor, level).
    QString experiment;
    QString cell;
    QList<std::pair<QString, QString>> factors;
    /// Levels as JSON, [["qos", "1"], ["payload", "50%"]], as run files and experiments write them.
    static QJsonArray levelsJson(const QList<std::pair<QString, QString>>& levels);
    /// Back from JSON: what is not a pair of strings is left out; at most `maxLevels`, each text cut
    /// at `maxText` characters.
    static QList<std::pair<QString, QString>> levelsFromJson(const QJsonArray& json, qsizetype maxLevels,
                                                             qsizetype maxText);

    /// Fills `host` and `version` with this machine and this Bridgescope, where they are empty.
    void describeThisMachine();
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

/// A host's clock as measured while recording (the clock service's estimate), and the drain tick
/// after which it held: a replay corrects the samples of later ticks by it, as live did.
struct RecordedClock
{
    ClockEstimate estimate;
    qint64 drainedNs = 0;
};

/// A watch event as recorded: a link's or a bridge's state change (WatchEvent in core/watch).
struct RecordedEvent
{
    QString subject; ///< a link id ("config|ros2mqtt|/ros/topic|mqtt/topic") or "bridge:NAME"
    QString level; ///< "warning" or "alert"
    QStringList reasons; ///< "stall", "source_stopped", "loss", "rate", "latency", "bridge_down", ...
    QString detail; ///< a sentence for people
    qint64 startNs = 0;
    qint64 endNs = 0; ///< 0: still open when the recording stopped
    QByteArray json; ///< the whole event as a JSON object, with its figures at start and end

    /// In long double: INT64_MIN to INT64_MAX overflowed a difference of qint64 (and showed -0.0 s).
    double durationSeconds() const
    {
        return endNs > startNs ? double((static_cast<long double>(endNs) - startNs) / 1e9L) : 0;
    }
};

/// A run in memory: its info and every raw event, in the order they arrived.
struct RunData
{
    RunInfo info;
    QStringList topics;
    std::vector<RecordedStamp> stamps;
    QStringList series;
    std::vector<RecordedLatency> latencies;
    std::vector<RecordedEvent> events; ///< by start time
    std::vector<RecordedClock> clocks; ///< by drain tick; none in a run recorded without the clock service
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
