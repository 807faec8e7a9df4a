// SPDX-License-Identifier: MIT
#pragma once

#include <deque>
#include <QtGlobal>
#include <utility>
#include <vector>

/// The newest items of a stream, bounded by count and bytes between two take() calls.
///
/// Unlike EventBuffer, which refuses what comes when full, a push over either bound drops the
/// oldest items (and counts them): a plot wants the latest values. Not locked: its owner keeps it
/// under the lock its network thread writes with (RosMonitor's, Ros2Participant's).
template<typename T> class NewestQueue
{
public:
    explicit NewestQueue(std::size_t maxItems = 0, qint64 maxBytes = 0)
        : m_maxItems(maxItems)
        , m_maxBytes(maxBytes)
    { }

    void setLimits(std::size_t maxItems, qint64 maxBytes)
    {
        m_maxItems = maxItems;
        m_maxBytes = maxBytes;
        trim();
    }

    /// Adds an item of `bytes` size, dropping the oldest while a bound is exceeded (the item
    /// itself when it alone is larger than maxBytes).
    void push(T item, qint64 bytes)
    {
        m_items.push_back({std::move(item), bytes});
        m_bytes += bytes;
        trim();
    }

    /// Everything kept since the last call, oldest first.
    std::vector<T> take()
    {
        std::vector<T> out;
        out.reserve(m_items.size());
        for (Entry& e : m_items)
            out.push_back(std::move(e.item));
        m_items.clear();
        m_bytes = 0;
        return out;
    }

    std::size_t size() const { return m_items.size(); }
    /// Items dropped because a bound was hit, since the queue was made.
    quint64 dropped() const { return m_dropped; }

private:
    struct Entry
    {
        T item;
        qint64 bytes = 0;
    };

    void trim()
    {
        while (!m_items.empty() && (m_items.size() > m_maxItems || m_bytes > m_maxBytes)) {
            m_bytes -= m_items.front().bytes;
            m_items.pop_front();
            ++m_dropped;
        }
    }

    std::deque<Entry> m_items;
    std::size_t m_maxItems;
    qint64 m_maxBytes;
    qint64 m_bytes = 0;
    quint64 m_dropped = 0;
};
