// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "clock/clockestimate.h"
#include "clock/clockestimator.h"
#include "clock/clockprobe.h"
#include "clock/clocksync.h"

#include <QHash>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QTimer>

/// How often a prober probes.
struct ClockProberOptions
{
    int burst = 8; ///< probes at the start, kBurstIntervalMs apart
    int intervalMs = 1000; ///< then one per interval
    qint64 count = 0; ///< probes in all, then it stops (0: until stop())
    int answerTimeoutMs = 2000; ///< an answer later than this is lost (and counted late if it comes)

    static constexpr int kBurstIntervalMs = 50; ///< 20 Hz: within the service's per-peer budget
    static constexpr int kMaxPending = 64; ///< probes awaiting an answer; beyond, the oldest is lost
};

/// What a prober has counted.
struct ClockProberCounters
{
    qint64 sent = 0;
    qint64 answered = 0; ///< answers that matched a probe (the estimator may still refuse them)
    qint64 lost = 0; ///< no answer within the timeout
    qint64 unknown = 0; ///< answers to no probe of ours (late, duplicated, foreign) or from another host
    qint64 malformed = 0; ///< not an answer
    qint64 sendFailed = 0;
    qint64 pending = 0; ///< sent and still awaited
};

/// Probes one far host's clock service and keeps its clock estimate (ClockEstimator): a burst of
/// probes at the start, then one per interval; answers are matched by nonce and fed to the
/// estimator, and each new estimate is signalled. Event-driven (timers and socket signals, no
/// waits), so it runs on the GUI thread. t1 and t4 come from wallClockNs() as close to the send
/// and the receipt as the transport allows. The transport is a subclass's: UdpClockProber
/// (core/clock), MqttClockProber (core/mqtt).
class ClockProber : public QObject
{
    Q_OBJECT
public:
    /// `host`: the far host's name, as pipelines name it (also the estimate's `host`).
    explicit ClockProber(const QString& host, QObject* parent = nullptr);
    ~ClockProber() override;

    void setOptions(const ClockProberOptions& options) { m_options = options; }
    const ClockProberOptions& options() const { return m_options; }
    const QString& host() const { return m_estimator.host(); }

    /// Starts probing (after the transport is ready: subclasses call startProbing()).
    virtual void start() = 0;
    /// Stops sending; answers still on their way are counted when they come.
    virtual void stop();
    bool isProbing() const { return m_timer.isActive(); }

    /// The estimate at `nowNs` (our wall clock); invalid before the first answer.
    ClockEstimate estimate(qint64 nowNs) const { return m_estimator.estimate(nowNs); }
    const ClockEstimator& estimator() const { return m_estimator; }
    ClockProberCounters counters() const;
    /// The far host's own sync state, from its latest answer.
    const ClockSyncState& farSyncState() const { return m_farSync; }
    /// The name the far host answers with (empty until it answered).
    const QString& farName() const { return m_farName; }
    /// Why the last probe that could not be sent was not (empty when none failed).
    const QString& lastSendError() const { return m_lastSendError; }
    /// What keeps the transport from working now (a broker not reached, and why); empty when it works.
    const QString& transportProblem() const { return m_transportProblem; }
    /// Whether every probe asked for (options().count) was sent and none is still awaited.
    bool isDone() const;

signals:
    void estimateChanged(const ClockEstimate& estimate);
    /// Counters changed (a probe sent, lost, answered, or something unknown arrived).
    void countersChanged();
    /// The transport failed (cannot bind, cannot connect); it says why.
    void failed(const QString& why);
    /// The last probe was answered or lost (only with options().count).
    void finished();

protected:
    /// Sends the probe's bytes, or says why it could not.
    virtual Status send(const QByteArray& bytes) = 0;
    /// What the transport adds to a probe (the reply topic over MQTT).
    virtual void prepare(ClockProbe& probe) { Q_UNUSED(probe) }
    /// The transport is ready: the burst begins.
    void startProbing();
    void setTransportProblem(const QString& problem) { m_transportProblem = problem; }
    /// An answer's bytes, received at `t4Ns` (our wall clock, taken as soon as they were read).
    void received(const QByteArray& bytes, qint64 t4Ns);
    /// Something arrived that cannot be an answer to us (another sender): counted as unknown.
    void countUnknown();

private:
    void tick();
    void sendOne();
    void expire(qint64 nowNs);

    ClockProberOptions m_options;
    ClockEstimator m_estimator;
    QTimer m_timer;
    QHash<quint64, qint64> m_pending; ///< nonce -> t1
    ClockProberCounters m_counters;
    ClockSyncState m_farSync;
    QString m_farName;
    QString m_lastSendError;
    QString m_transportProblem;
    bool m_finished = false;
};

Q_DECLARE_METATYPE(ClockEstimate)
