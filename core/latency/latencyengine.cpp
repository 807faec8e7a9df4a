// SPDX-License-Identifier: MIT
#include "latencyengine.h"

#include <limits>

using namespace Qt::StringLiterals;

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
    rebuildSeries();
}

int LatencyEngine::addSeries(SeriesInfo info, double msPerUnit)
{
    const int index = int(m_series.size());
    m_byId.insert(info.id, index);
    m_info.push_back(std::move(info));
    m_series.push_back(std::make_unique<LatencySeries>(msPerUnit));
    m_series.back()->setWindow(m_window);
    return index;
}

void LatencyEngine::rebuildSeries()
{
    // Externals survive a pipeline change: they do not depend on it.
    std::vector<SeriesInfo> externalInfo;
    std::vector<std::unique_ptr<LatencySeries>> externalSeries;
    for (std::size_t i = 0; i < m_info.size(); ++i) {
        if (m_info[i].kind == Kind::External) {
            externalInfo.push_back(m_info[i]);
            externalSeries.push_back(std::move(m_series[i]));
        }
    }
    m_info.clear();
    m_series.clear();
    m_byId.clear();
    m_total = m_roundTrip = m_oneWay = m_clockOffset = m_there = m_back = -1;
    m_crossings.clear();
    m_sameHost.clear();
    m_offsetStages = {-1, -1};

    const Pipeline& p = m_pipeline;
    for (int s = 0; s < p.stageCount(); ++s) {
        SeriesInfo info;
        info.id = SeriesId::ofStage(s).toString();
        info.label = p.stageLabel(s);
        info.detail = p.topics()[s] + u" →\n"_s + p.topics()[s + 1];
        info.kind = Kind::Stage;
        info.stage = s;
        info.crossing = p.isCrossing(s);
        info.hostFrom = p.host(s);
        info.hostTo = p.host(s + 1);
        if (info.crossing)
            m_crossings.push_back(s);
        else if (!info.hostFrom.isEmpty() && info.hostFrom == info.hostTo)
            m_sameHost.push_back(s);
        addSeries(std::move(info), 1e-6);
    }
    if (p.stageCount() > 0) {
        SeriesInfo total;
        total.id = SeriesId::ofKind(Kind::Total).toString();
        total.label = tr("total");
        total.kind = Kind::Total;
        total.hostFrom = p.host(0);
        total.hostTo = p.host(p.topicCount() - 1);
        m_total = addSeries(std::move(total), 1e-6);
    }
    if (!m_crossings.empty()) {
        SeriesInfo rt;
        rt.id = SeriesId::ofKind(Kind::RoundTrip).toString();
        rt.label = tr("communication, round trip");
        rt.kind = Kind::RoundTrip;
        m_roundTrip = addSeries(std::move(rt), 1e-6);
        SeriesInfo ow;
        ow.id = SeriesId::ofKind(Kind::OneWay).toString();
        ow.label = tr("communication, one way (half the round trip)");
        ow.kind = Kind::OneWay;
        m_oneWay = addSeries(std::move(ow), 0.5e-6);
        if (const auto pair = p.outAndReturnCrossings())
            addLegSeries(*pair);
    }
    for (std::size_t i = 0; i < externalInfo.size(); ++i) {
        const int index = int(m_series.size());
        m_byId.insert(externalInfo[i].id, index);
        m_info.push_back(std::move(externalInfo[i]));
        m_series.push_back(std::move(externalSeries[i]));
        m_series.back()->setWindow(m_window);
    }
    ++m_revision;
    ++m_layoutRevision;
}

void LatencyEngine::addLegSeries(std::pair<int, int> legs)
{
    const Pipeline& p = m_pipeline;
    m_offsetStages = legs;
    const QString home = p.host(legs.first);
    const QString away = p.host(legs.first + 1);
    if (p.oneClock()) {
        // One clock: each leg is its own one-way latency, however unequal the two are.
        const auto leg = [this](Kind kind, const QString& label, const QString& from, const QString& to) {
            SeriesInfo info;
            info.id = SeriesId::ofKind(kind).toString();
            info.label = label;
            info.kind = kind;
            info.hostFrom = from;
            info.hostTo = to;
            return addSeries(std::move(info), 1e-6);
        };
        m_there = leg(Kind::There, tr("communication, there (%1 → %2)").arg(home, away), home, away);
        m_back = leg(Kind::Back, tr("communication, back (%1 → %2)").arg(away, home), away, home);
        return;
    }
    SeriesInfo off;
    off.id = SeriesId::ofKind(Kind::ClockOffset).toString();
    off.hostFrom = home;
    off.hostTo = away;
    off.label = tr("clock offset (%1 ahead of %2)").arg(away, home);
    off.kind = Kind::ClockOffset;
    m_clockOffset = addSeries(std::move(off), 0.5e-6);
}

