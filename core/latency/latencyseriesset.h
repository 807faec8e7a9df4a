// SPDX-License-Identifier: MIT
#pragma once

#include "latency/ecdfsource.h"
#include "latency/latencyseries.h"

#include <memory>
#include <QHash>
#include <vector>

/// Named latency series without a pipeline: values in nanoseconds, each series over the whole
/// run. What a probe measures (one series per step) and an ECDF chart draws.
class LatencySeriesSet final : public EcdfSource
{
public:
    /// Adds `valueNs` to the series `name` (made on first use); its id is SeriesId::external(name).
    void add(const QString& name, qint64 valueNs);
    /// Empties the series `name` (it keeps its place and colour).
    void clear(const QString& name);
    /// The series `name`, or null.
    const LatencySeries* find(const QString& name) const;
    static QString idOf(const QString& name);
    quint64 revision() const { return m_revision; } ///< changes with every value

    int ecdfIndex(const QString& id) const override { return m_byId.value(id, -1); }
    const LatencySeries& ecdfSeries(int index) const override { return *m_series[std::size_t(index)]; }
    QString ecdfLabel(int index) const override { return m_names[std::size_t(index)]; }
    quint64 ecdfLayoutRevision() const override { return quint64(m_series.size()); }

private:
    QHash<QString, int> m_byId;
    std::vector<QString> m_names;
    std::vector<std::unique_ptr<LatencySeries>> m_series;
    quint64 m_revision = 0;
};
