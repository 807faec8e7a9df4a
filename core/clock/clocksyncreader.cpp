// SPDX-License-Identifier: MIT
#include "clock/clocksyncreader.h"

#include <QPointer>
#include <QThread>

ClockSyncReader::ClockSyncReader(int intervalMs, QObject* parent)
    : QObject(parent)
{
    m_timer.setInterval(intervalMs);
    connect(&m_timer, &QTimer::timeout, this, &ClockSyncReader::readNow);
}

ClockSyncReader::~ClockSyncReader()
{
    m_timer.stop();
    if (m_thread) {
        // A read takes at most two programs' timeouts.
        m_thread->wait();
        delete m_thread;
    }
}

void ClockSyncReader::start()
{
    m_timer.start();
    readNow();
}

void ClockSyncReader::readNow()
{
    if (m_thread)
        return; // the last one is still reading
    auto result = std::make_shared<ClockSyncState>();
    m_thread = QThread::create([result] { *result = ClockSync::read(); });
    connect(m_thread, &QThread::finished, this, [this, result] {
        m_thread->deleteLater();
        m_thread = nullptr;
        const bool changed = !m_read || !(*result == m_state);
        m_read = true;
        m_state = *result;
        if (changed)
            emit stateChanged(m_state);
    });
    m_thread->start();
}
