// SPDX-License-Identifier: MIT
#include "linktraffic.h"

#include "latency/quantile.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace LinkWindows;

void LinkSide::add(qint64 ns, int size)
{
    if (firstNs == 0)
        firstNs = ns;
    if (f.lastNs == 0 || ns - f.lastNs > std::max<qint64>(3 * expectedPeriodNs(), 1'000'000'000LL))
        resumedNs = ns;
    ++f.messages;
    f.bytes += quint64(size);
    f.lastNs = std::max(f.lastNs, ns);
    arrivals.emplace_back(ns, size);
    if (arrivals.size() > kMaxArrivals)
        arrivals.pop_front();
}

void LinkSide::refresh(qint64 now)
{
    while (!arrivals.empty() && now - arrivals.front().first > kKeepArrivalsNs)
        arrivals.pop_front();
    // As rostopic hz: the intervals between the arrivals of the last 5 s.
    qsizetype n = 0;
    qint64 bytes = 0;
    qint64 first = 0;
    for (auto it = arrivals.crbegin(); it != arrivals.crend() && now - it->first <= kRateWindowNs; ++it) {
        ++n;
        bytes += it->second;
        first = it->first;
    }
    const qint64 last = n ? arrivals.back().first : 0;
    f.rateHz = n >= 2 && last > first ? double(n - 1) / (double(last - first) / 1e9) : 0;
    f.bytesPerSecond = n ? double(bytes) / (double(kRateWindowNs) / 1e9) : 0;
    if (f.rateHz > 0)
        rateAtLastHz = f.rateHz;
    cumulative.emplace_back(now, f.messages);
    while (cumulative.size() > 2 && now - cumulative.front().first > kLossWindowNs + 5 * kSecond)
        cumulative.pop_front();
}

quint64 LinkSide::countIn(qint64 from, qint64 to) const
{
    quint64 n = 0;
    for (auto it = arrivals.crbegin(); it != arrivals.crend() && it->first > from; ++it)
        n += it->first <= to;
    return n;
}

quint64 LinkSide::messagesAt(qint64 ns) const
{
    quint64 m = 0;
    for (const auto& [t, count] : cumulative) {
        if (t > ns)
            break;
        m = count;
    }
    return m;
}

void SeqTracker::add(quint32 seq)
{
    constexpr quint32 kRestart = 1'000'000; // a jump this large is a restarted publisher
    if (!started) {
        started = true;
        last = seq;
        return;
    }
    if (seq == last) {
        ++duplicates;
    } else if (seq > last) {
        const quint32 skipped = seq - last - 1;
        if (skipped < kRestart)
            gaps += skipped;
        last = seq;
    } else if (last - seq < kRestart && seq != 0) {
        ++reordered; // counted as a gap when the later one came
        if (gaps > 0)
            --gaps;
    } else {
        last = seq; // restarted from 0 or wrapped
    }
}

void LinkTraffic::addLatency(qint64 ns, double ms, LatencySource source)
{
    if (!std::isfinite(ms) || std::abs(ms) > 86'400'000.0)
        return; // not a latency: a stamp from another day
    figures.latencySource = source;
    latencies.emplace_back(ns, ms);
    if (latencies.size() > kMaxLatencies)
        latencies.pop_front();
    ++latencySamples;
    if (keepLatencies && newLatencies.size() < kMaxLatencies)
        newLatencies.push_back(ms);
}

void LinkTraffic::addContent(bool atSource, const ContentKey& key, qint64 ns)
{
    if (blind)
        return; // an end the watcher cannot see: nothing is judged
    if (!content)
        content = std::make_unique<ContentMatcher>();
    const std::optional<qint64> latency = atSource ? content->source(key, ns) : content->destination(key, ns);
    if (!latency)
        return;
    observed.emplace_back(ns, double(*latency) / 1e6);
    if (observed.size() > kMaxLatencies)
        observed.pop_front();
    if (!keepObserved)
        return;
    if (newObserved.size() < kMaxLatencies)
        newObserved.emplace_back(ns, *latency);
    else
        ++newObservedDropped;
}

void LinkTraffic::refresh(qint64 nowNs)
{
    src.refresh(nowNs);
    dst.refresh(nowNs);
    figures.source = src.f;
    figures.destination = dst.f;
    refreshLoss(nowNs);
    while (!latencies.empty() && nowNs - latencies.front().first > kLatencyWindowNs)
        latencies.pop_front();
    std::vector<double> values;
    values.reserve(latencies.size());
    for (const auto& l : latencies)
        values.push_back(l.second);
    figures.latencyP50Ms = Quantile::of(values, 0.50);
    figures.latencyP99Ms = Quantile::of(values, 0.99);
    if (content) {
        content->expire(nowNs);
        while (!observed.empty() && nowNs - observed.front().first > kLatencyWindowNs)
            observed.pop_front();
        values.clear();
        for (const auto& l : observed)
            values.push_back(l.second);
        figures.observedP50Ms = Quantile::of(values, 0.50);
        figures.observedP99Ms = Quantile::of(values, 0.99);
    }
}

void LinkTraffic::loseSight()
{
    blind = true;
    if (content)
        content->restart(); // what waits now is neither lost nor matched: the watcher did not see
}

void LinkTraffic::regainSight(qint64 nowNs)
{
    blind = false;
    sightNs = nowNs;
    baseline.set = false;
    // Header.seq jumps over what the watcher did not see: not a gap.
    seq.started = false;
    srcSeq.started = false;
}

void LinkTraffic::refreshLoss(qint64 nowNs)
{
    LinkFigures& f = figures;
    // What the watcher could not see is not lost: while it is blind and until its subscriptions
    // are back nothing is counted; then everything is counted from the counts at that moment.
    if (blind || (sightNs > 0 && nowNs - sightNs < kSightMarginNs)) {
        f.lossPercent = 0;
        f.lost = lostMax;
        return;
    }
    if (sightNs > 0 && !baseline.set)
        baseline = {true, nowNs, src.f.messages, dst.f.messages, lostMax, seq.gaps, srcSeq.gaps};
    // Loss: what the source sent in a 10 s window that ended a second ago (messages on their
    // way are not lost) against what arrived in as long a window. The edges of two windows can cut one
    // message differently: one missing message is not counted, so a loss shown is a loss.
    // Before the destination's first message nothing is judged: at a start the monitor's
    // subscription at the source is up before that at the destination (a ROS subscriber's
    // connection takes a while), and the first messages would look lost.
    if (!beforeDestination && dst.firstNs > 0) {
        const quint64 since = src.countIn(dst.firstNs - 1, std::numeric_limits<qint64>::max());
        const quint64 before = src.f.messages - std::min(since, src.f.messages);
        beforeDestination = before > 0 ? before - 1 : 0; // the one that arrived was sent before
    }
    const quint64 unjudged = beforeDestination.value_or(0);
    const quint64 srcThen = src.messagesAt(nowNs - kLossLagNs);
    // The destination's window is the source's, shifted by the typical latency where stamps tell it.
    const double p50 = f.latencyP50Ms;
    const qint64 shift = std::isfinite(p50) ? std::clamp<qint64>(qint64(p50 * 1e6), 0, kLossLagNs) : 0;
    qint64 from = nowNs - kLossLagNs - kLossWindowNs;
    if (dst.firstNs > 0)
        from = std::max(from, dst.firstNs - 1 - shift);
    if (baseline.set)
        from = std::max(from, baseline.atNs);
    const quint64 sent = src.countIn(from, nowNs - kLossLagNs);
    const quint64 got = dst.countIn(from + shift, nowNs - kLossLagNs + shift);
    f.lossPercent
        = sent >= kMinLossSample && sent > got + 1 ? 100.0 * double(sent - got - 1) / double(sent) : 0;
    // Lost for sure: what the source sent a second ago and never arrived, or, once the source
    // pauses, everything it sent that never arrived; Header.seq gaps are losses as well.
    const bool paused
        = src.f.lastNs > 0 && nowNs - src.f.lastNs > std::max<qint64>(3 * src.expectedPeriodNs(), kSecond);
    const quint64 srcCount = paused ? src.f.messages : srcThen;
    const quint64 srcFloor = baseline.set ? baseline.src : std::min(unjudged, srcThen);
    const quint64 sentBy = srcCount - std::min(srcFloor, srcCount);
    const quint64 arrived = dst.f.messages - std::min(baseline.dst, dst.f.messages);
    if (sentBy > arrived)
        lostMax = std::max(lostMax, baseline.lost + sentBy - arrived);
    const quint64 gaps = seq.gaps - std::min(baseline.seqGaps, seq.gaps);
    const quint64 srcGaps = srcSeq.gaps - std::min(baseline.srcSeqGaps, srcSeq.gaps);
    if (gaps > srcGaps) // gaps the bridge made: lost for sure
        lostMax = std::max(lostMax, baseline.lost + gaps - srcGaps);
    f.lost = lostMax;
}

LinkFigures LinkTraffic::liveFigures() const
{
    // Counts are live; rates are those of the last refresh.
    const auto counts = [](const SideFigures& live, SideFigures& out) {
        out.messages = live.messages;
        out.bytes = live.bytes;
        out.lastNs = live.lastNs;
    };
    LinkFigures f = figures;
    counts(src.f, f.source);
    counts(dst.f, f.destination);
    f.seqGaps = seq.gaps;
    f.duplicates = seq.duplicates;
    f.reordered = seq.reordered;
    f.latencySamples = latencySamples;
    if (content) { // the counts so far; what waits is judged at refreshes
        const ContentMatcher::Counts& c = content->counts();
        f.observedSamples = c.matched;
        f.observedLost = c.lost;
        f.observedAmbiguous = c.ambiguous;
        f.observedUnexplained = c.unexplained;
        f.observedOverflow = c.overflow;
    }
    f.observedUnconverted = unconverted;
    return f;
}
