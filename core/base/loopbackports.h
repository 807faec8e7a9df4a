// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <QList>
#include <QtGlobal>

/// Ports on 127.0.0.1 for servers we start ourselves (the demo lab, the tests).
namespace LoopbackPorts {
/// A port nothing listens on right now (0 when none could be found).
quint16 freePort();
/// A free port that is none of `taken`: the ports handed to servers that may not listen yet (a
/// mosquitto just launched leaves its port free, and the kernel may hand it out again: the demo
/// lab's broker and master once got the same port).
quint16 freePort(const QList<quint16>& taken);
/// Whether a UDP socket can be bound to `port` on 127.0.0.1 now (a DDS domain's discovery port).
bool isUdpFree(quint16 port);
/// Waits until something accepts connections on `port`, at most `timeoutMs` and while
/// `keepWaiting` (if given) holds.
bool waitForListener(quint16 port, int timeoutMs, const std::function<bool()>& keepWaiting = {});
} // namespace LoopbackPorts
