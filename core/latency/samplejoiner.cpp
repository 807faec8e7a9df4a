// SPDX-License-Identifier: MIT
#include "samplejoiner.h"

#include <algorithm>
#include <limits>

namespace {
constexpr qint64 kMissing = std::numeric_limits<qint64>::min();
/// How many finished samples are remembered to recognise duplicates and late stamps.
constexpr std::size_t kRememberFinished = 8192;
} // namespace

SampleJoiner::SampleJoiner(int topics)
{
    reset(topics);
}

void SampleJoiner::reset(int topics)
{
    m_topics = std::max(0, topics);
    m_seen.assign(std::size_t(m_topics), 0);
    m_seenCount = 0;
    m_open.clear();
    m_slots.clear();
    m_times.clear();
    m_freeSlots.clear();
    m_order.clear();
    m_finished.clear();
    m_finishedOrder.clear();
    m_counters = {};
}

int SampleJoiner::openSlot(qint64 sample, qint64 receivedNs)
{
    int slot;
    if (!m_freeSlots.empty()) {
        slot = m_freeSlots.back();
        m_freeSlots.pop_back();
    } else {
        slot = int(m_slots.size());
        m_slots.emplace_back();
        m_times.resize(m_times.size() + std::size_t(m_topics));
    }
    Slot& s = m_slots[std::size_t(slot)];
    s.sample = sample;
    s.firstReceivedNs = receivedNs;
    s.serial = ++m_serial;
    s.have = 0;
    s.early = m_seenCount < m_topics;
    std::fill_n(timesOf(slot), m_topics, kMissing);
    m_open.emplace(sample, slot);
    m_order.push_back({sample, s.serial});
    if (m_order.size() > 2 * m_open.size() + 1024)
        compactOrder();
    return slot;
}

void SampleJoiner::closeSlot(int slot)
{
    m_open.erase(m_slots[std::size_t(slot)].sample);
    m_slots[std::size_t(slot)].serial = 0;
    m_freeSlots.push_back(slot);
}

void SampleJoiner::rememberFinished(qint64 sample, Finished how)
{
    if (m_finished.insert_or_assign(sample, how).second)
        m_finishedOrder.push_back(sample);
    while (m_finishedOrder.size() > kRememberFinished) {
        m_finished.erase(m_finishedOrder.front());
        m_finishedOrder.pop_front();
    }
}

void SampleJoiner::drop(int slot, bool timedOut)
{
    if (m_slots[std::size_t(slot)].early)
        ++m_counters.beforeAllTopics;
    else if (timedOut)
        ++m_counters.timedOut;
    else
        ++m_counters.evicted;
    rememberFinished(m_slots[std::size_t(slot)].sample, Finished::Dropped);
    closeSlot(slot);
}

void SampleJoiner::compactOrder()
{
    // Samples that completed behind a long-open one leave entries behind; sweep them out.
    const auto stale = [this](const OrderEntry& e) {
        const auto it = m_open.find(e.sample);
        return it == m_open.end() || m_slots[std::size_t(it->second)].serial != e.serial;
    };
    m_order.erase(std::remove_if(m_order.begin(), m_order.end(), stale), m_order.end());
}

void SampleJoiner::popStaleOrder()
{
    while (!m_order.empty()) {
        const auto it = m_open.find(m_order.front().sample);
        if (it != m_open.end() && m_slots[std::size_t(it->second)].serial == m_order.front().serial)
            return;
        m_order.pop_front();
    }
}

bool SampleJoiner::add(int topic, qint64 sampleNs, qint64 timeNs, qint64 receivedNs,
                       std::vector<qint64>& times)
{
    ++m_counters.stamps;
    if (topic < 0 || topic >= m_topics) {
        ++m_counters.unknownTopic;
        return false;
    }
    if (!m_seen[std::size_t(topic)]) {
        m_seen[std::size_t(topic)] = 1;
        ++m_seenCount;
    }
    int slot;
    const auto it = m_open.find(sampleNs);
    if (it != m_open.end()) {
        slot = it->second;
    } else {
        const auto finished = m_finished.find(sampleNs);
        if (finished != m_finished.end()) {
            if (finished->second == Finished::Completed)
                ++m_counters.duplicates;
            else
                ++m_counters.late;
            return false;
        }
        if (int(m_open.size()) >= m_maxPending) {
            popStaleOrder();
            drop(m_open.at(m_order.front().sample), false);
        }
        slot = openSlot(sampleNs, receivedNs);
    }
    qint64* t = timesOf(slot);
    if (t[topic] != kMissing) {
        ++m_counters.duplicates;
        return false;
    }
    t[topic] = timeNs;
    Slot& s = m_slots[std::size_t(slot)];
    if (++s.have < m_topics)
        return false;
    times.assign(t, t + m_topics);
    ++m_counters.complete;
    rememberFinished(sampleNs, Finished::Completed);
    closeSlot(slot);
    popStaleOrder();
    return true;
}

void SampleJoiner::expire(qint64 nowNs)
{
    popStaleOrder();
    while (!m_order.empty()) {
        const int slot = m_open.at(m_order.front().sample);
        // Compared without a signed subtraction, which overflowed for clocks decades apart.
        const qint64 first = m_slots[std::size_t(slot)].firstReceivedNs;
        if (nowNs <= first || quint64(nowNs) - quint64(first) <= quint64(std::max<qint64>(m_timeoutNs, 0)))
            return;
        drop(slot, true);
        popStaleOrder();
    }
}
