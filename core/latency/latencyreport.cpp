// SPDX-License-Identifier: MIT
#include "latencyreport.h"

#include "latency/latencyengine.h"
#include "latency/latencywarnings.h"
#include "latency/seriesid.h"

#include <cmath>
#include <QJsonArray>

using namespace Qt::StringLiterals;

QJsonValue LatencyReport::number(double value)
{
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

QJsonObject LatencyReport::statsJson(const LatencyStats& s)
{
    QJsonObject o;
    o.insert(u"count"_s, s.count);
    o.insert(u"mean_ms"_s, number(s.mean));
    o.insert(u"median_ms"_s, number(s.median));
    o.insert(u"std_ms"_s, number(s.std));
    o.insert(u"min_ms"_s, number(s.min));
    o.insert(u"max_ms"_s, number(s.max));
    o.insert(u"p90_ms"_s, number(s.p90));
    o.insert(u"p95_ms"_s, number(s.p95));
    o.insert(u"p99_ms"_s, number(s.p99));
    o.insert(u"p999_ms"_s, number(s.p999));
    return o;
}

QJsonObject LatencyReport::measuredJson(const PipelineSeries& series, int index)
{
    QJsonObject o = statsJson(series.series(index).stats());
    o.insert(u"uncertainty_ms"_s, number(series.uncertaintyMs(index).value_or(std::nan(""))));
    return o;
}

QJsonObject LatencyReport::clockJson(const ClockEstimate& c)
{
    return QJsonObject {{u"offset_ms"_s, double(c.offsetNs) / 1e6},
                        {u"uncertainty_ms"_s, double(c.uncertaintyNs) / 1e6},
                        {u"drift_ppm"_s, c.driftPpm},
                        {u"best_round_trip_ms"_s, double(c.bestRoundTripNs) / 1e6},
                        {u"probes"_s, c.probes},
                        {u"at_ns"_s, QString::number(c.atNs)}};
}

QJsonObject LatencyReport::json(const LatencyEngine& engine, qint64 extraDropped)
{
    const Pipeline& p = engine.pipeline();
    QJsonObject doc;
    doc.insert(u"samples"_s, engine.samples());
    doc.insert(u"dropped"_s, qint64(engine.counters().dropped()) + extraDropped);
    const PipelineSeries& series = engine.pipelineSeries();
    const auto statsOf = [&series](int index) { return statsJson(series.series(index).stats()); };
    QJsonArray stages;
    for (int s = 0; s < p.stageCount(); ++s) {
        QJsonObject stage;
        stage.insert(u"from"_s, p.topics()[s]);
        stage.insert(u"to"_s, p.topics()[s + 1]);
        stage.insert(u"crossing"_s, p.isCrossing(s));
        stage.insert(u"stats"_s, statsOf(series.stageSeries(s)));
        if (const int corrected = series.correctedSeries(s); corrected >= 0)
            stage.insert(u"corrected"_s, measuredJson(series, corrected));
        stages.append(stage);
    }
    doc.insert(u"stages"_s, stages);
    doc.insert(u"total"_s,
               engine.totalSeries() >= 0 ? QJsonValue(statsJson(engine.series(engine.totalSeries()).stats()))
                                         : QJsonValue(QJsonValue::Null));
    if (series.roundTripSeries() >= 0) {
        QJsonObject comm;
        comm.insert(u"round_trip"_s, statsOf(series.roundTripSeries()));
        comm.insert(u"one_way"_s, statsOf(series.oneWaySeries()));
        if (series.thereSeries() >= 0) {
            comm.insert(u"there"_s, statsOf(series.thereSeries()));
            comm.insert(u"back"_s, statsOf(series.backSeries()));
        }
        if (series.asymmetrySeries() >= 0)
            comm.insert(u"asymmetry"_s, measuredJson(series, series.asymmetrySeries()));
        doc.insert(u"communication"_s, comm);
    } else {
        doc.insert(u"communication"_s, QJsonValue::Null);
    }
    doc.insert(u"clock_offset"_s,
               series.clockOffsetSeries() >= 0 ? QJsonValue(statsOf(series.clockOffsetSeries()))
                                               : QJsonValue(QJsonValue::Null));
    doc.insert(u"one_clock"_s, p.oneClock());
    const auto bounds = series.clockOffsetBoundsMs();
    QJsonArray warnings;
    for (const LatencyWarning& w : LatencyWarnings::of(engine))
        warnings.append(
            QJsonObject {{u"series"_s, w.seriesId}, {u"label"_s, w.label}, {u"reason"_s, w.reason}});
    doc.insert(u"warnings"_s, warnings);
    doc.insert(u"clock_offset_bounds_ms"_s,
               bounds ? QJsonValue(QJsonArray {number(bounds->first), number(bounds->second)})
                      : QJsonValue(QJsonValue::Null));
    QJsonObject clocks;
    for (auto c = series.clocks().cbegin(); c != series.clocks().cend(); ++c)
        clocks.insert(c.key(), clockJson(*c));
    if (!clocks.isEmpty())
        doc.insert(u"clocks"_s, clocks);
    // Single-stage series: mqtt_client's own latencies and the watch's observed hop latencies.
    QJsonArray single;
    for (int i : series.externalWithValues()) {
        const PipelineSeries::Info& info = series.info(i);
        single.append(QJsonObject {{u"name"_s, info.label},
                                   {u"observed"_s, SeriesId::isObserved(info.label)},
                                   {u"stats"_s, statsOf(i)}});
    }
    if (!single.isEmpty())
        doc.insert(u"single_stage"_s, single);
    return doc;
}
