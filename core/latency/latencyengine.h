// SPDX-License-Identifier: MIT
#pragma once

#include "latency/ecdfsource.h"
#include "latency/latencyseries.h"
#include "latency/latencytimeline.h"
#include "latency/pipeline.h"
#include "latency/samplejoiner.h"
#include "latency/seriesid.h"
#include "wire/stampevent.h"

#include <functional>
#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <vector>

/// The measurement engine: joins stamps into samples and keeps one latency series per stage, the
/// total, the derived communication figures, and any single-stage series measured elsewhere.
///
/// Pure logic (no ROS, no MQTT, no widgets): sources hand it plain events on the GUI thread, the
/// report command hands it samples from files. Per sample it does O(stages · log window) work.
class LatencyEngine final : public EcdfSource
{
    Q_DECLARE_TR_FUNCTIONS(LatencyEngine)
public:
    using Kind = SeriesKind;
    struct SeriesInfo
    {
        QString id; ///< SeriesId::toString(), stable
        QString label;
        QString detail; ///< stages: both topics in full
        Kind kind = Kind::Stage;
        int stage = -1;
        bool crossing = false;
        QString hostFrom;
        QString hostTo;
    };
    /// Called with each complete sample's stamps in pipeline order (for recording).
    using SampleListener = std::function<void(qint64 sampleNs, const std::vector<qint64>& times)>;

    explicit LatencyEngine(const Pipeline& pipeline = {});
    ~LatencyEngine();
    LatencyEngine(LatencyEngine&&) noexcept;
    LatencyEngine& operator=(LatencyEngine&&) noexcept;

    /// Starts over with another pipeline (externals are kept).
    void setPipeline(const Pipeline& pipeline);
    const Pipeline& pipeline() const { return m_pipeline; }
    /// Last N samples, or 0 for the whole run.
    void setWindow(qint64 samples);
    qint64 window() const { return m_window; }
    void setTimeoutNs(qint64 ns) { m_joiner.setTimeoutNs(ns); }
    qint64 timeoutNs() const { return m_joiner.timeoutNs(); }
    void setMaxPending(int samples) { m_joiner.setMaxPending(samples); }
    void setSampleListener(SampleListener listener) { m_listener = std::move(listener); }

    void ingest(const StampEvent& event);
    void ingest(const std::vector<StampEvent>& events);
    /// The fast path for a source that resolved the topic already (indexOf()).
    void ingest(int topicIndex, qint64 sampleNs, qint64 timeNs, qint64 receivedNs);
    void ingest(const LatencyValue& value);
    /// A sample joined elsewhere (a CSV row): its stamps in pipeline order.
    void addSample(const std::vector<qint64>& times);
    void expire(qint64 nowNs);
    /// Forgets every value and counter; keeps the pipeline and the series.
    void reset();

    int seriesCount() const { return int(m_series.size()); }
    const SeriesInfo& info(int series) const { return m_info[std::size_t(series)]; }
    const LatencySeries& series(int series) const { return *m_series[std::size_t(series)]; }
    int indexOf(const QString& id) const { return m_byId.value(id, -1); }
    int stageSeries(int stage) const { return stage; }
    int totalSeries() const { return m_total; }
    int roundTripSeries() const { return m_roundTrip; }
    int oneWaySeries() const { return m_oneWay; }
    int clockOffsetSeries() const { return m_clockOffset; }
    /// The total latency per second of the samples' first stamps (the Measure page's time plot).
    const LatencyTimeline& timeline() const { return m_timeline; }
    /// With one clock (Pipeline::oneClock()) and an outbound and a return crossing: each crossing
    /// as its own one-way latency; -1 otherwise (then there may be a clock offset instead).
    int thereSeries() const { return m_there; }
    int backSeries() const { return m_back; }
    /// Where the clock offset can lie, in ms, over the window: each sample bounds it by
    /// [-(return leg), outbound leg] (the legs take no negative time), so the interval is
    /// [-min return, min outbound]. An offset and a difference of the legs cannot be told apart
    /// inside it. nullopt without a clock offset series or samples.
    std::optional<std::pair<double, double>> clockOffsetBoundsMs() const;

    const SampleJoiner::Counters& counters() const { return m_joiner.counters(); }
    int pending() const { return m_joiner.pending(); }
    const SampleJoiner& joiner() const { return m_joiner; }
    /// Samples that left the statistics since the last reset (counted by addSample too).
    qint64 samples() const { return m_samples; }
    /// Changes whenever a value arrives or the series change (redraw only when it moved).
    quint64 revision() const { return m_revision; }
    quint64 layoutRevision() const { return m_layoutRevision; }

    int ecdfIndex(const QString& id) const override { return indexOf(id); }
    const LatencySeries& ecdfSeries(int index) const override { return series(index); }
    QString ecdfLabel(int index) const override { return info(index).label; }
    quint64 ecdfLayoutRevision() const override { return m_layoutRevision; }

private:
    void rebuildSeries();
    int addSeries(SeriesInfo info, double msPerUnit);
    /// The figures of an outbound and a return crossing: there and back (one clock) or the offset.
    void addLegSeries(std::pair<int, int> legs);
    void takeSample(const std::vector<qint64>& times);

    Pipeline m_pipeline;
    qint64 m_window = Pipeline::kDefaultWindow;
    SampleJoiner m_joiner;
    std::vector<SeriesInfo> m_info;
    std::vector<std::unique_ptr<LatencySeries>> m_series;
    QHash<QString, int> m_byId;
    int m_total = -1;
    int m_roundTrip = -1;
    int m_oneWay = -1;
    int m_clockOffset = -1;
    int m_there = -1;
    int m_back = -1;
    std::vector<int> m_crossings;
    std::vector<int> m_sameHost;
    std::pair<int, int> m_offsetStages {-1, -1};
    std::vector<qint64> m_times; ///< scratch for the joiner
    SampleListener m_listener;
    LatencyTimeline m_timeline;
    qint64 m_samples = 0;
    quint64 m_revision = 0;
    quint64 m_layoutRevision = 0;
};
