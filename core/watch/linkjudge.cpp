// SPDX-License-Identifier: MIT
#include "linkjudge.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kSecond = 1'000'000'000LL;

/// The level at which `value` passes `t` (above when `above`, else below).
LinkLevel levelOf(const Threshold& t, double value, bool above)
{
    const auto passes
        = [&](double limit) { return std::isfinite(limit) && (above ? value > limit : value < limit); };
    if (passes(t.alert))
        return LinkLevel::Alert;
    if (passes(t.warning))
        return LinkLevel::Warning;
    return LinkLevel::Ok;
}

/// The silence a limit in seconds, or else in periods of `periodNs` (at least 1 s), allows (inf: none).
double silenceLimitNs(double seconds, double periods, qint64 periodNs)
{
    if (std::isfinite(seconds))
        return seconds * 1e9;
    if (std::isfinite(periods))
        return std::max(periods * double(periodNs), 1e9);
    return qInf();
}

/// Silence `silenceNs` against limits in seconds, or in periods of `periodNs` (at least 1 s).
LinkLevel silenceLevel(const Threshold& seconds, const Threshold& periods, qint64 periodNs, qint64 silenceNs)
{
    if (double(silenceNs) > silenceLimitNs(seconds.alert, periods.alert, periodNs))
        return LinkLevel::Alert;
    if (double(silenceNs) > silenceLimitNs(seconds.warning, periods.warning, periodNs))
        return LinkLevel::Warning;
    return LinkLevel::Ok;
}

/// The source's silence up to which it still publishes (LinkJudge::sourcePublishes).
qint64 publishingLimitNs(qint64 periodNs)
{
    // Shorter than the shortest stall (1 s): a source that stops is never taken for a stall.
    return std::max<qint64>(2 * periodNs, kSecond / 2);
}
} // namespace

bool LinkJudge::sourcePublishes(const Input& in)
{
    return in.sourceSilenceNs >= 0 && in.sourceSilenceNs <= publishingLimitNs(in.periodNs);
}

qint64 LinkJudge::quietNs(const LinkRules& r, const Input& in)
{
    if (in.blindness != LinkBlindness::None)
        return 0; // the monitor judges every link again when the watcher's sight changes
    qint64 next = std::numeric_limits<qint64>::max();
    // A silence passes a limit the nanosecond after it equals it (the levels compare with >).
    const auto until = [&](double limitNs, qint64 silenceNs) {
        if (silenceNs >= 0 && std::isfinite(limitNs) && double(silenceNs) <= limitNs)
            next = std::min(next, qint64(std::ceil(limitNs)) - silenceNs + 1);
    };
    until(double(publishingLimitNs(in.periodNs)), in.sourceSilenceNs);
    const Threshold& stopped = r[LinkRules::SourceStoppedSeconds];
    until(silenceLimitNs(stopped.warning, qInf(), in.periodNs), in.sourceSilenceNs);
    until(silenceLimitNs(stopped.alert, qInf(), in.periodNs), in.sourceSilenceNs);
    const Threshold& stallS = r[LinkRules::StallSeconds];
    const Threshold& stallP = r[LinkRules::StallPeriods];
    until(silenceLimitNs(stallS.warning, stallP.warning, in.periodNs), in.destinationSilenceNs);
    until(silenceLimitNs(stallS.alert, stallP.alert, in.periodNs), in.destinationSilenceNs);
    if (in.stallLevel != LinkLevel::Ok && in.destinationSteadyNs < kStallRecoveryNs)
        next = std::min(next, kStallRecoveryNs - std::max<qint64>(in.destinationSteadyNs, 0));
    if (!in.settled && in.settlesInNs > 0)
        next = std::min(next, in.settlesInNs);
    return next == std::numeric_limits<qint64>::max() ? 0 : std::max<qint64>(next, 1);
}

