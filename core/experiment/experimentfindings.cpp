// SPDX-License-Identifier: MIT
#include "experimentfindings.h"

#include "experiment/experimentreport.h"
#include "latency/latencyseries.h"

using namespace Qt::StringLiterals;

namespace {
using Cell = ExperimentReport::Cell;
using Column = ExperimentReport::Column;
using FactorTable = ExperimentReport::FactorTable;

QString formatMs(double v)
{
    return ExperimentReport::formatMs(v);
}
} // namespace

std::optional<ShiftEstimate> ExperimentFindings::shiftOf(const LatencySeries& low, const LatencySeries& high)
{
    // The values in each series' window: the last count() of those it keeps.
    const auto window = [](const LatencySeries& s) {
        const std::vector<qint64>& v = s.values();
        return std::vector<qint64>(v.end() - qsizetype(std::min<qint64>(s.count(), qint64(v.size()))),
                                   v.end());
    };
    return ShiftEstimate::of(window(low), window(high), low.msPerUnit());
}

QString ExperimentFindings::shiftText(const ShiftEstimate& shift)
{
    return tr("%1 ms [%2, %3] ms, 95 %")
        .arg(formatMs(shift.shiftMs), formatMs(shift.lowMs), formatMs(shift.highMs));
}

QString ExperimentFindings::differenceFinding(const QString& factor, const QString& lowLevel, double lowMs,
                                              const QString& highLevel, double highMs,
                                              const std::optional<ShiftEstimate>& shift)
{
    if (shift && !shift->significant())
        return tr("%1: no significant difference between %2 and %3: the totals shift by %4 (the means: "
                  "%5 and %6 ms)")
            .arg(factor, lowLevel, highLevel, shiftText(*shift), formatMs(lowMs), formatMs(highMs));
    QString line
        = tr("%1: the total mean is lowest at %2 (%3 ms) and highest at %4 (%5 ms), %6 ms more (%7 %)")
              .arg(factor, lowLevel, formatMs(lowMs), highLevel, formatMs(highMs), formatMs(highMs - lowMs))
              .arg(lowMs > 0 ? QString::number(qRound(100 * (highMs - lowMs) / lowMs)) : u"–"_s);
    if (shift)
        line += tr("; the totals shift by %1").arg(shiftText(*shift));
    else
        line += tr(" (too few samples for an interval)");
    return line;
}

QStringList ExperimentFindings::of(const ExperimentReport& report)
{
    QStringList out;
    for (const Cell& c : report.cells()) {
        if (c.status.state == CellStatus::Failed)
            out << tr("Cell %1 (%2) failed: %3").arg(c.cell.id(), c.cell.label(), c.status.reason);
        else if (c.status.state != CellStatus::Complete)
            out << tr("Cell %1 (%2) is not done (%3): --resume finishes it.")
                       .arg(c.cell.id(), c.cell.label(), CellStatus::stateName(c.status.state));
        else if (!c.problem.isEmpty())
            out << tr("Cell %1 is left out: %2").arg(c.cell.id(), c.problem);
    }
    for (const ThroughputResult& t : report.throughput())
        if (t.complete && !t.points.isEmpty())
            out << (t.maxSustainableHz() > 0
                        ? tr("Throughput with %1 (%2 bytes): up to %3 Hz sustained, %4 MB/s.")
                              .arg(t.level)
                              .arg(t.payloadBytes)
                              .arg(t.maxSustainableHz())
                              .arg(formatMs(t.megabytesPerSecond()))
                        : tr("Throughput with %1 (%2 bytes): not even %3 Hz was sustained.")
                              .arg(t.level)
                              .arg(t.payloadBytes)
                              .arg(t.points.first().rateHz));
    const int total = int(report.groups().size()) - 1;
    for (const FactorTable& t : report.tables()) {
        QList<const Column*> measured;
        for (const Column& c : t.columns)
            if (!c.cells.isEmpty() && std::isfinite(c.groups[total].mean))
                measured << &c;
        if (measured.size() < 2)
            continue;
        const auto [low, high]
            = std::minmax_element(measured.cbegin(), measured.cend(), [total](auto a, auto b) {
                  return a->groups[total].mean < b->groups[total].mean;
              });
        const double lo = (*low)->groups[total].mean;
        const double hi = (*high)->groups[total].mean;
        const std::optional<ShiftEstimate> shift
            = (*low)->total && (*high)->total ? shiftOf(*(*low)->total, *(*high)->total) : std::nullopt;
        if (shift && !shift->significant()) {
            out << differenceFinding(t.factor, (*low)->level, lo, (*high)->level, hi, shift) + u'.';
            continue; // nothing moved that the samples can tell apart from chance
        }
        // The group that moved most between the two levels.
        int most = -1;
        double moved = 0;
        for (int g = 0; g < total; ++g) {
            const double d = (*high)->groups[g].mean - (*low)->groups[g].mean;
            if (std::isfinite(d) && std::abs(d) > std::abs(moved)) {
                moved = d;
                most = g;
            }
        }
        QString line = differenceFinding(t.factor, (*low)->level, lo, (*high)->level, hi, shift);
        if (most >= 0)
            line += tr("; most of it in %1 (%2 ms).").arg(report.groups()[most].label, formatMs(moved));
        else
            line += u'.';
        out << line;
        // What the bridge notes already explain.
        const auto levelMean = [&](const QString& level, int group) {
            for (const Column* c : measured)
                if (c->level == level)
                    return c->groups[group].mean;
            return LatencyStats::nan();
        };
        if (t.factor == u"qos"_s
            && levelMean(u"0"_s, total) < std::max(levelMean(u"1"_s, total), levelMean(u"2"_s, total)))
            out << tr("QoS 1 and 2 wait for the broker's acknowledgements (PUBACK; PUBREC, PUBREL, PUBCOMP), "
                      "and a client without TCP_NODELAY (Paho) can wait for a delayed ACK of up to 40 ms "
                      "on each.");
        if (t.factor == u"announce"_s && levelMean(u"once"_s, total) < levelMean(u"every_message"_s, total))
            out << tr("Announcing the type before every message (mqtt_client 2.2.1) puts a small publish in "
                      "front of each message; without TCP_NODELAY the message then waits for the delayed ACK "
                      "of the first, up to 40 ms.");
        if (t.factor == u"payload"_s && measured.size() >= 2
            && report.groups().first().label == u"interfaces"_s) {
            const Column* smallest = measured.first();
            const Column* next = measured.at(1);
            if (smallest->groups[0].mean > next->groups[0].mean)
                out << tr("The smallest payload (%1) is slower through the interfaces than %2 (%3 against %4 "
                          "ms): small messages wait for delayed ACKs where Nagle's algorithm holds them.")
                           .arg(smallest->level, next->level, formatMs(smallest->groups[0].mean),
                                formatMs(next->groups[0].mean));
        }
    }
    return out;
}
