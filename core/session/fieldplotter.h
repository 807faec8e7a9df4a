// SPDX-License-Identifier: MIT
#pragma once

#include "session/livesources.h"

#include <functional>
#include <memory>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QPointF>
#include <QStringList>

class MqttTopicTree;
class Ros2Participant;
class TopicTableModel;
class RosTypeRegistry;
struct SourceArrival;

/// A numeric field of an MQTT, ROS 1 or ROS 2 topic to plot over time.
struct PlotField
{
    enum class Source { Mqtt, Ros, Ros2 };
    Source source = Source::Mqtt;
    QString topic;
    QStringList path; ///< names and "[i]" indices (FieldPath)
    bool operator==(const PlotField& o) const
    {
        return source == o.source && topic == o.topic && path == o.path;
    }
};

/// What one plotted field collected.
struct PlotSeries
{
    PlotField field;
    QString label; ///< "topic: path"
    QList<QPointF> points; ///< (seconds since the plotter's origin, value), oldest first
    quint64 errors = 0; ///< messages in which the field was no number, or that did not decode
    QString lastError;
};

/// Values of chosen fields over time, from the live session's ticks (its drain, through Parts).
///
/// Nothing runs per network message: every plotted topic is watched on its graph's MessageSource
/// (MQTT, ROS 1 or ROS 2 alike), whose queue is taken once per drain. Work per tick is bounded: at
/// most kMessagesPerTick messages per topic are decoded (evenly spread over what came, the rest
/// counted as skipped) and at most kBytesPerTick bytes; larger payloads are errors. Points are kept
/// for the buffer's seconds, at most its points per field; the user sets both, and the points are
/// bounded by kMemoryBudgetBytes for all fields together.
class FieldPlotter : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMessagesPerTick = 50;
    static constexpr qint64 kBytesPerTick = 8 * 1024 * 1024;
    static constexpr qint64 kMaxPayloadBytes = 4 * 1024 * 1024;
    static constexpr int kMaxFields = 8;
    /// What the points of all fields may take: each point is a QPointF (16 bytes).
    static constexpr qint64 kMemoryBudgetBytes = 64 * 1024 * 1024;
    /// The most points a field keeps, so that kMaxFields of them stay within the budget.
    static constexpr int kMaxPointsPerField
        = int(kMemoryBudgetBytes / (kMaxFields * qint64(sizeof(QPointF))));
    static constexpr int kMinPointsPerField = 100;
    static constexpr int kDefaultPointsPerField = 100'000;
    static constexpr int kMinSeconds = 5;
    static constexpr int kMaxSeconds = 3600;
    static constexpr int kDefaultSeconds = 60;
    /// What a source keeps of a plotted topic between two ticks: enough for a few ticks at any
    /// rate (the tick decodes at most kMessagesPerTick of them); older ones are dropped and skipped.
    static constexpr std::size_t kQueued = 1000;
    static constexpr qint64 kQueuedBytes = 4 * kBytesPerTick;

    /// What the plotter reads: the sources of the plotted topics, and where their types are known.
    struct Parts
    {
        LiveSources sources;
        const MqttTopicTree* mqttTopics = nullptr; ///< the types mqtt_client announces
        const Ros2Participant* ros2 = nullptr; ///< the ROS 2 graph's types
        const TopicTableModel* rosTopics = nullptr; ///< the ROS 1 monitor's types and definitions
        /// The ROS 2 definitions ROS 2 samples decode with (they may change while plotting).
        std::function<const RosTypeRegistry&()> ros2Types;
    };

    explicit FieldPlotter(const Parts& parts, QObject* parent = nullptr);
    ~FieldPlotter() override;

    /// Starts plotting a field; false when it is plotted already or kMaxFields are.
    bool add(const PlotField& field);
    void remove(int index);
    void clear();
    const QList<PlotSeries>& series() const { return m_series; }
    /// Keeps the last `seconds` (kMinSeconds to kMaxSeconds) and at most `pointsPerField`
    /// (kMinPointsPerField to kMaxPointsPerField) of each field; values outside are clamped.
    /// Fewer points are dropped at once, fewer seconds at the next tick.
    void setBuffer(int seconds, int pointsPerField);
    int bufferSeconds() const { return m_seconds; }
    int bufferPoints() const { return m_points; }
    /// The time of the last update, in the points' seconds: where a live plot's time axis ends.
    double nowSeconds() const { return m_nowSeconds; }
    int indexOf(const PlotField& field) const;
    /// Messages of plotted topics that were not decoded to keep a tick's work bounded, or that
    /// their source dropped because more came between two ticks than it keeps (kQueued).
    quint64 skippedMessages() const { return m_skipped; }
    /// The most messages decoded for one topic in one tick (never above kMessagesPerTick).
    int mostDecodedInATick() const { return m_mostDecoded; }

signals:
    /// Once per tick in which points came or went, and a few times a second while none come.
    void updated();
    void fieldsChanged();

private:
    struct Private;
    struct Decoding;
    void onDrained(qint64 nowNs);
    void watch(PlotField::Source source, const QString& topic, bool on);
    /// How a topic's payloads decode: the ROS type announced (MQTT) or monitored (ROS), the ROS 2
    /// graph's type as CDR with the session's ROS 2 definitions (ROS 2), else JSON.
    Decoding decodingOf(PlotField::Source source, const QString& topic);
    /// Decodes a bounded share of one topic's messages into its fields' points; true when any came.
    bool plotTopic(PlotField::Source source, const QString& topic, const std::vector<SourceArrival>& messages);
    /// Keeps the buffer's seconds (up to `nowNs`; 0: all) and points per field; true when points went.
    bool trimWindow(qint64 nowNs);

    Parts m_parts; ///< m_parts.sources.alive() is false once the session went first
    std::unique_ptr<Private> d;
    QList<PlotSeries> m_series;
    quint64 m_skipped = 0;
    int m_mostDecoded = 0;
    int m_seconds = kDefaultSeconds;
    int m_points = kDefaultPointsPerField;
    double m_nowSeconds = 0;
    double m_shownNow = 0;
};
