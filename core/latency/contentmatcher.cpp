// SPDX-License-Identifier: MIT
#include "contentmatcher.h"

#include <algorithm>

ContentKey ContentKey::of(QByteArrayView bytes)
{
    ContentKey key;
    key.size = bytes.size();
    key.hash = qHashBits(bytes.data(), size_t(std::min(bytes.size(), kHashedBytes)), 0);
    return key;
}

std::optional<ContentKey> ContentKey::ofPayload(QByteArrayView payload, qsizetype stampBytes)
{
    if (stampBytes < 0 || payload.size() < stampBytes)
        return std::nullopt;
    return of(payload.sliced(stampBytes));
}

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
        ++it->taken; // the oldest untaken ones are the taken ones: expiry tells them from the lost
        return Take::Ambiguous;
    }
    Entry& e = m_entries[std::size_t(it->firstSeq - m_base)];
    e.taken = true;
    *ns = e.ns;
    m_slots.erase(it); // it was the only one waiting
    return Take::Unique;
}

bool ContentMatcher::End::add(const ContentKey& key, qint64 ns, std::size_t maxPending)
{
    bool droppedUnmatched = false;
    while (m_entries.size() >= maxPending) {
        bool unmatched = false;
        expireOldest(0, true, &unmatched);
        droppedUnmatched = droppedUnmatched || unmatched;
    }
    const quint64 seq = m_base + m_entries.size();
    m_entries.push_back({key, ns, false});
    Slot& slot = m_slots[key];
    if (slot.waiting == 0)
        slot.firstSeq = seq;
    else
        slot.ambiguous = true; // another with the key waits, or was consumed without being told apart
    ++slot.waiting;
    return !droppedUnmatched;
}

bool ContentMatcher::End::expireOldest(qint64 beforeNs, bool force, bool* unmatched)
{
    *unmatched = false;
    if (m_entries.empty() || (!force && m_entries.front().ns >= beforeNs))
        return false;
    const Entry e = m_entries.front();
    m_entries.pop_front();
    ++m_base;
    if (e.taken)
        return true;
    const auto it = m_slots.find(e.key);
    Q_ASSERT(it != m_slots.end());
    if (it->taken > 0)
        --it->taken; // consumed by an ambiguous match
    else
        *unmatched = true;
    if (--it->waiting == 0)
        m_slots.erase(it);
    return true;
}

void ContentMatcher::End::clear()
{
    m_entries.clear();
    m_slots.clear();
    m_base = 0;
}

void ContentMatcher::expire(qint64 nowNs)
{
    const qint64 before = nowNs - m_limits.maxWaitNs;
    bool unmatched = false;
    while (m_in.expireOldest(before, false, &unmatched))
        m_counts.lost += unmatched;
    while (m_out.expireOldest(before, false, &unmatched))
        m_counts.unexplained += unmatched;
}

std::optional<qint64> ContentMatcher::arrive(End& here, End& there, const ContentKey& key, qint64 ns,
                                             bool isSource)
{
    expire(ns);
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
    if (!here.add(key, ns, m_limits.maxPending))
        ++m_counts.overflow;
    return std::nullopt;
}

std::optional<qint64> ContentMatcher::source(const ContentKey& key, qint64 ns)
{
    ++m_counts.sources;
    return arrive(m_in, m_out, key, ns, true);
}

std::optional<qint64> ContentMatcher::destination(const ContentKey& key, qint64 ns)
{
    ++m_counts.destinations;
    return arrive(m_out, m_in, key, ns, false);
}

void ContentMatcher::clear()
{
    m_in.clear();
    m_out.clear();
    m_counts = {};
}
