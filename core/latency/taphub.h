// SPDX-License-Identifier: MIT
#pragma once

#include "latency/messagesource.h"

#include <functional>
#include <memory>
#include <QString>

/// The open taps of one MessageSource, by topic: what a source delivers a message to (each tap's
/// own bounded queue; the bytes shared, not copied). Thread-safe: a transport thread (roscpp's)
/// delivers while the GUI thread takes. Taps hold the hub's state weakly, so a tap destroyed after
/// its source is harmless.
class TapHub
{
public:
    /// `tappedChanged(topic, true)` when a topic gets its first tap, `false` when its last one
    /// closes (called without the hub's lock, on the thread that opens or destroys the tap).
    explicit TapHub(std::function<void(const QString& topic, bool tapped)> tappedChanged = {});
    ~TapHub();
    TapHub(const TapHub&) = delete;
    TapHub& operator=(const TapHub&) = delete;

    std::unique_ptr<Tap> open(const QString& topic, std::size_t maxMessages, qint64 maxBytes);
    bool tapped(const QString& topic) const;
    bool empty() const;
    /// Puts `message` into every tap of its topic; false when none is open.
    bool deliver(const SourceArrival& message);

private:
    struct State;
    class HubTap;
    std::shared_ptr<State> m_state;
};
