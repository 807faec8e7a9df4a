// SPDX-License-Identifier: MIT
#pragma once

#include "latency/ecdfsource.h"
#include "latency/latencyseries.h"
#include "latency/seriesid.h"

#include <memory>
#include <optional>
#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <vector>

class Pipeline;

/// The latency series of a measured pipeline, as LatencyEngine fills them: one per stage, the
/// total, the communication figures of its crossings (round trip and one way; with an outbound and
/// a return crossing each leg on its own under one clock, else the clock offset), and the
/// externals measured elsewhere, which survive a change of pipeline. Found by index or by their
/// SeriesId text; an ECDF chart draws them.
class PipelineSeries final : public EcdfSource
{
    Q_DECLARE_TR_FUNCTIONS(PipelineSeries)
public:
    using Kind = SeriesKind;
    struct Info
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

    PipelineSeries();
    ~PipelineSeries() override;
    PipelineSeries(PipelineSeries&&) noexcept;
    PipelineSeries& operator=(PipelineSeries&&) noexcept;

    /// The series of `pipeline`, each over the last `window` samples (0: the whole run); the
    /// externals are kept, empty ones too.
    void rebuild(const Pipeline& pipeline, qint64 window);
    /// The index of the external series `name` (SeriesId::external), made on first use.
    int external(const QString& name, qint64 window);
    /// A complete sample's stamps in pipeline order, into every series it gives a value to; its
    /// total (first stamp to last, ns). Needs a pipeline of a stage at least.
    qint64 add(const std::vector<qint64>& times);
    void setWindow(qint64 samples);
    /// Empties every series; the layout stays.
    void clearValues();

    int count() const { return int(m_series.size()); }
    const Info& info(int series) const { return m_info[std::size_t(series)]; }
    const LatencySeries& series(int series) const { return *m_series[std::size_t(series)]; }
    LatencySeries& series(int series) { return *m_series[std::size_t(series)]; }
    int indexOf(const QString& id) const { return m_byId.value(id, -1); }
    int stageSeries(int stage) const { return stage; }
    int totalSeries() const { return m_total; }
    int roundTripSeries() const { return m_roundTrip; }
    int oneWaySeries() const { return m_oneWay; }
    int clockOffsetSeries() const { return m_clockOffset; }
    /// With one clock (Pipeline::oneClock()) and an outbound and a return crossing: each crossing
    /// as its own one-way latency; -1 otherwise (then there may be a clock offset instead).
    int thereSeries() const { return m_there; }
    int backSeries() const { return m_back; }
    /// Where the clock offset can lie, in ms, over the window: each sample bounds it by
    /// [-(return leg), outbound leg] (the legs take no negative time), so the interval is
    /// [-min return, min outbound]. An offset and a difference of the legs cannot be told apart
    /// inside it. nullopt without a clock offset series or samples.
    std::optional<std::pair<double, double>> clockOffsetBoundsMs() const;
    /// Changes whenever series come or go.
    quint64 layoutRevision() const { return m_layoutRevision; }

    int ecdfIndex(const QString& id) const override { return indexOf(id); }
    const LatencySeries& ecdfSeries(int index) const override { return series(index); }
    QString ecdfLabel(int index) const override { return info(index).label; }
    quint64 ecdfLayoutRevision() const override { return m_layoutRevision; }

private:
    int addSeries(Info info, double msPerUnit, qint64 window);
    /// The figures of an outbound and a return crossing: there and back (one clock) or the offset.
    void addLegSeries(const Pipeline& pipeline, std::pair<int, int> legs, qint64 window);

    std::vector<Info> m_info;
    std::vector<std::unique_ptr<LatencySeries>> m_series;
    QHash<QString, int> m_byId;
    int m_stages = 0;
    int m_total = -1;
    int m_roundTrip = -1;
    int m_oneWay = -1;
    int m_clockOffset = -1;
    int m_there = -1;
    int m_back = -1;
    std::vector<int> m_sameHost;
    std::pair<int, int> m_offsetStages {-1, -1};
    quint64 m_layoutRevision = 0;
};
