// SPDX-License-Identifier: MIT
#include "latency/pipelineseries.h"

#include "latency/pipeline.h"

#include <algorithm>
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
    m_window = window;
    m_crossingHosts.assign(std::size_t(m_stages), {});
    m_corrected.assign(std::size_t(m_stages), -1);
    m_asymmetry = -1;
    m_uncertainty.clear();

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
        if (info.crossing) {
            crossing = true;
            if (!p.oneClock())
                m_crossingHosts[std::size_t(s)] = {info.hostFrom, info.hostTo};
        } else if (!info.hostFrom.isEmpty() && info.hostFrom == info.hostTo)
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
        addCorrectedSeries();
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

ClockEstimate PipelineSeries::clockBetween(const QString& from, const QString& to) const
{
    const auto a = m_clocks.constFind(from);
    const auto b = m_clocks.constFind(to);
    if (a == m_clocks.cend() || b == m_clocks.cend())
        return {};
    return ClockEstimate::between(*a, *b);
}

void PipelineSeries::setClock(const ClockEstimate& estimate)
{
    // The prober measures the hosts a pipeline names; a bound keeps a stream of names from growing it.
    constexpr qsizetype kMaxHosts = 256;
    if (!estimate.isValid() || estimate.host.isEmpty()
        || (m_clocks.size() >= kMaxHosts && !m_clocks.contains(estimate.host)))
        return;
    m_clocks.insert(estimate.host, estimate);
    if (addCorrectedSeries())
        ++m_layoutRevision;
}

int PipelineSeries::correctedSeries(int stage) const
{
    return stage >= 0 && std::size_t(stage) < m_corrected.size() ? m_corrected[std::size_t(stage)] : -1;
}

bool PipelineSeries::addCorrectedSeries()
{
    bool made = false;
    const auto withUncertainty = [this](Info info, double msPerUnit) {
        const int index = addSeries(std::move(info), msPerUnit, m_window);
        auto uncertainty = std::make_shared<LatencySeries>(msPerUnit);
        uncertainty->setWindow(m_window);
        m_uncertainty.insert(index, std::move(uncertainty));
        return index;
    };
    for (std::size_t s = 0; s < m_crossingHosts.size(); ++s) {
        const auto& [from, to] = m_crossingHosts[s];
        if (from.isEmpty() || m_corrected[s] >= 0 || !clockBetween(from, to).isValid())
            continue;
        Info info;
        info.id = SeriesId::ofCorrected(int(s)).toString();
        // Named by its hosts, as the paper's communication rows are; by its stage where two crossings
        // share the same hosts.
        const bool shared = std::count(m_crossingHosts.cbegin(), m_crossingHosts.cend(), m_crossingHosts[s]) > 1;
        info.label = shared ? tr("%1, clocks measured").arg(m_info[s].label)
                            : tr("communication, %1 → %2, clocks measured").arg(from, to);
        info.detail = m_info[s].detail;
        info.kind = Kind::Corrected;
        info.stage = int(s);
        info.hostFrom = from;
        info.hostTo = to;
        m_corrected[s] = withUncertainty(std::move(info), 1e-6);
        made = true;
    }
    const auto [out, back] = m_offsetStages;
    if (m_asymmetry < 0 && out >= 0 && correctedSeries(out) >= 0 && correctedSeries(back) >= 0) {
        Info info;
        info.id = SeriesId::ofKind(Kind::Asymmetry).toString();
        info.label = tr("path asymmetry (there − half the round trip)");
        info.kind = Kind::Asymmetry;
        info.hostFrom = m_crossingHosts[std::size_t(out)].first;
        info.hostTo = m_crossingHosts[std::size_t(out)].second;
        m_asymmetry = withUncertainty(std::move(info), 0.5e-6); // (there − back), read at half scale
        made = true;
    }
    return made;
}

void PipelineSeries::appendCorrected(const std::vector<qint64>& t)
{
    // The corrected value of crossing s and the uncertainty it carries; nullopt while unmeasured.
    const auto corrected = [&](std::size_t s) -> std::optional<std::pair<LatencyInt128, qint64>> {
        const ClockEstimate c = clockBetween(m_crossingHosts[s].first, m_crossingHosts[s].second);
        if (!c.isValid())
            return std::nullopt;
        return std::make_pair(span(t, s, s + 1) - c.offsetNs, c.uncertaintyNs);
    };
    for (std::size_t s = 0; s < m_corrected.size(); ++s) {
        if (m_corrected[s] < 0)
            continue;
        if (const auto value = corrected(s)) {
            m_series[std::size_t(m_corrected[s])]->append(saturated(value->first));
            m_uncertainty.value(m_corrected[s])->append(value->second);
        }
    }
    if (m_asymmetry < 0)
        return;
    const auto there = corrected(std::size_t(m_offsetStages.first));
    const auto back = corrected(std::size_t(m_offsetStages.second));
    if (there && back) {
        m_series[std::size_t(m_asymmetry)]->append(saturated(there->first - back->first));
        m_uncertainty.value(m_asymmetry)->append(saturated(LatencyInt128(there->second) + back->second));
    }
}

std::optional<double> PipelineSeries::uncertaintyMs(int series) const
{
    const auto it = m_uncertainty.constFind(series);
    if (it == m_uncertainty.cend() || (*it)->count() == 0)
        return std::nullopt;
    return (*it)->stats().max;
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
    if (!m_uncertainty.isEmpty())
        appendCorrected(t);
    return total;
}

void PipelineSeries::setWindow(qint64 samples)
{
    m_window = samples;
    for (auto& s : m_series)
        s->setWindow(samples);
    for (auto& s : m_uncertainty)
        s->setWindow(samples);
}

void PipelineSeries::clearValues()
{
    for (auto& s : m_series)
        s->clear();
    for (auto& s : m_uncertainty)
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

QList<int> PipelineSeries::externalWithValues() const
{
    QList<int> out;
    for (int i = 0; i < count(); ++i)
        if (m_info[std::size_t(i)].kind == Kind::External && m_series[std::size_t(i)]->count() > 0)
            out << i;
    return out;
}