LinkJudge::Verdict LinkJudge::judge(const LinkRules& r, const LinkDef& link, const Input& in)
{
    const LinkFigures& f = in.figures;
    const bool publishes = sourcePublishes(in);
    Verdict v;
    if (in.blindness != LinkBlindness::None) {
        // What the watcher cannot see is neither stalled nor lost: it is not known.
        v.unknown = true;
        v.detail = tr("unknown (%1)").arg(blindnessText(in.blindness));
        return v;
    }
    const auto add = [&](LinkLevel l, LinkReason reason, const QString& text) {
        if (l == LinkLevel::Ok)
            return;
        v.reasons << reason;
        if (l > v.level || v.detail.isEmpty())
            v.detail = text;
        v.level = std::max(v.level, l);
    };
    const LinkLevel stopped = in.sourceSilenceNs < 0
        ? LinkLevel::Ok
        : silenceLevel(r[LinkRules::SourceStoppedSeconds], Threshold(), in.periodNs, in.sourceSilenceNs);
    LinkLevel stall = publishes ? silenceLevel(r[LinkRules::StallSeconds], r[LinkRules::StallPeriods],
                                               in.periodNs, in.destinationSilenceNs)
                                : LinkLevel::Ok;
    v.silent = stall != LinkLevel::Ok;
    // Hysteresis: a stall goes on until the destination has carried messages steadily for a while.
    const bool recovering = publishes && stall == LinkLevel::Ok && in.stallLevel != LinkLevel::Ok
        && in.destinationSteadyNs < kStallRecoveryNs;
    add(stopped, LinkReason::SourceStopped,
        tr("the source %1 has been silent for %2 s")
            .arg(link.sourceTopic())
            .arg(double(in.sourceSilenceNs) / 1e9, 0, 'f', 1));
    add(stall, LinkReason::Stall,
        tr("nothing arrived on %1 for %2 s while %3 publishes")
            .arg(link.destinationTopic())
            .arg(double(in.destinationSilenceNs) / 1e9, 0, 'f', 1)
            .arg(link.sourceTopic()));
    if (recovering) {
        stall = in.stallLevel;
        add(stall, LinkReason::Stall,
            tr("%1 carries messages again, not yet steadily for %2 s")
                .arg(link.destinationTopic())
                .arg(double(kStallRecoveryNs) / 1e9, 0, 'f', 0));
    }
    if (!publishes || stall != LinkLevel::Ok || !in.settled)
        return v;
    add(levelOf(r[LinkRules::MaxLossPercent], f.lossPercent, true), LinkReason::Loss,
        tr("%1 % of the messages lost").arg(f.lossPercent, 0, 'f', 1));
    if (f.source.rateHz > 0) {
        add(levelOf(r[LinkRules::MinRateHz], f.destination.rateHz, false), LinkReason::Rate,
            tr("%1 Hz at the destination").arg(f.destination.rateHz, 0, 'f', 1));
        add(levelOf(r[LinkRules::MinRatePercent], 100.0 * f.destination.rateHz / f.source.rateHz, false),
            LinkReason::RateShare,
            tr("%1 Hz at the destination for %2 Hz at the source")
                .arg(f.destination.rateHz, 0, 'f', 1)
                .arg(f.source.rateHz, 0, 'f', 1));
    }
    if (std::isfinite(f.latencyP99Ms))
        add(levelOf(r[LinkRules::LatencyP99Ms], f.latencyP99Ms, true), LinkReason::Latency,
            tr("latency p99 %1 ms").arg(f.latencyP99Ms, 0, 'f', 1));
    return v;
}

QString LinkJudge::blindnessText(LinkBlindness blindness)
{
    switch (blindness) {
    case LinkBlindness::None:
        break;
    case LinkBlindness::Broker:
        return tr("broker unreachable");
    case LinkBlindness::RosMaster:
        return tr("ROS master unreachable");
    case LinkBlindness::Ros2Domain:
        return tr("ROS 2 domain unreachable");
    }
    return {};
}

QString LinkJudge::reasonName(LinkReason reason)
{
    // In the order of LinkReason.
    static const char16_t* const names[]
        = {u"source_stopped", u"stall", u"loss", u"rate", u"rate_share", u"latency", u"bridge_down"};
    static_assert(std::size(names) == std::size_t(LinkReason::BridgeDown) + 1);
    return QString::fromUtf16(names[std::size_t(reason)]);
}

QStringList LinkJudge::reasonNames(const QList<LinkReason>& reasons)
{
    QStringList names;
    names.reserve(reasons.size());
    for (LinkReason r : reasons)
        names << reasonName(r);
    return names;
}
