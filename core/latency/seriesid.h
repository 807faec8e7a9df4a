// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QString>

/// What a latency series measures.
enum class SeriesKind {
    Stage, ///< stamp i to stamp i+1
    Total, ///< first stamp to last
    RoundTrip, ///< total minus every same-host stage: the sum of the crossings
    OneWay, ///< half the round trip (the paper's "average of both ways")
    ClockOffset, ///< ((c_in - v_out) - (v_in - c_out)) / 2: the far host's clock ahead of ours
    There, ///< one clock: the outbound crossing, its own one-way latency
    Back, ///< one clock: the return crossing
    External, ///< a latency measured by somebody else (mqtt_client's ~/latencies, stamped MQTT)
    Corrected, ///< a crossing stage corrected by the hosts' measured clocks: its one-way latency
    Asymmetry, ///< measured clocks: (there − back) / 2, what half the round trip misattributes to each way
};

/// The stable id of a latency series, the key by which charts, tables, settings and reports name
/// it. Its text ("stage:3", "total", "round_trip", "one_way", "clock_offset", "there", "back",
/// "ext:<name>", "corrected:3", "asymmetry") is built and read only here.
struct SeriesId
{
    SeriesKind kind = SeriesKind::Total;
    int stage = -1; ///< Stage, Corrected: the stage's index in the pipeline
    QString name; ///< External: the series' name

    static SeriesId ofStage(int index) { return {SeriesKind::Stage, index, {}}; }
    static SeriesId ofCorrected(int stage) { return {SeriesKind::Corrected, stage, {}}; }
    static SeriesId ofKind(SeriesKind kind) { return {kind, -1, {}}; } ///< not Stage, Corrected or External
    static SeriesId external(const QString& name) { return {SeriesKind::External, -1, name}; }
    /// The name of the external series of a link's observed hop latency (issue 45: both ends of a
    /// bridge matched by content, no stamps): "observed SOURCE → DESTINATION".
    static QString observedName(const QString& source, const QString& destination);
    /// Whether the external series `name` is an observed hop latency (observedName()).
    static bool isObserved(const QString& name);

    QString toString() const;
    /// nullopt when `text` is not an id.
    static std::optional<SeriesId> parse(const QString& text);

    bool operator==(const SeriesId& o) const { return kind == o.kind && stage == o.stage && name == o.name; }
};
