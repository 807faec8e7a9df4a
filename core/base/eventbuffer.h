// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <mutex>
#include <QtGlobal>
#include <vector>

/// A bounded hand-over buffer between a network thread and the GUI thread.
///
/// Network threads (Paho, roscpp spinners) push plain events under a short lock; the GUI thread
/// takes everything at once by swapping the vector out, and does all parsing outside the lock.
/// When the buffer is full, new events are dropped and counted; the count is shown, never hidden.
template<typename T> class EventBuffer
{
public:
    explicit EventBuffer(std::size_t maxEvents = 500000, std::size_t maxBytes = 512u * 1024u * 1024u)
        : m_maxEvents(maxEvents)
        , m_maxBytes(maxBytes)
    { }

    /// Adds an event of `bytes` size; false (and counted) when it had to be dropped.
    bool push(T&& event, std::size_t bytes = 0)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_events.size() >= m_maxEvents || m_bytes + bytes > m_maxBytes) {
            m_dropped.fetch_add(1, std::memory_order_relaxed);
            return false;
        }
        m_events.push_back(std::move(event));
        m_bytes += bytes;
        return true;
    }

    /// Everything pushed since the last call, oldest first.
    std::vector<T> take()
    {
        std::vector<T> out;
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            out.swap(m_events);
            m_bytes = 0;
        }
        return out;
    }

    quint64 dropped() const { return m_dropped.load(std::memory_order_relaxed); }
    std::size_t maxEvents() const { return m_maxEvents; }

private:
    std::mutex m_mutex;
    std::vector<T> m_events;
    std::size_t m_bytes = 0;
    std::size_t m_maxEvents;
    std::size_t m_maxBytes;
    std::atomic<quint64> m_dropped {0};
};
