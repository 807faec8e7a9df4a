// SPDX-License-Identifier: MIT
#include "latencyseriesset.h"

#include "latency/seriesid.h"

QString LatencySeriesSet::idOf(const QString& name)
{
    return SeriesId::external(name).toString();
}

void LatencySeriesSet::add(const QString& name, qint64 valueNs)
{
    const QString id = idOf(name);
    int index = m_byId.value(id, -1);
    if (index < 0) {
        index = int(m_series.size());
        m_byId.insert(id, index);
        m_names.push_back(name);
        m_series.push_back(std::make_unique<LatencySeries>(1e-6));
        m_series.back()->setWindow(0); // the whole run
    }
    m_series[std::size_t(index)]->append(valueNs);
    ++m_revision;
}

const LatencySeries* LatencySeriesSet::find(const QString& name) const
{
    const int index = ecdfIndex(idOf(name));
    return index < 0 ? nullptr : m_series[std::size_t(index)].get();
}

void LatencySeriesSet::clear(const QString& name)
{
    if (const int i = m_byId.value(idOf(name), -1); i >= 0) {
        m_series[std::size_t(i)]->clear();
        ++m_revision;
    }
}
