// SPDX-License-Identifier: MIT
#pragma once

#include "latency/messagesource.h"

#include <functional>
#include <memory>

/// The open head taps of one MessageSource (MessageSource::openHeadTap()): every monitored
/// message's head goes into each tap's own bounded buffer, so that two consumers (a window's Watch
/// and another) never take each other's. Thread-safe: a transport thread delivers while the GUI
/// thread takes. Taps hold the hub's state weakly, so a tap destroyed after its source is harmless.
class HeadHub
{
public:
    /// `boundChanged(n)` when the largest bound of the open taps changes: 0 once the last one
    /// closes (called without the hub's lock, on the thread that opens or destroys the tap).
    explicit HeadHub(std::function<void(std::size_t largestBound)> boundChanged = {});
    ~HeadHub();
    HeadHub(const HeadHub&) = delete;
    HeadHub& operator=(const HeadHub&) = delete;

    std::unique_ptr<HeadTap> open(std::size_t maxHeads);
    /// True while a tap is open: a source checks it before it builds a head.
    bool active() const;
    /// Puts `head` into every open tap (a full tap drops it and counts it).
    void deliver(SourceHead&& head);
    /// Heads dropped before they reached this hub (a child process's own bound): counted in every
    /// tap open now.
    void addDroppedUpstream(quint64 heads);

private:
    struct State;
    class HubHeadTap;
    std::shared_ptr<State> m_state;
};
