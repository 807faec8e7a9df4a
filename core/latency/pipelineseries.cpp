// SPDX-License-Identifier: MIT
#include "latency/pipelineseries.h"

#include "latency/pipeline.h"

#include <limits>

using namespace Qt::StringLiterals;

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

PipelineSeries::PipelineSeries() = default;
PipelineSeries::~PipelineSeries() = default;
PipelineSeries::PipelineSeries(PipelineSeries&&) noexcept = default;
PipelineSeries& PipelineSeries::operator=(PipelineSeries&&) noexcept = default;

int PipelineSeries::addSeries(Info info, double msPerUnit, qint64 window)
{
    const int index = int(m_series.size());
    m_byId.insert(info.id, index);
    m_info.push_back(std::move(info));
    m_series.push_back(std::make_unique<LatencySeries>(msPerUnit));
    m_series.back()->setWindow(window);
    return index;
}

void PipelineSeries::rebuild(const Pipeline& p, qint64 window)
{
    // Externals survive a pipeline change: they do not depend on it.
    std::vector<Info> externalInfo;
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
    m_sameHost.clear();
    m_offsetStages = {-1, -1};
    m_stages = p.stageCount();

    bool crossing = false;
    for (int s = 0; s < p.stageCount(); ++s) {
        Info info;
        info.id = SeriesId::ofStage(s).toString();
        info.label = p.stageLabel(s);
        info.detail = p.topics()[s] + u" →\n"_s + p.topics()[s + 1];
        info.kind = Kind::Stage;
        info.stage = s;
        info.crossing = p.isCrossing(s);
        info.hostFrom = p.host(s);
        info.hostTo = p.host(s + 1);
        if (info.crossing)
            crossing = true;
        else if (!info.hostFrom.isEmpty() && info.hostFrom == info.hostTo)
            m_sameHost.push_back(s);
        addSeries(std::move(info), 1e-6, window);
    }
    if (p.stageCount() > 0) {
        Info total;
        total.id = SeriesId::ofKind(Kind::Total).toString();
        total.label = tr("total");
        total.kind = Kind::Total;
        total.hostFrom = p.host(0);
        total.hostTo = p.host(p.topicCount() - 1);
        m_total = addSeries(std::move(total), 1e-6, window);
    }
    if (crossing) {
        Info rt;
        rt.id = SeriesId::ofKind(Kind::RoundTrip).toString();
        rt.label = tr("communication, round trip");
        rt.kind = Kind::RoundTrip;
        m_roundTrip = addSeries(std::move(rt), 1e-6, window);
        Info ow;
        ow.id = SeriesId::ofKind(Kind::OneWay).toString();
        ow.label = tr("communication, one way (half the round trip)");
        ow.kind = Kind::OneWay;
        m_oneWay = addSeries(std::move(ow), 0.5e-6, window);
        if (const auto pair = p.outAndReturnCrossings())
            addLegSeries(p, *pair, window);
    }
    for (std::size_t i = 0; i < externalInfo.size(); ++i) {
        const int index = int(m_series.size());
        m_byId.insert(externalInfo[i].id, index);
        m_info.push_back(std::move(externalInfo[i]));
        m_series.push_back(std::move(externalSeries[i]));
        m_series.back()->setWindow(window);
    }
    ++m_layoutRevision;
}

void PipelineSeries::addLegSeries(const Pipeline& p, std::pair<int, int> legs, qint64 window)
{
    m_offsetStages = legs;
    const QString home = p.host(legs.first);
    const QString away = p.host(legs.first + 1);
    if (p.oneClock()) {
        // One clock: each leg is its own one-way latency, however unequal the two are.
        const auto leg
            = [this, window](Kind kind, const QString& label, const QString& from, const QString& to) {
                  Info info;
                  info.id = SeriesId::ofKind(kind).toString();
                  info.label = label;
                  info.kind = kind;
                  info.hostFrom = from;
                  info.hostTo = to;
                  return addSeries(std::move(info), 1e-6, window);
              };
        m_there = leg(Kind::There, tr("communication, there (%1 → %2)").arg(home, away), home, away);
        m_back = leg(Kind::Back, tr("communication, back (%1 → %2)").arg(away, home), away, home);
        return;
    }
    Info off;
    off.id = SeriesId::ofKind(Kind::ClockOffset).toString();
    off.hostFrom = home;
    off.hostTo = away;
    off.label = tr("clock offset (%1 ahead of %2)").arg(away, home);
    off.kind = Kind::ClockOffset;
    m_clockOffset = addSeries(std::move(off), 0.5e-6, window);
}

int PipelineSeries::external(const QString& name, qint64 window)
{
    const QString id = SeriesId::external(name).toString();
    if (const int index = m_byId.value(id, -1); index >= 0)
        return index;
    Info info;
    info.id = id;
    info.label = name;
    info.kind = Kind::External;
    ++m_layoutRevision;
    return addSeries(std::move(info), 1e-6, window);
}

qint64 PipelineSeries::add(const std::vector<qint64>& t)
{
    for (int s = 0; s < m_stages; ++s)
        m_series[std::size_t(s)]->append(saturated(span(t, std::size_t(s), std::size_t(s) + 1)));
    const qint64 total = saturated(span(t, 0, t.size() - 1));
    m_series[std::size_t(m_total)]->append(total);
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
    return total;
}

void PipelineSeries::setWindow(qint64 samples)
{
    for (auto& s : m_series)
        s->setWindow(samples);
}

void PipelineSeries::clearValues()
{
    for (auto& s : m_series)
        s->clear();
}

std::optional<std::pair<double, double>> PipelineSeries::clockOffsetBoundsMs() const
{
    if (m_clockOffset < 0)
        return std::nullopt;
    const LatencyStats out = m_series[std::size_t(m_offsetStages.first)]->stats();
    const LatencyStats back = m_series[std::size_t(m_offsetStages.second)]->stats();
    if (out.count == 0 || back.count == 0)
        return std::nullopt;
    return std::make_pair(-back.min, out.min);
}
