// SPDX-License-Identifier: MIT
#pragma once

#include "latency/contentmatcher.h"
#include "watch/linkdef.h"

#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

/// What a link's traffic is measured over: the windows of its rates, loss and latency.
namespace LinkWindows {
constexpr qint64 kSecond = 1'000'000'000LL;
constexpr qint64 kRateWindowNs = 5 * kSecond;
constexpr qint64 kLossWindowNs = 10 * kSecond;
constexpr qint64 kLossLagNs = kSecond; ///< what the source sent in the last second may still be on its way
constexpr qint64 kLatencyWindowNs = 60 * kSecond;
constexpr qint64 kKeepArrivalsNs
    = kLossWindowNs + kLossLagNs + kSecond; ///< arrivals kept for the loss window
constexpr std::size_t kMaxLatencies = 10000;
constexpr std::size_t kMaxArrivals = 100000;
constexpr quint64 kMinLossSample = 10; ///< source messages a loss figure needs
/// After the watcher sees a side again (its own connection back), what it counts from: its
/// subscriptions are made again, and messages on their way meanwhile are not the bridge's losses.
constexpr qint64 kSightMarginNs = kLossLagNs + kSecond;
} // namespace LinkWindows

/// One end of a link: its counts, its arrivals of the last seconds and its rate.
struct LinkSide
{
    SideFigures f;
    std::deque<std::pair<qint64, int>> arrivals; ///< (time, bytes) of the last 12 s
    std::deque<std::pair<qint64, quint64>> cumulative; ///< (time, messages) once a second, for loss
    double rateAtLastHz = 0; ///< the rate while it last published: its expected period
    qint64 resumedNs = 0; ///< the first message after a silence (or ever)
    qint64 firstNs = 0; ///< the first message ever (0: none yet)

    void add(qint64 ns, int size);
    /// Drops arrivals older than the loss window and computes the rates at `now`.
    void refresh(qint64 now);
    /// Messages that arrived in (from, to].
    quint64 countIn(qint64 from, qint64 to) const;
    /// Messages counted up to `ns` (0 before the first refresh).
    quint64 messagesAt(qint64 ns) const;
    qint64 expectedPeriodNs() const
    {
        return rateAtLastHz > 0 ? qint64(1e9 / rateAtLastHz) : LinkWindows::kSecond;
    }
};

/// Header.seq at the destination: gaps, duplicates and reordering.
struct SeqTracker
{
    bool started = false;
    quint32 last = 0;
    quint64 gaps = 0;
    quint64 duplicates = 0;
    quint64 reordered = 0;

    void add(quint32 seq);
};

/// A link's traffic: what both ends saw, Header.seq at each, the loss and the latency samples.
///
/// Counting is per message (add() on a side, addLatency()); refresh() turns the windows into the
/// figures once a second. The percentiles are those of core/latency (Quantile), as on the
/// Measure page.
struct LinkTraffic
{
    LinkSide src;
    LinkSide dst;
    SeqTracker seq; ///< at the destination
    SeqTracker srcSeq; ///< at the source: gaps the publisher made are not the bridge's losses
    /// What the source sent before the destination's first message, which no loss can be told
    /// of (the destination's subscription may not have been up yet); counted once it arrives.
    std::optional<quint64> beforeDestination;
    std::deque<std::pair<qint64, double>> latencies; ///< (time, ms) of the latency window
    quint64 latencySamples = 0;
    /// Since the last takeNewLatencies(), for histograms: only while they are taken (keepLatencies).
    std::vector<double> newLatencies;
    bool keepLatencies = false;
    LinkFigures figures; ///< as of the last refresh
    /// The two ends matched by content (issue 45): made at the first message with a key, for links
    /// whose payloads are the ROS serialization.
    std::unique_ptr<ContentMatcher> content;
    quint64 unconverted = 0; ///< a `json` link's MQTT payloads that did not convert: not matched
    std::deque<std::pair<qint64, double>> observed; ///< (time, ms) of matched messages, the latency window
    /// Matched messages since the last LinkMonitor::takeNewObserved() (time, latency, both ns), kept
    /// only while a measurement takes them (keepObserved), at most kMaxLatencies.
    std::vector<std::pair<qint64, qint64>> newObserved;
    bool keepObserved = false;
    /// Matched messages or drops since the last take: the measurement should visit this link.
    bool observedToHandOver() const { return !newObserved.empty() || newObservedDropped > 0; }
    quint64 newObservedDropped = 0; ///< past the bound since the last take
    quint64 lostMax = 0;
    /// The watcher cannot see a side (its broker connection, the ROS master): nothing is lost then.
    bool blind = false;
    qint64 sightNs = 0; ///< when it saw both sides again, last (0: it never lost sight)
    /// What loss is counted from after an outage of the watcher's sight: the counts at its end.
    struct Baseline
    {
        bool set = false;
        qint64 atNs = 0;
        quint64 src = 0;
        quint64 dst = 0;
        quint64 lost = 0; ///< lost before the outage
        quint64 seqGaps = 0;
        quint64 srcSeqGaps = 0;
    } baseline;

    /// The watcher lost sight of a side: loss is not counted until it sees again.
    void loseSight();
    /// It sees both sides again at `nowNs`: loss is counted afresh, kSightMarginNs later.
    void regainSight(qint64 nowNs);

    /// A latency sample (ms) at `ns`; one beyond a day is a stamp of another day and ignored.
    void addLatency(qint64 ns, double ms, LatencySource source);
    /// A message with its content key at the source (`atSource`) or the destination, at `ns`:
    /// matched with its copy at the other end for the observed hop latency. Not while blind.
    void addContent(bool atSource, const ContentKey& key, qint64 ns);
    /// Rates, loss and the latency percentiles at `nowNs` into `figures`.
    void refresh(qint64 nowNs);
    /// The figures with the live counts (rates and percentiles are those of the last refresh).
    LinkFigures liveFigures() const;

private:
    void refreshLoss(qint64 nowNs);
};
