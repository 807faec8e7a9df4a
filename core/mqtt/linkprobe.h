// SPDX-License-Identifier: MIT
#pragma once

#include "latency/latencystats.h"
#include "mqtt/mqttprofile.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <QCoreApplication>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <thread>
#include <utility>
#include <vector>

/// What a link probe sends, how fast, and how a sweep raises the rate.
struct LinkProbeOptions
{
    static constexpr int kHeaderBytes = 24; ///< magic, run, sequence number, send time
    static constexpr int kMaxPayloadBytes = 256 * 1024 * 1024 - 1024; ///< MQTT's limit, less the header

    MqttProfile profile;
    int payloadBytes = 1024; ///< whole payload, header included
    double rateHz = 10; ///< the rate of a plain run; the first step of a sweep
    int qos = 0;
    qint64 count = 100; ///< messages of a plain run
    bool viaEcho = false; ///< listen to .../pong (an echo client's copies) instead of .../ping
    int drainMs = 2000; ///< how long to wait for stragglers after the last send
    // Sweep
    double maxRateHz = 5000;
    double rateFactor = 1.5; ///< each step's rate is the previous one's times this
    double stepSeconds = 1.0; ///< each step lasts about this long (at least kMinStepMessages messages)
    double sweepSeconds = 30; ///< the whole sweep stops after this long
    double maxLossPercent = 1.0;
    bool keepArrivals = false; ///< collect every round trip for LinkProbe::takeProgress() (live views)

    static constexpr qint64 kMinStepMessages = 20;
    static constexpr qint64 kMaxStepMessages = 5000;

    /// Checks sizes, rates, counts and QoS; the message names the option.
    Status validate() const;
};

/// The outcome of sending at one rate: counts and the round trip times.
struct LinkProbeStep
{
    double rateHz = 0; ///< asked for
    double sentRateHz = 0; ///< achieved by the sender
    qint64 sent = 0;
    qint64 received = 0; ///< distinct messages that came back
    qint64 lost = 0; ///< sent - received
    qint64 outOfOrder = 0; ///< came back after a message sent later
    qint64 duplicates = 0; ///< came back more than once (QoS 0 and 1 allow it)
    LatencyStats rtt; ///< ms, as the latency engine computes them
    bool interrupted = false; ///< stopped before it was done

    double lossPercent() const { return sent > 0 ? 100.0 * double(lost) / double(sent) : 0; }
};

/// The outcome of a plain run (one step) or of a sweep (one step per rate).
struct LinkProbeReport
{
    QString error; ///< why it could not run (broker unreachable, ...); empty when it ran
    QString clientId;
    QString sendTopic;
    QString receiveTopic;
    int payloadBytes = 0;
    bool sweep = false;
    std::vector<LinkProbeStep> steps;
    int best = -1; ///< sweep: index of the highest sustainable step, -1 when none was
    QString sweepEnd; ///< sweep: why it stopped raising the rate
    bool interrupted = false;

    qint64 received() const;
    /// The step the summary describes: the best of a sweep (or its first), the only one of a run.
    const LinkProbeStep* summary() const;
    double maxRateHz() const;
    /// payload × max rate, in MB/s (10^6 bytes).
    double throughputMBs() const;
};

/// What the running step has counted so far, and the round trips that came back since last asked.
struct LinkProbeProgress
{
    int step = -1; ///< index of the step running now, or of the last one (0 in a plain run); -1 before
    double rateHz = 0;
    qint64 sent = 0;
    qint64 received = 0;
    qint64 outOfOrder = 0;
    qint64 duplicates = 0;
    /// Round trips (ns, arrival order) since the previous takeProgress(), each with its step.
    std::vector<std::pair<int, qint64>> rttNs;
};

Q_DECLARE_METATYPE(LinkProbeStep)
Q_DECLARE_METATYPE(LinkProbeReport)

/// Round trips through a broker, timed where Paho hands the message over.
///
/// A worker thread connects with its own Paho client, paces the sends and waits for stragglers;
/// Paho's callback thread stamps each arrival (steady clock) and counts it under a short lock. No
/// event loop sits between the socket and the clock. A message carries a magic, the run, its
/// sequence number and the wall-clock send time (ns), padded to the payload size. Echo mode
/// answers other probes: each payload from bridgescope/probe/+/ping goes back unchanged on
/// .../pong. Results arrive as signals on the thread that owns the probe.
class LinkProbe : public QObject
{
    Q_OBJECT
public:
    explicit LinkProbe(QObject* parent = nullptr);
    ~LinkProbe() override;

    static QString pingTopic(const QString& clientId);
    static QString pongTopic(const QString& clientId);
    static QString echoFilter(); ///< what an echo client subscribes

    /// A plain run: options.count messages at options.rateHz.
    void start(const LinkProbeOptions& options);
    /// Raises the rate step by step until the link does not keep up.
    void startSweep(const LinkProbeOptions& options);
    /// Echoes pings back as pongs until stop().
    void startEcho(const LinkProbeOptions& options);
    /// Stops sending; `finished` follows with what was measured so far.
    void stop();
    bool isRunning() const { return m_worker.joinable() && !m_done; }
    /// Echo mode: payloads sent back so far (any thread).
    qint64 echoed() const { return m_echoed.load(); }
    /// The current step's counts, and the round trips since the last call (any thread, a short
    /// lock). Round trips are collected only with LinkProbeOptions::keepArrivals; they stay here
    /// after `finished` until taken.
    LinkProbeProgress takeProgress();

signals:
    void connected(const QString& clientId);
    void stepFinished(const LinkProbeStep& step);
    void finished(const LinkProbeReport& report);

private:
    struct Run;
    struct Live
    {
        std::mutex mutex;
        LinkProbeProgress progress;
    };
    void launch(const LinkProbeOptions& options, int mode);
    void join();

    std::thread m_worker;
    std::atomic<bool> m_stop {false};
    std::atomic<qint64> m_echoed {0};
    Live m_live;
    bool m_done = false;
    quint64 m_generation = 0; ///< tells a replaced run's late result from the current one
};
