// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencyseries.h"
#include "latency/latencytimeline.h"
#include "latency/pipeline.h"
#include "latency/pipelineseries.h"
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

/// The measurement engine: joins stamps into samples (SampleJoiner) and keeps one latency series
/// per stage, the total, the derived communication figures, and any single-stage series measured
/// elsewhere (PipelineSeries).
///
/// Pure logic (no ROS, no MQTT, no widgets): sources hand it plain events on the GUI thread, the
/// report command hands it samples from files. Per sample it does O(stages · log window) work.
class LatencyEngine final
{
public:
    using Kind = SeriesKind;
    using SeriesInfo = PipelineSeries::Info;
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

    /// Every series, with the communication figures and the clock offset's bounds; an EcdfSource.
    /// A host's measured clock (PipelineSeries::setClock): later samples' crossings are corrected.
    void setClock(const ClockEstimate& estimate);
    /// Forgets the clocks; setPipeline() after it makes no corrected series until one comes.
    void clearClocks() { m_series.clearClocks(); }
    const PipelineSeries& pipelineSeries() const { return m_series; }
    int seriesCount() const { return m_series.count(); }
    const SeriesInfo& info(int series) const { return m_series.info(series); }
    const LatencySeries& series(int series) const { return m_series.series(series); }
    int indexOf(const QString& id) const { return m_series.indexOf(id); }
    int totalSeries() const { return m_series.totalSeries(); }
    /// The total latency per second of the samples' first stamps (the Measure page's time plot).
    const LatencyTimeline& timeline() const { return m_timeline; }

    const SampleJoiner::Counters& counters() const { return m_joiner.counters(); }
    int pending() const { return m_joiner.pending(); }
    const SampleJoiner& joiner() const { return m_joiner; }
    /// Samples that left the statistics since the last reset (counted by addSample too).
    qint64 samples() const { return m_samples; }
    /// Changes whenever a value arrives or the series change (redraw only when it moved).
    quint64 revision() const { return m_revision; }

private:
    void takeSample(const std::vector<qint64>& times);

    Pipeline m_pipeline;
    qint64 m_window = Pipeline::kDefaultWindow;
    SampleJoiner m_joiner;
    PipelineSeries m_series;
    std::vector<qint64> m_times; ///< scratch for the joiner
    SampleListener m_listener;
    LatencyTimeline m_timeline;
    qint64 m_samples = 0;
    quint64 m_revision = 0;
};
