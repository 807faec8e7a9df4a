// SPDX-License-Identifier: MIT
#include "latencywarnings.h"

#include "latency/latencyengine.h"

#include <cmath>
#include <QHash>
#include <QSet>

using namespace Qt::StringLiterals;

namespace {
/// Whether a negative median of this series contradicts the pipeline.
bool mustNotBeNegative(const LatencyEngine::SeriesInfo& info, bool oneClock)
{
    switch (info.kind) {
    case SeriesKind::Stage:
        return !info.crossing || oneClock; // a crossing between two clocks holds their offset
    case SeriesKind::Total:
        return info.hostFrom == info.hostTo || oneClock;
    case SeriesKind::RoundTrip:
    case SeriesKind::OneWay:
    case SeriesKind::There:
    case SeriesKind::Back:
    case SeriesKind::Corrected: // beyond its uncertainty: see below
        return true;
    case SeriesKind::Asymmetry: // either way may be the longer
    case SeriesKind::ClockOffset:
    case SeriesKind::External: // measured by a bridge, not by this pipeline's order
        return false;
    }
    return false;
}
} // namespace

QList<LatencyWarning> LatencyWarnings::of(const LatencyEngine& engine)
{
    QList<LatencyWarning> out;
    const Pipeline& p = engine.pipeline();
    for (int i = 0; i < engine.seriesCount(); ++i) {
        const LatencyEngine::SeriesInfo& info = engine.info(i);
        const LatencyStats s = engine.series(i).stats();
        // A corrected crossing may lie below zero by as much as its clocks are uncertain.
        const double floor = -engine.pipelineSeries().uncertaintyMs(i).value_or(0);
        if (s.count == 0 || !(s.median < floor) || !mustNotBeNegative(info, p.oneClock()))
            continue;
        out.append({info.id, info.label,
                    tr("median %1 ms: a latency cannot be negative, so the stamps' order or their hosts are "
                       "wrong")
                        .arg(QString::number(s.median, 'f', 2))});
    }
    // Going to each other host and back crosses twice per host; more crossings mean the stamps
    // of one host are interleaved with another's.
    QSet<QString> hosts;
    for (int t = 0; t < p.topicCount(); ++t)
        if (!p.host(t).isEmpty())
            hosts.insert(p.host(t));
    const qsizetype crossings = p.crossings().size();
    const qsizetype expected = 2 * (hosts.size() - 1);
    if (hosts.size() > 1 && crossings > expected) {
        const int roundTrip = engine.pipelineSeries().roundTripSeries();
        const int pinned = roundTrip >= 0 ? roundTrip : engine.totalSeries();
        if (pinned >= 0)
            out.append({engine.info(pinned).id, engine.info(pinned).label,
                        tr("the order crosses between hosts %1 times where going there and back crosses %2 "
                           "times: the stamps of one host are interleaved with another's")
                            .arg(crossings)
                            .arg(expected)});
    }
    return out;
}

QString LatencyWarnings::fixInWindow()
{
    return tr("Set each stamp's host in the pipeline's Host column, or load a pipeline (Load Pipeline…).");
}

QString LatencyWarnings::fixOnCommandLine()
{
    return tr("Set each stamp's host (hosts: in the pipeline file), or give the pipeline with --pipeline.");
}

QStringList LatencyWarnings::lines(const QList<LatencyWarning>& warnings)
{
    // Figures wrong for the same reason (a crossing and the leg derived from it) share a line.
    QStringList reasons;
    QHash<QString, QStringList> labels;
    for (const LatencyWarning& w : warnings) {
        if (!labels.contains(w.reason))
            reasons << w.reason;
        labels[w.reason] << w.label;
    }
    QStringList out;
    for (const QString& reason : std::as_const(reasons))
        out << tr("%1: %2").arg(labels.value(reason).join(u", "_s), reason);
    return out;
}