std::optional<std::pair<double, double>> LatencyEngine::clockOffsetBoundsMs() const
{
    if (m_clockOffset < 0)
        return std::nullopt;
    const LatencyStats out = m_series[std::size_t(m_offsetStages.first)]->stats();
    const LatencyStats back = m_series[std::size_t(m_offsetStages.second)]->stats();
    if (out.count == 0 || back.count == 0)
        return std::nullopt;
    return std::make_pair(-back.min, out.min);
}

void LatencyEngine::setWindow(qint64 samples)
{
    m_window = std::max<qint64>(0, samples);
    for (auto& s : m_series)
        s->setWindow(m_window);
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
    const QString id = SeriesId::external(value.series).toString();
    int index = m_byId.value(id, -1);
    if (index < 0) {
        SeriesInfo info;
        info.id = id;
        info.label = value.series;
        info.kind = Kind::External;
        index = addSeries(std::move(info), 1e-6);
        ++m_layoutRevision;
    }
    m_series[std::size_t(index)]->append(value.valueNs);
    ++m_revision;
}

void LatencyEngine::addSample(const std::vector<qint64>& times)
{
    if (int(times.size()) != m_pipeline.topicCount())
        return;
    takeSample(times);
}

namespace {
/// Differences of stamps in 128 bits, saturated to 64: sources keep stamps to ROS times, whose
/// differences fit, but a sum over many stages of extreme (accepted) values would not.
qint64 saturated(LatencyInt128 v)
{
    return v > std::numeric_limits<qint64>::max() ? std::numeric_limits<qint64>::max()
        : v < std::numeric_limits<qint64>::min()  ? std::numeric_limits<qint64>::min()
                                                  : qint64(v);
}

LatencyInt128 span(const std::vector<qint64>& t, std::size_t from, std::size_t to)
{
    return LatencyInt128(t[to]) - t[from];
}
} // namespace

void LatencyEngine::takeSample(const std::vector<qint64>& t)
{
    const int stages = m_pipeline.stageCount();
    if (stages == 0)
        return;
    for (int s = 0; s < stages; ++s)
        m_series[std::size_t(s)]->append(saturated(span(t, std::size_t(s), std::size_t(s) + 1)));
    m_series[std::size_t(m_total)]->append(saturated(span(t, 0, t.size() - 1)));
    m_timeline.add(t.front(), saturated(span(t, 0, t.size() - 1)));
    if (m_roundTrip >= 0) {
        // As in the paper: total minus every stage that stays on one host.
        LatencyInt128 rt = span(t, 0, t.size() - 1);
        for (int s : m_sameHost)
            rt -= span(t, std::size_t(s), std::size_t(s) + 1);
        m_series[std::size_t(m_roundTrip)]->append(saturated(rt));
        m_series[std::size_t(m_oneWay)]->append(saturated(rt)); // read at half scale
    }
    if (m_clockOffset >= 0) {
        const auto [out, back] = m_offsetStages;
        const LatencyInt128 outbound = span(t, std::size_t(out), std::size_t(out) + 1);
        const LatencyInt128 inbound = span(t, std::size_t(back), std::size_t(back) + 1);
        m_series[std::size_t(m_clockOffset)]->append(saturated(outbound - inbound)); // read at half scale
    }
    if (m_there >= 0) {
        const auto [out, back] = m_offsetStages;
        m_series[std::size_t(m_there)]->append(saturated(span(t, std::size_t(out), std::size_t(out) + 1)));
        m_series[std::size_t(m_back)]->append(saturated(span(t, std::size_t(back), std::size_t(back) + 1)));
    }
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

void LatencyEngine::reset()
{
    m_joiner.reset(m_pipeline.topicCount());
    for (auto& s : m_series)
        s->clear();
    m_timeline.clear();
    m_samples = 0;
    ++m_revision;
}
