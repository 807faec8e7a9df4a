// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clockestimate.h"
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
///
/// With the hosts' clocks measured (setClock(), from the clock service's probes), each crossing
/// also has its one-way latency corrected by the offset between its two hosts, each value with the
/// uncertainty of the estimate it was corrected by; with an outbound and a return crossing, their
/// asymmetry beside the paper's derived round trip.
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

    /// What the clock of `estimate.host` is known to be, relative to the prober: every later sample
    /// corrects the crossings between two hosts with estimates by their offset. The corrected
    /// series of a crossing is made when both its hosts first have one. Kept across rebuilds.
    void setClock(const ClockEstimate& estimate);
    const QHash<QString, ClockEstimate>& clocks() const { return m_clocks; }
    /// Forgets every clock (another run is shown); the corrected series stay until the next rebuild.
    void clearClocks() { m_clocks.clear(); }
    /// The offset of `to`'s clock relative to `from`'s; invalid unless both were measured.
    ClockEstimate clockBetween(const QString& from, const QString& to) const;

    int count() const { return int(m_series.size()); }
    /// The single-stage series (mqtt_client's latencies, the watch's observed hops) that hold values,
    /// in the order they were made: what a report lists after the stages.
    QList<int> externalWithValues() const;
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
    /// The crossing `stage` corrected by the measured clocks; -1 when not (yet) measured.
    int correctedSeries(int stage) const;
    /// (corrected there − corrected back) / 2; -1 without both corrected legs.
    int asymmetrySeries() const { return m_asymmetry; }
    /// How far the values of a Corrected or Asymmetry series can be off, in ms: the largest
    /// uncertainty any value in its window was corrected with. nullopt for other series, or none.
    std::optional<double> uncertaintyMs(int series) const;
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
    /// The corrected series of every crossing whose hosts both have a clock, and the asymmetry;
    /// true when one was made.
    bool addCorrectedSeries();
    void appendCorrected(const std::vector<qint64>& times);

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
    qint64 m_window = 0;
    /// Crossings by stage: (from host, to host); their corrected series, -1 while not measured.
    std::vector<std::pair<QString, QString>> m_crossingHosts;
    std::vector<int> m_corrected;
    int m_asymmetry = -1;
    QHash<QString, ClockEstimate> m_clocks;
    /// Per Corrected or Asymmetry series: the uncertainty each value carried, in the series' unit.
    QHash<int, std::shared_ptr<LatencySeries>> m_uncertainty;
    quint64 m_layoutRevision = 0;
};
