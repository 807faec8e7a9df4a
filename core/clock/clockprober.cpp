// SPDX-License-Identifier: MIT
#include "clock/clockprober.h"

#include "base/wallclock.h"

#include <QRandomGenerator>

ClockProber::ClockProber(const QString& host, QObject* parent)
    : QObject(parent)
    , m_estimator(host)
{
    qRegisterMetaType<ClockEstimate>();
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &ClockProber::tick);
}

ClockProber::~ClockProber() = default;

void ClockProber::stop()
{
    m_timer.stop();
}

ClockProberCounters ClockProber::counters() const
{
    ClockProberCounters c = m_counters;
    c.pending = m_pending.size();
    return c;
}

bool ClockProber::isDone() const
{
    return m_options.count > 0 && m_counters.sent + m_counters.sendFailed >= m_options.count
        && m_pending.isEmpty();
}

void ClockProber::startProbing()
{
    m_finished = false;
    m_timer.start(m_options.burst > 1 ? ClockProberOptions::kBurstIntervalMs : m_options.intervalMs);
    sendOne();
}

void ClockProber::tick()
{
    expire(wallClockNs());
    const qint64 tried = m_counters.sent + m_counters.sendFailed;
    if (m_options.count > 0 && tried >= m_options.count) {
        // All sent: the timer now only waits for the last answers.
        if (m_pending.isEmpty()) {
            m_timer.stop();
            if (!m_finished) {
                m_finished = true;
                emit finished();
            }
        }
        return;
    }
    if (tried >= m_options.burst && m_timer.interval() != m_options.intervalMs)
        m_timer.setInterval(m_options.intervalMs);
    sendOne();
}

void ClockProber::sendOne()
{
    if (m_pending.size() >= ClockProberOptions::kMaxPending) {
        // The oldest is given up for lost: the bound holds whatever the far side does.
        auto oldest = m_pending.begin();
        for (auto it = m_pending.begin(); it != m_pending.end(); ++it)
            if (it.value() < oldest.value())
                oldest = it;
        m_pending.erase(oldest);
        ++m_counters.lost;
    }
    ClockProbe probe;
    probe.nonce = QRandomGenerator::global()->generate64();
    probe.name = host();
    prepare(probe);
    probe.t1 = wallClockNs();
    if (const Status sent = send(probe.encode()); sent.ok()) {
        m_pending.insert(probe.nonce, probe.t1);
        ++m_counters.sent;
    } else {
        m_lastSendError = sent.error().toString();
        ++m_counters.sendFailed;
    }
    emit countersChanged();
    if (m_options.count > 0 && m_counters.sent + m_counters.sendFailed >= m_options.count)
        m_timer.setInterval(qMin(m_options.intervalMs, 100)); // now only waiting: look often
}

void ClockProber::expire(qint64 nowNs)
{
    const qint64 limit = nowNs - qint64(m_options.answerTimeoutMs) * 1'000'000;
    bool any = false;
    for (auto it = m_pending.begin(); it != m_pending.end();) {
        if (it.value() < limit) {
            it = m_pending.erase(it);
            ++m_counters.lost;
            any = true;
        } else {
            ++it;
        }
    }
    if (any)
        emit countersChanged();
}

void ClockProber::received(const QByteArray& bytes, qint64 t4Ns)
{
    const Result<ClockProbe> answer = ClockProbe::decode(bytes);
    if (!answer.ok() || answer->kind != ClockProbe::Kind::Answer) {
        ++m_counters.malformed;
        emit countersChanged();
        return;
    }
    const auto pending = m_pending.constFind(answer->nonce);
    if (pending == m_pending.cend() || pending.value() != answer->t1
        || (!host().isEmpty() && answer->name != host())) {
        countUnknown();
        return;
    }
    m_pending.erase(pending);
    ++m_counters.answered;
    m_farName = answer->name;
    m_farSync = answer->sync;
    m_estimator.add(answer->t1, answer->t2, answer->t3, t4Ns);
    emit countersChanged();
    if (m_estimator.accepted() > 0)
        emit estimateChanged(m_estimator.estimate(t4Ns));
}

void ClockProber::countUnknown()
{
    ++m_counters.unknown;
    emit countersChanged();
}
