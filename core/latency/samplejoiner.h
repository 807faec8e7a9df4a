// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <deque>
#include <QtGlobal>
#include <unordered_map>
#include <vector>

/// Joins the stamps of each sample (keyed by the sample header's stamp) until every topic of the
/// pipeline has stamped it.
///
/// A sample that misses stamps for longer than the timeout (measured on the receiving clock) is
/// dropped and counted; so is the oldest pending sample when more than `maxPending` are open, so
/// memory stays bounded whatever arrives. A second stamp of a topic for the same sample, and any
/// stamp for a sample that already completed, count as duplicates; stamps for a recently dropped
/// sample count as late and do not reopen it.
///
/// A sample that began before every topic had delivered a stamp (since the last reset) is not
/// counted as dropped when it misses stamps: they were sent before the subscriptions to the later
/// topics existed (a measurement starting, or reset mid-sample), so nothing was lost. It counts as
/// `beforeAllTopics` instead; while a topic never delivers, every sample goes there, which the
/// views show as waiting for that topic rather than as loss.
class SampleJoiner
{
public:
    struct Counters
    {
        quint64 stamps = 0; ///< all stamps offered, counted or not
        quint64 complete = 0;
        quint64 timedOut = 0;
        quint64 evicted = 0; ///< dropped because too many samples were open
        quint64 duplicates = 0;
        quint64 late = 0;
        quint64 unknownTopic = 0;
        quint64 beforeAllTopics = 0; ///< incomplete, begun before every topic had a stamp
        quint64 dropped() const { return timedOut + evicted; }
    };

    static constexpr qint64 kDefaultTimeoutNs = 5'000'000'000LL;
    static constexpr int kDefaultMaxPending = 100'000;

    explicit SampleJoiner(int topics = 0);
    /// Forgets everything, for a pipeline of `topics` stamps.
    void reset(int topics);
    void setTimeoutNs(qint64 ns) { m_timeoutNs = ns; }
    qint64 timeoutNs() const { return m_timeoutNs; }
    void setMaxPending(int samples) { m_maxPending = std::max(1, samples); }

    /// Adds one stamp. Returns true when it completed its sample; `times` then holds the sample's
    /// stamps in pipeline order. A negative topic index counts an unknown topic.
    bool add(int topic, qint64 sampleNs, qint64 timeNs, qint64 receivedNs, std::vector<qint64>& times);
    /// Drops samples whose first stamp arrived more than the timeout before `nowNs`.
    void expire(qint64 nowNs);

    int topicCount() const { return m_topics; }
    /// Whether every topic delivered a stamp since the last reset.
    bool allTopicsSeen() const { return m_seenCount >= m_topics; }
    /// Whether a topic delivered a stamp since the last reset.
    bool topicSeen(int topic) const { return topic >= 0 && topic < m_topics && m_seen[std::size_t(topic)]; }
    int pending() const { return int(m_open.size()); }
    /// Entries of every internal structure together (tests check that it stays bounded).
    std::size_t bookkeeping() const
    {
        return m_open.size() + m_slots.size() + m_order.size() + m_finished.size() + m_finishedOrder.size();
    }
    const Counters& counters() const { return m_counters; }

private:
    struct Slot
    {
        qint64 sample = 0;
        qint64 firstReceivedNs = 0;
        quint64 serial = 0; ///< tells a reused slot from the one an order entry meant
        int have = 0;
        bool early = false; ///< opened before every topic had a stamp
    };
    struct OrderEntry
    {
        qint64 sample;
        quint64 serial;
    };
    enum class Finished : char { Completed, Dropped };

    int openSlot(qint64 sample, qint64 receivedNs);
    void closeSlot(int slot);
    void drop(int slot, bool timedOut);
    void rememberFinished(qint64 sample, Finished how);
    void popStaleOrder();
    void compactOrder();
    qint64* timesOf(int slot) { return m_times.data() + std::size_t(slot) * std::size_t(m_topics); }

    int m_topics = 0;
    std::vector<char> m_seen; ///< per topic: a stamp came since the reset
    int m_seenCount = 0;
    qint64 m_timeoutNs = kDefaultTimeoutNs;
    int m_maxPending = kDefaultMaxPending;
    std::unordered_map<qint64, int> m_open; ///< sample -> slot
    std::vector<Slot> m_slots;
    std::vector<qint64> m_times; ///< m_topics per slot; kMissing where no stamp came yet
    std::vector<int> m_freeSlots;
    std::deque<OrderEntry> m_order; ///< open samples by first arrival (stale entries skipped)
    quint64 m_serial = 0;
    std::unordered_map<qint64, Finished> m_finished; ///< recently completed or dropped samples
    std::deque<qint64> m_finishedOrder;
    Counters m_counters;
};
