// SPDX-License-Identifier: MIT
#include "contentmatcher.h"

#include <algorithm>

ContentMatcher::ContentMatcher()
    : ContentMatcher(Limits())
{ }

ContentMatcher::ContentMatcher(Limits limits)
    : m_limits(limits)
{
    m_limits.maxPending = std::max<std::size_t>(m_limits.maxPending, 1);
}

ContentMatcher::End::Take ContentMatcher::End::take(const ContentKey& key, qint64* ns)
{
    const auto it = m_slots.find(key);
    if (it == m_slots.end() || it->waiting - it->taken <= 0)
        return Take::None;
    if (it->ambiguous) {
        // Which of them this is cannot be told. A bridge delivers in order, soon: the newest is
        // taken, so the older ones that stay are the lost, judged as they expire; once none with
        // the key waits, the next is told apart again (one loss in a stream of equal messages does
        // not make every later match ambiguous).
        for (auto e = m_entries.rbegin(); e != m_entries.rend(); ++e) {
            if (!e->taken && e->key == key) {
                e->taken = true;
                e->inSlot = true;
                break;
            }
        }
        ++it->taken;
        popTaken();
        return Take::Ambiguous;
    }
    takeOnly(it, ns);
    return Take::Unique;
}

void ContentMatcher::End::takeOnly(QHash<ContentKey, Slot>::iterator slot, qint64* ns)
{
    Entry& e = m_entries[std::size_t(slot->firstSeq - m_base)];
    e.taken = true;
    *ns = e.ns;
    m_slots.erase(slot); // it was the only one waiting
    popTaken();
}

void ContentMatcher::End::popTaken()
{
    // In order, as a bridge delivers: what was matched leaves at once, the state stays small.
    while (!m_entries.empty() && m_entries.front().taken) {
        release(m_entries.front());
        m_entries.pop_front();
        ++m_base;
    }
}

bool ContentMatcher::End::release(const Entry& e)
{
    if (e.taken && !e.inSlot)
        return false; // told apart: its slot went when it was taken
    const auto it = m_slots.find(e.key);
    Q_ASSERT(it != m_slots.end());
    if (e.taken)
        --it->taken;
    if (--it->waiting == 0)
        m_slots.erase(it);
    return !e.taken;
}

bool ContentMatcher::End::dropStale(const ContentKey& key, qint64 nowNs, qint64* ns)
{
    const auto it = m_slots.find(key);
    if (it == m_slots.end() || it->ambiguous || it->waiting - it->taken != 1)
        return false;
    const Entry& e = m_entries[std::size_t(it->firstSeq - m_base)];
    if (e.gapNs <= 0 || nowNs - e.ns <= e.gapNs / 2)
        return false;
    takeOnly(it, ns);
    return true;
}

bool ContentMatcher::End::add(const ContentKey& key, qint64 ns, qint64 gapNs, std::size_t maxPending)
{
    bool droppedUnmatched = false;
    while (m_entries.size() >= maxPending) {
        bool unmatched = false;
        expireOldest(0, true, &unmatched);
        droppedUnmatched = droppedUnmatched || unmatched;
    }
    const quint64 seq = m_base + m_entries.size();
    m_entries.push_back({key, ns, gapNs, false});
    Slot& slot = m_slots[key];
    if (slot.waiting == 0)
        slot.firstSeq = seq;
    else
        slot.ambiguous = true; // another with the key waits, or was consumed without being told apart
    ++slot.waiting;
    return !droppedUnmatched;
}

bool ContentMatcher::End::expireOldest(qint64 beforeNs, bool force, bool* unmatched, qint64* ns)
{
    *unmatched = false;
    if (m_entries.empty() || (!force && m_entries.front().ns >= beforeNs))
        return false;
    const Entry e = m_entries.front();
    m_entries.pop_front();
    ++m_base;
    if (ns)
        *ns = e.ns;
    *unmatched = release(e);
    popTaken();
    return true;
}

void ContentMatcher::End::clear()
{
    m_entries.clear();
    m_slots.clear();
    m_base = 0;
}

void ContentMatcher::judge(qint64 ns, std::optional<qint64> otherFirstNs, quint64* count)
{
    if (otherFirstNs && ns >= *otherFirstNs)
        ++*count;
    else
        ++m_counts.unjudged;
}

void ContentMatcher::expire(qint64 nowNs)
{
    const qint64 before = nowNs - m_limits.maxWaitNs;
    bool unmatched = false;
    qint64 ns = 0;
    while (m_in.expireOldest(before, false, &unmatched, &ns))
        if (unmatched)
            judge(ns, m_firstOut, &m_counts.lost);
    while (m_out.expireOldest(before, false, &unmatched, &ns))
        if (unmatched)
            judge(ns, m_firstIn, &m_counts.unexplained);
}

qint64 ContentMatcher::copyGap(const ContentKey& key, qint64 ns)
{
    if (!m_lastOut)
        m_lastOut = std::make_unique<std::array<LastCopy, kGapSlots>>();
    const quint64 id = (key.hash ^ (quint64(key.size) * 0x9E3779B97F4A7C15ULL)) | 1; // never 0
    LastCopy& slot = (*m_lastOut)[std::size_t(id >> 32) % kGapSlots];
    const qint64 gap = slot.id == id ? std::max<qint64>(ns - slot.ns, 0) : 0;
    slot = {id, ns};
    return gap;
}

std::optional<qint64> ContentMatcher::arrive(End& here, End& there, const ContentKey& key, qint64 ns,
                                             bool isSource)
{
    expire(ns);
    // A copy waiting since before half its stream's period: its original was missed (above).
    qint64 staleNs = 0;
    if (m_out.dropStale(key, ns, &staleNs))
        judge(staleNs, m_firstIn, &m_counts.unexplained);
    const qint64 gapNs = isSource ? 0 : copyGap(key, ns);
    qint64 otherNs = 0;
    switch (there.take(key, &otherNs)) {
    case End::Take::Unique:
        ++m_counts.matched;
        return isSource ? otherNs - ns : ns - otherNs;
    case End::Take::Ambiguous:
        ++m_counts.ambiguous;
        return std::nullopt;
    case End::Take::None:
        break;
    }
    if (!here.add(key, ns, gapNs, m_limits.maxPending))
        ++m_counts.overflow;
    return std::nullopt;
}

std::optional<qint64> ContentMatcher::source(const ContentKey& key, qint64 ns)
{
    ++m_counts.sources;
    if (!m_firstIn)
        m_firstIn = ns;
    return arrive(m_in, m_out, key, ns, true);
}

std::optional<qint64> ContentMatcher::destination(const ContentKey& key, qint64 ns)
{
    ++m_counts.destinations;
    if (!m_firstOut)
        m_firstOut = ns;
    return arrive(m_out, m_in, key, ns, false);
}

void ContentMatcher::restart()
{
    m_in.clear();
    m_out.clear();
    m_firstIn.reset();
    m_firstOut.reset();
    m_lastOut.reset();
}

void ContentMatcher::clear()
{
    restart();
    m_counts = {};
}
