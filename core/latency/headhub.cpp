// SPDX-License-Identifier: MIT
#include "headhub.h"

#include "base/eventbuffer.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <vector>

namespace {
struct HeadQueue
{
    explicit HeadQueue(std::size_t maxHeads)
        : heads(maxHeads)
    { }
    EventBuffer<SourceHead> heads; ///< locks itself
    std::atomic<quint64> droppedUpstream {0};
};
} // namespace

struct HeadHub::State
{
    mutable std::mutex mutex;
    std::vector<std::shared_ptr<HeadQueue>> taps; ///< under `mutex`
    std::atomic<int> open {0}; ///< taps.size(), read without the lock
    std::function<void(std::size_t)> boundChanged;

    /// Under `mutex`.
    std::size_t largestBound() const
    {
        std::size_t n = 0;
        for (const auto& q : taps)
            n = std::max(n, q->heads.maxEvents());
        return n;
    }
};

class HeadHub::HubHeadTap : public HeadTap
{
public:
    HubHeadTap(std::weak_ptr<State> state, std::shared_ptr<HeadQueue> queue)
        : m_state(std::move(state))
        , m_queue(std::move(queue))
    { }

    ~HubHeadTap() override
    {
        const std::shared_ptr<State> state = m_state.lock();
        if (!state)
            return; // the source went first
        std::function<void(std::size_t)> changed; // called without the lock
        std::size_t bound = 0;
        {
            std::lock_guard<std::mutex> lock(state->mutex);
            const std::size_t before = state->largestBound();
            auto& taps = state->taps;
            taps.erase(std::remove(taps.begin(), taps.end(), m_queue), taps.end());
            state->open.store(int(taps.size()), std::memory_order_relaxed);
            bound = state->largestBound();
            if (bound != before)
                changed = state->boundChanged;
        }
        if (changed)
            changed(bound);
    }

    std::vector<SourceHead> take() override { return m_queue->heads.take(); }

    quint64 dropped() const override
    {
        return m_queue->heads.dropped() + m_queue->droppedUpstream.load(std::memory_order_relaxed);
    }

private:
    std::weak_ptr<State> m_state;
    std::shared_ptr<HeadQueue> m_queue;
};

HeadHub::HeadHub(std::function<void(std::size_t largestBound)> boundChanged)
    : m_state(std::make_shared<State>())
{
    m_state->boundChanged = std::move(boundChanged);
}

HeadHub::~HeadHub()
{
    // Taps still open see the state go (their weak pointer) and end without calling back.
    std::lock_guard<std::mutex> lock(m_state->mutex);
    m_state->boundChanged = nullptr;
}

std::unique_ptr<HeadTap> HeadHub::open(std::size_t maxHeads)
{
    auto queue = std::make_shared<HeadQueue>(std::max<std::size_t>(1, maxHeads));
    std::function<void(std::size_t)> changed; // called without the lock
    std::size_t bound = 0;
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        const std::size_t before = m_state->largestBound();
        m_state->taps.push_back(queue);
        m_state->open.store(int(m_state->taps.size()), std::memory_order_relaxed);
        bound = m_state->largestBound();
        if (bound != before)
            changed = m_state->boundChanged;
    }
    if (changed)
        changed(bound);
    return std::make_unique<HubHeadTap>(m_state, std::move(queue));
}

bool HeadHub::active() const
{
    return m_state->open.load(std::memory_order_relaxed) > 0;
}

void HeadHub::deliver(SourceHead&& head)
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    const std::size_t n = m_state->taps.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (i + 1 == n)
            m_state->taps[i]->heads.push(std::move(head));
        else
            m_state->taps[i]->heads.push(SourceHead(head));
    }
}

void HeadHub::addDroppedUpstream(quint64 heads)
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    for (const auto& q : m_state->taps)
        q->droppedUpstream.fetch_add(heads, std::memory_order_relaxed);
}
