// SPDX-License-Identifier: MIT
#include "taphub.h"

#include "base/newestqueue.h"

#include <algorithm>
#include <mutex>
#include <QHash>
#include <vector>

namespace {
/// One tap's queue: its own lock, so that a take never waits for another topic's delivery.
struct Queue
{
    mutable std::mutex mutex;
    NewestQueue<SourceArrival> items;
};
} // namespace

struct TapHub::State
{
    mutable std::mutex mutex;
    QHash<QString, std::vector<std::shared_ptr<Queue>>> taps; ///< under `mutex`
    std::function<void(const QString&, bool)> tappedChanged;
};

class TapHub::HubTap : public Tap
{
public:
    HubTap(std::weak_ptr<State> state, QString topic, std::shared_ptr<Queue> queue)
        : m_state(std::move(state))
        , m_topic(std::move(topic))
        , m_queue(std::move(queue))
    { }

    ~HubTap() override
    {
        const std::shared_ptr<State> state = m_state.lock();
        if (!state)
            return; // the source went first
        std::function<void(const QString&, bool)> untapped; // called without the lock
        {
            std::lock_guard<std::mutex> lock(state->mutex);
            const auto it = state->taps.find(m_topic);
            if (it == state->taps.end())
                return;
            auto& list = it.value();
            list.erase(std::remove(list.begin(), list.end(), m_queue), list.end());
            if (list.empty()) {
                state->taps.erase(it);
                untapped = state->tappedChanged;
            }
        }
        if (untapped)
            untapped(m_topic, false);
    }

    std::vector<SourceArrival> take() override
    {
        std::lock_guard<std::mutex> lock(m_queue->mutex);
        return m_queue->items.take();
    }

    quint64 dropped() const override
    {
        std::lock_guard<std::mutex> lock(m_queue->mutex);
        return m_queue->items.dropped();
    }

private:
    std::weak_ptr<State> m_state;
    QString m_topic;
    std::shared_ptr<Queue> m_queue;
};

TapHub::TapHub(std::function<void(const QString& topic, bool tapped)> tappedChanged)
    : m_state(std::make_shared<State>())
{
    m_state->tappedChanged = std::move(tappedChanged);
}

TapHub::~TapHub()
{
    // Taps still open see the state go (their weak pointer) and end without calling back.
    std::lock_guard<std::mutex> lock(m_state->mutex);
    m_state->tappedChanged = nullptr;
}

std::unique_ptr<Tap> TapHub::open(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    auto queue = std::make_shared<Queue>();
    queue->items.setLimits(maxMessages, maxBytes);
    std::function<void(const QString&, bool)> tapped; // called without the lock
    {
        std::lock_guard<std::mutex> lock(m_state->mutex);
        auto& list = m_state->taps[topic];
        if (list.empty())
            tapped = m_state->tappedChanged;
        list.push_back(queue);
    }
    if (tapped)
        tapped(topic, true);
    return std::make_unique<HubTap>(m_state, topic, std::move(queue));
}

bool TapHub::tapped(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    return m_state->taps.contains(topic);
}

bool TapHub::empty() const
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    return m_state->taps.isEmpty();
}

bool TapHub::deliver(const SourceArrival& message)
{
    std::lock_guard<std::mutex> lock(m_state->mutex);
    const auto it = m_state->taps.constFind(message.topic);
    if (it == m_state->taps.cend())
        return false;
    for (const std::shared_ptr<Queue>& q : it.value()) {
        std::lock_guard<std::mutex> queueLock(q->mutex);
        q->items.push(message, message.bytes.size());
    }
    return true;
}
