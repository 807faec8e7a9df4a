// SPDX-License-Identifier: MIT
#include "latencyengine.h"

LatencyEngine::LatencyEngine(const Pipeline& pipeline)
{
    setPipeline(pipeline);
}

LatencyEngine::~LatencyEngine() = default;
LatencyEngine::LatencyEngine(LatencyEngine&&) noexcept = default;
LatencyEngine& LatencyEngine::operator=(LatencyEngine&&) noexcept = default;

void LatencyEngine::setPipeline(const Pipeline& pipeline)
{
    m_pipeline = pipeline;
    m_window = pipeline.window();
    m_joiner.reset(pipeline.topicCount());
    m_samples = 0;
    m_timeline.clear();
    m_series.rebuild(m_pipeline, m_window);
    ++m_revision;
}

void LatencyEngine::setWindow(qint64 samples)
{
    m_window = std::max<qint64>(0, samples);
    m_series.setWindow(m_window);
    ++m_revision;
}

void LatencyEngine::ingest(const StampEvent& event)
{
    ingest(m_pipeline.indexOf(event.topic), event.sampleNs, event.timeNs, event.receivedNs);
}

void LatencyEngine::ingest(const std::vector<StampEvent>& events)
{
    for (const StampEvent& e : events)
        ingest(e);
}

void LatencyEngine::ingest(int topicIndex, qint64 sampleNs, qint64 timeNs, qint64 receivedNs)
{
    if (m_joiner.add(topicIndex, sampleNs, timeNs, receivedNs, m_times)) {
        takeSample(m_times);
        if (m_listener)
            m_listener(sampleNs, m_times);
    }
}

void LatencyEngine::ingest(const LatencyValue& value)
{
    m_series.series(m_series.external(value.series, m_window)).append(value.valueNs);
    ++m_revision;
}

void LatencyEngine::addSample(const std::vector<qint64>& times)
{
    if (int(times.size()) != m_pipeline.topicCount())
        return;
    takeSample(times);
}

void LatencyEngine::takeSample(const std::vector<qint64>& t)
{
    if (m_pipeline.stageCount() == 0)
        return;
    m_timeline.add(t.front(), m_series.add(t));
    ++m_samples;
    ++m_revision;
}

void LatencyEngine::expire(qint64 nowNs)
{
    const quint64 before = m_joiner.counters().dropped();
    m_joiner.expire(nowNs);
    if (m_joiner.counters().dropped() != before)
        ++m_revision;
}

void LatencyEngine::setClock(const ClockEstimate& estimate)
{
    const quint64 layout = m_series.layoutRevision();
    m_series.setClock(estimate);
    if (m_series.layoutRevision() != layout)
        ++m_revision;
}

void LatencyEngine::reset()
{
    m_joiner.reset(m_pipeline.topicCount());
    m_series.clearValues();
    m_timeline.clear();
    m_samples = 0;
    ++m_revision;
}
