// SPDX-License-Identifier: MIT
#pragma once

#include "wire/contentkey.h"

#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <QHash>
#include <QtGlobal>

/// Matches the messages that go into a bridge with those that come out of it by their content, in
/// arrival order, with bounded state: the hop latency of each message Bridgescope sees at both ends
/// (on its one clock), what never arrives (loss) and what cannot be told apart.
///
/// Both ends are held alike: a message seen at one end waits for its copy at the other, so a copy
/// that Bridgescope happens to get before the original is matched too (its latency is then
/// negative: the two subscriptions' delivery, not the bridge). A message waits at most `maxWaitNs`:
/// an original that waited that long is lost, a copy that did is an arrival nobody sent through the
/// bridge (another publisher on the destination). At most `maxPending` wait at each end; beyond
/// it the oldest is dropped unjudged and counted. Identical contents in flight at one time cannot be
/// told apart: each such match is counted as ambiguous and gives no latency.
///
/// A copy waits for its original only while it can be the earlier of the two by the subscriptions'
/// delivery: once it waited more than half the time since the last copy with its content (an equal
/// stream's period), it is judged unexplained (its original was missed) rather than matched with
/// the next original, which would put every later match of the stream one period off.
///
/// Work per message: a hash lookup and a deque step; expiry is amortised over the messages.
class ContentMatcher
{
public:
    struct Limits
    {
        std::size_t maxPending = 512;
        qint64 maxWaitNs = 2'000'000'000LL;
    };
    struct Counts
    {
        quint64 sources = 0; ///< messages seen going in
        quint64 destinations = 0; ///< messages seen coming out
        quint64 matched = 0; ///< with a latency
        quint64 ambiguous = 0; ///< matched to one of several identical contents: no latency
        quint64 lost = 0; ///< went in, did not come out within maxWaitNs
        quint64 unexplained = 0; ///< came out with nothing gone in within maxWaitNs
        quint64 overflow = 0; ///< dropped unjudged: more than maxPending waited at one end
        /// Went unmatched, but waited from before the other end's first message (since the start or
        /// restart()): the other end's subscription may not have been up; neither lost nor unexplained.
        quint64 unjudged = 0;
        /// Lost among the messages judged (matched, ambiguous or lost); 0 before any.
        double lossRatio() const
        {
            const quint64 judged = matched + ambiguous + lost;
            return judged ? double(lost) / double(judged) : 0.0;
        }
    };

    ContentMatcher();
    explicit ContentMatcher(Limits limits);

    /// A message went into the bridge at `ns`: the latency (ns) when its copy came out before and
    /// is told apart.
    std::optional<qint64> source(const ContentKey& key, qint64 ns);
    /// A message came out at `ns`: its latency (ns) when it matches one message that went in.
    std::optional<qint64> destination(const ContentKey& key, qint64 ns);
    /// Judges what waited past maxWaitNs at `nowNs` (source() and destination() do it as they go).
    void expire(qint64 nowNs);

    const Counts& counts() const { return m_counts; }
    /// Forgets what waits, unjudged, and judges as after a start (the counts stay): after the
    /// watcher lost sight of an end, whose subscription is made again.
    void restart();
    /// Messages waiting at both ends: the state held now.
    std::size_t pending() const { return m_in.size() + m_out.size(); }
    void clear();

private:
    /// The messages of one end that wait for their copies, oldest first.
    class End
    {
    public:
        enum class Take { None, Unique, Ambiguous };
        /// Consumes the oldest waiting message with `key`; `ns` is its time when Unique.
        Take take(const ContentKey& key, qint64* ns);
        /// Adds a message; false when it made room by dropping the oldest (counted by the caller).
        /// `gapNs`: the time since the last message with the key at this end (0: none known).
        bool add(const ContentKey& key, qint64 ns, qint64 gapNs, std::size_t maxPending);
        /// Drops the one message waiting with `key` when, at `nowNs`, it waited more than half its
        /// gap: true, with `*ns` its time, when it did.
        bool dropStale(const ContentKey& key, qint64 nowNs, qint64* ns);
        /// Drops the oldest when it waited past `beforeNs` (or `force`): true when one was dropped;
        /// `*unmatched` whether it went without its copy, `*ns` its time.
        bool expireOldest(qint64 beforeNs, bool force, bool* unmatched, qint64* ns = nullptr);
        std::size_t size() const { return m_entries.size(); }
        void clear();

    private:
        struct Entry
        {
            ContentKey key;
            qint64 ns = 0;
            qint64 gapNs = 0;
            bool taken = false;
            bool inSlot = false; ///< taken by an ambiguous match: still counted in its key's slot
        };
        struct Slot
        {
            quint64 firstSeq = 0; ///< the oldest waiting entry with the key, while it is unique
            int waiting = 0; ///< entries with the key in m_entries, taken ones included
            int taken = 0; ///< of those, consumed by ambiguous matches
            bool ambiguous = false; ///< two with the key waited at once
        };
        /// Takes the one entry waiting in `slot`, its time into `*ns`.
        void takeOnly(QHash<ContentKey, Slot>::iterator slot, qint64* ns);
        /// Drops the taken entries at the front.
        void popTaken();
        /// Takes a leaving entry out of its key's slot: true when it went unmatched.
        bool release(const Entry& e);

        std::deque<Entry> m_entries;
        quint64 m_base = 0; ///< the sequence number of m_entries.front()
        QHash<ContentKey, Slot> m_slots;
    };

    std::optional<qint64> arrive(End& here, End& there, const ContentKey& key, qint64 ns, bool isSource);
    /// The time since the last copy with `key` came out (0: none remembered), remembering `ns`.
    qint64 copyGap(const ContentKey& key, qint64 ns);
    /// An unmatched message of one end judged: lost (or unexplained) when the other end had been
    /// heard from by then, else unjudged.
    void judge(qint64 ns, std::optional<qint64> otherFirstNs, quint64* count);

    Limits m_limits;
    End m_in; ///< gone in, waiting to come out
    End m_out; ///< come out, waiting for what went in
    Counts m_counts;
    std::optional<qint64> m_firstIn; ///< the first message in since the start or restart()
    std::optional<qint64> m_firstOut;
    /// When the last copy with a content came out, by its hash: kGapSlots slots (1 KiB, made with the
    /// first copy), a content taking the slot of another (no allocation per message; an equal
    /// stream keeps its slot while it is the topic's only content in its slot).
    struct LastCopy
    {
        quint64 id = 0; ///< the content's hash and size mixed; 0: empty
        qint64 ns = 0;
    };
    static constexpr std::size_t kGapSlots = 64;
    std::unique_ptr<std::array<LastCopy, kGapSlots>> m_lastOut;
};
