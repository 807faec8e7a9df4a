// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "experiment/planhosts.h"

#include <optional>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

/// Delay, jitter, bandwidth and loss between a bridge and the broker, emulated by a relay.
struct LinkProfile
{
    double delayMs = 0; ///< one way, each direction
    double jitterMs = 0; ///< standard deviation of the delay
    double bandwidthMbit = 0; ///< per direction; 0: unlimited
    double lossPercent = 0; ///< of the relay's chunks, each "lost" one waits a retransmission timeout
    /// Added to the way there only (the vehicle's bridge to the broker): a path whose two ways differ,
    /// which half the round trip cannot see (`there_extra_ms`).
    double thereExtraMs = 0;
    bool isNone() const
    {
        return delayMs == 0 && jitterMs == 0 && bandwidthMbit == 0 && lossPercent == 0 && thereExtraMs == 0;
    }
};

/// Which bridge carries the cell's data: ours, or a command that starts the lab's own.
struct BridgeImplementation
{
    QString name = QStringLiteral("reference");
    /// Empty: the reference bridge. Otherwise a shell command with {config}, {name}, {broker_host},
    /// {broker_port}, {ros_master} and {ros_domain} replaced (each shell-quoted), run once per
    /// bridge; with `ros: 2` {config} is a ROS 2 params file whose node is {name}.
    QString command;
    /// What the command's bridge announces, as its `bridges:` entry says: "once", "every_message",
    /// or empty when the plan does not say (a cell then cannot ask it for `announce: once`).
    QString announce;
};

/// Everything a cell sets: the levels of every factor, defaults filled in.
struct CellSettings
{
    int payloadBytes = 180'000; ///< the vehicle's point cloud
    double rateHz = 10;
    int qos = 0;
    bool tls = false;
    bool announceEveryMessage = false; ///< the type announcement before every message (mqtt_client 2.2.1)
    int queueSize = 1;
    BridgeImplementation bridge;
    QString linkName = QStringLiteral("none");
    LinkProfile link;
    double detectionMs = 40;
    /// Why the cell cannot run as its levels ask (a level its bridge cannot honour); empty: it can.
    /// Such a cell fails with this reason and is pooled nowhere.
    QString problem;
};

/// One cell of the matrix: a combination of levels, and which repetition of it.
struct ExperimentCell
{
    int index = 0; ///< 0-based, in the order cells run
    int repetition = 0; ///< 0-based
    QList<std::pair<QString, QString>> levels; ///< (factor, level as written in the plan), in factor order
    CellSettings settings;
    /// Stable and file-name safe: "003-qos-1-payload-50pct" (+ "-r2" for a repetition).
    QString id() const;
    QString label() const; ///< "qos 1, payload 50%"
};

/// What the plan asks of the optional throughput step (ThroughputStep): per payload size, a rate
/// sweep through the bridges.
struct ThroughputSettings
{
    QList<double> ratesHz;
    double secondsPerRate = 10;
};

/// An experiment plan: factors crossed (or cells listed), samples per cell, servers, pipeline.
/// Read from YAML (docs/formats.md, "Experiment plan"); every error names its line.
class ExperimentPlan
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentPlan)
public:
    static constexpr int kMaxCells = 10'000;
    static constexpr int kScanBytes = 180'000; ///< the paper's VelodyneScan, "100%"
    static constexpr int kPointCloud2Bytes = 1'080'000; ///< the same scan as PointCloud2
    static constexpr int kMaxPayloadBytes = 64 * 1024 * 1024;

    QString name;
    int samples = 600; ///< complete samples recorded per cell
    int warmup = 20; ///< samples that complete before recording starts, not kept
    int repetitions = 1;
    double cellTimeoutS = 0; ///< 0: from the samples and rate (3x, plus a minute)
    QString brokerUrl; ///< empty: a private mosquitto per cell
    QString rosMasterUri; ///< empty: a private rosmaster per cell (ROS 1)
    /// 1: ROS 1 nodes and bridges around a rosmaster; 2: DDS nodes and ROS 2 bridges, every cell
    /// on a fresh private domain (`ros: 2`).
    int ros = 1;
    QString pipelinePath; ///< empty: the paper's pipeline of the lab
    QStringList factors; ///< names of the factors that vary, in the plan's order
    QList<ExperimentCell> cells;
    std::optional<ThroughputSettings> throughput;
    /// The hosts the vehicle's and the cloud's side run on over ssh (`hosts:`, `program:`); none:
    /// every side runs here.
    PlanHosts hosts;

    /// Reads a plan from YAML (bounded by YamlLimits); relative paths in it are taken from
    /// `baseDir`. The error is located at the value it is about ("line 4, column 9: …").
    static Result<ExperimentPlan> read(const QByteArray& yaml, const QString& baseDir);
    /// Reads a plan file; `text` gets its bytes (a copy of the plan is kept with its runs). A plan
    /// without a name keeps it empty: the caller names it (after the file, or the folder).
    static Result<ExperimentPlan> readFile(const QString& path, QByteArray* text = nullptr);

    /// The factors a plan may vary, with what their levels are.
    static QStringList knownFactors();
    /// Seconds a cell is expected to take: start, warm-up, samples, stop.
    double expectedSeconds(const ExperimentCell& cell) const;
    double timeoutSeconds(const ExperimentCell& cell) const;
    /// A payload level: bytes ("20000"), percent of the scan ("25%"), "scan" or "pointcloud2".
    static std::optional<int> payloadBytes(const QString& level);
    /// "45 s", "12 min", "3 h 20 min": how long cells take, in progress and estimates.
    static QString durationText(double seconds);
};
