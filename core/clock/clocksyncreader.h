// SPDX-License-Identifier: MIT
#pragma once

#include "clock/clocksync.h"

#include <atomic>
#include <memory>
#include <QObject>
#include <QTimer>

class QThread;

/// Keeps the host's sync state (ClockSync::read) fresh: reads it now and every `intervalMs` on a
/// thread of its own, never on its owner's, and hands each result over as `stateChanged`.
class ClockSyncReader : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMs = 60'000;

    explicit ClockSyncReader(int intervalMs = kDefaultIntervalMs, QObject* parent = nullptr);
    ~ClockSyncReader() override;

    void start();
    /// The latest state read ("not reported" until the first read is done).
    const ClockSyncState& state() const { return m_state; }

signals:
    /// After the first read, and whenever a read differs from the one before.
    void stateChanged(const ClockSyncState& state);

private:
    void readNow();

    QTimer m_timer;
    QThread* m_thread = nullptr; ///< the read under way, if any
    ClockSyncState m_state;
    bool m_read = false; ///< the first read is always handed over, "not reported" too
};
