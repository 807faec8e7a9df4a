// SPDX-License-Identifier: MIT
#include "linkprobe.h"

#include "base/wallclock.h"
#include "latency/latencyseries.h"
#include "mqtt/mqttlink.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
constexpr char kMagic[4] = {'B', 'S', 'P', 'R'};
enum Mode { Plain = 0, Sweep = 1, Echo = 2 };

qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

/// Sleeps until `deadlineNs` (steady clock) in short slices, so that a stop is seen soon.
void sleepUntil(qint64 deadlineNs, const std::atomic<bool>& stop)
{
    for (;;) {
        const qint64 left = deadlineNs - steadyNs();
        if (left <= 0 || stop)
            return;
        std::this_thread::sleep_for(std::chrono::nanoseconds(std::min<qint64>(left, 50'000'000)));
    }
}

/// One step's book-keeping, shared between the sender and Paho's callback thread.
struct StepBook
{
    quint32 run = 0; ///< arrivals of other runs (stragglers of an earlier step) are ignored
    std::vector<qint64> sentAt; ///< steady ns per sequence number, -1 until sent
    std::vector<quint8> seen;
    qint64 sent = 0;
    qint64 received = 0;
    qint64 duplicates = 0;
    qint64 outOfOrder = 0;
    qint64 maxSeq = -1;
    std::vector<qint64> rttNs; ///< in arrival order
};
} // namespace

struct LinkProbe::Run
{
    LinkProbe* owner;
    LinkProbeOptions options;
    int mode = Plain;
    std::atomic<bool>& stop;
    std::atomic<qint64>& echoed;
    Live* live; ///< null unless the options keep arrivals

    std::mutex mutex;
    std::condition_variable changed;
    StepBook book;
    bool lost = false; ///< the connection dropped
    QString lostWhy;
    QString sendError; ///< why the last publish failed

    LinkProbeReport report;
    std::unique_ptr<MqttLink> link;

    Run(LinkProbe* o, LinkProbeOptions opts, int m, std::atomic<bool>& s, std::atomic<qint64>& e, Live* l)
        : owner(o)
        , options(std::move(opts))
        , mode(m)
        , stop(s)
        , echoed(e)
        , live(options.keepArrivals ? l : nullptr)
    { }

    /// Hands the book's counts (and a round trip, when `rttNs` >= 0) to takeProgress(); `mutex` is held.
    void showLive(qint64 rttNs = -1)
    {
        if (!live)
            return;
        std::lock_guard<std::mutex> lock(live->mutex);
        LinkProbeProgress& p = live->progress;
        p.sent = book.sent;
        p.received = book.received;
        p.outOfOrder = book.outOfOrder;
        p.duplicates = book.duplicates;
        if (rttNs >= 0)
            p.rttNs.emplace_back(p.step, rttNs);
    }

    void post(const LinkProbeStep& step)
    {
        LinkProbe* o = owner;
        QMetaObject::invokeMethod(
            o, [o, step] { emit o->stepFinished(step); }, Qt::QueuedConnection);
    }

    /// `receivedWallNs` is when Paho handed the message over; round trips run on the steady clock.
    void onArrival(const QByteArray& data, qint64 receivedWallNs)
    {
        const qint64 now = steadyNs() - (wallClockNs() - receivedWallNs);
        if (data.size() < LinkProbeOptions::kHeaderBytes
            || std::memcmp(data.constData(), kMagic, sizeof kMagic) != 0)
            return;
        const auto* bytes = reinterpret_cast<const uchar*>(data.constData());
        const auto run = qFromLittleEndian<quint32>(bytes + 4);
        const auto seq = qFromLittleEndian<quint64>(bytes + 8);
        std::lock_guard<std::mutex> lock(mutex);
        if (run != book.run || seq >= book.sentAt.size() || book.sentAt[seq] < 0)
            return;
        if (book.seen[seq]) {
            ++book.duplicates;
            showLive();
            return;
        }
        book.seen[seq] = 1;
        ++book.received;
        book.rttNs.push_back(now - book.sentAt[seq]);
        if (qint64(seq) < book.maxSeq)
            ++book.outOfOrder;
        else
            book.maxSeq = qint64(seq);
        showLive(book.rttNs.back());
        if (book.received == book.sent)
            changed.notify_all();
    }

    void onEcho(const QString& topic, const QByteArray& payload)
    {
        if (!topic.endsWith(u"/ping"_s) || topic.size() <= 5)
            return;
        if (link->publish(topic.chopped(4) + u"pong"_s, payload, options.qos, false))
            echoed.fetch_add(1, std::memory_order_relaxed);
    }

    bool connect()
    {
        const MqttProfile& p = options.profile;
        // A probe reports a broken link rather than hiding it behind reconnects.
        link = std::make_unique<MqttLink>(p, MqttLink::Options {{}, false, 65535});
        report.clientId = link->clientId();
        const QString id = report.clientId;
        report.sendTopic = pingTopic(id);
        report.receiveTopic = mode == Echo ? echoFilter() : (options.viaEcho ? pongTopic(id) : pingTopic(id));
        report.payloadBytes = options.payloadBytes;
        report.sweep = mode == Sweep;
        link->setMessageHandler([this](const QString& topic, const QByteArray& payload, qint64 receivedNs) {
            if (mode == Echo)
                onEcho(topic, payload);
            else
                onArrival(payload, receivedNs);
        });
        link->setLostHandler([this](const QString& cause) {
            std::lock_guard<std::mutex> lock(mutex);
            lost = true;
            lostWhy = cause.isEmpty() ? tr("the connection to the broker was lost")
                                      : tr("the connection to the broker was lost: %1").arg(cause);
            changed.notify_all();
        });
        Status ready = link->connect(10000);
        if (ready)
            ready = link->subscribeAndWait(report.receiveTopic, options.qos, 5000);
        if (!ready)
            report.error = ready.error().toString();
        return ready.ok();
    }

    void disconnect() { link.reset(); }

    /// Sends `count` messages at `rateHz` and waits for them to come back.
    LinkProbeStep runStep(quint32 run, double rateHz, qint64 count)
    {
        LinkProbeStep step;
        step.rateHz = rateHz;
        {
            std::lock_guard<std::mutex> lock(mutex);
            book = StepBook();
            book.run = run;
            book.sentAt.assign(std::size_t(count), -1);
            book.seen.assign(std::size_t(count), 0);
            if (live) {
                std::lock_guard<std::mutex> liveLock(live->mutex);
                live->progress.step = int(report.steps.size());
                live->progress.rateHz = rateHz;
            }
            showLive();
        }
        std::string payload(std::size_t(options.payloadBytes), '\0');
        std::memcpy(payload.data(), kMagic, sizeof kMagic);
        qToLittleEndian<quint32>(run, payload.data() + 4);
        const QString& topic = report.sendTopic;
        const double intervalNs = 1e9 / rateHz;
        const qint64 start = steadyNs();
        qint64 firstSend = 0;
        qint64 lastSend = 0;
        qint64 i = 0;
        for (; i < count; ++i) {
            sleepUntil(start + qint64(double(i) * intervalNs), stop);
            if (stop)
                break;
            {
                std::lock_guard<std::mutex> lock(mutex);
                if (lost)
                    break;
            }
            qToLittleEndian<quint64>(quint64(i), payload.data() + 8);
            qToLittleEndian<qint64>(wallClockNs(), payload.data() + 16);
            const qint64 now = steadyNs();
            {
                std::lock_guard<std::mutex> lock(mutex);
                book.sentAt[std::size_t(i)] = now;
                book.sent = i + 1;
                showLive();
            }
            if (!publish(topic, payload)) {
                std::lock_guard<std::mutex> lock(mutex);
                book.sentAt[std::size_t(i)] = -1;
                book.sent = i;
                showLive();
                break;
            }
            if (i == 0)
                firstSend = now;
            lastSend = now;
        }
        step.interrupted = stop;

        // Stragglers: until everything is back, the wait is over, or (after a stop) briefly.
        constexpr qint64 kStopDrainNs = 300'000'000;
        qint64 deadline = steadyNs() + qint64(options.drainMs) * 1'000'000;
        {
            std::unique_lock<std::mutex> lock(mutex);
            while (book.received < book.sent && !lost) {
                const qint64 now = steadyNs();
                if (stop)
                    deadline = std::min(deadline, now + kStopDrainNs);
                const qint64 left = deadline - now;
                if (left <= 0)
                    break;
                changed.wait_for(lock, std::chrono::nanoseconds(std::min<qint64>(left, 50'000'000)));
            }
            step.sent = book.sent;
            step.received = book.received;
            step.duplicates = book.duplicates;
            step.outOfOrder = book.outOfOrder;
            step.lost = book.sent - book.received;
            LatencySeries series;
            series.setWindow(0);
            for (const qint64 rtt : book.rttNs)
                series.append(rtt);
            step.rtt = series.stats();
            book.run = 0; // whatever comes later belongs to no step
        }
        step.sentRateHz = step.sent > 1 && lastSend > firstSend
            ? double(step.sent - 1) * 1e9 / double(lastSend - firstSend)
            : (step.sent == 1 ? rateHz : 0);
        step.interrupted = step.interrupted || stop;
        return step;
    }

    bool publish(const QString& topic, const std::string& payload)
    {
        // Paho refuses more than max_inflight unacknowledged (QoS 1/2) or too many unwritten
        // messages: wait for room, so an overloaded step shows as a sender falling behind.
        for (;;) {
            switch (link->tryPublish(topic, payload.data(), qsizetype(payload.size()), options.qos, false,
                                     &sendError)) {
            case MqttLink::Sent::Ok:
                return true;
            case MqttLink::Sent::Failed:
                return false;
            case MqttLink::Sent::Full:
                if (stop)
                    return false;
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                break;
            }
        }
    }

    void runPlain() { report.steps.push_back(runStep(1, options.rateHz, options.count)); }

    void runSweep()
    {
        const qint64 start = steadyNs();
        double rate = options.rateHz;
        double firstMedian = LatencyStats::nan();
        for (quint32 run = 1;; ++run) {
            const qint64 count
                = std::clamp<qint64>(std::llround(rate * options.stepSeconds),
                                     LinkProbeOptions::kMinStepMessages, LinkProbeOptions::kMaxStepMessages);
            const LinkProbeStep step = runStep(run, rate, count);
            report.steps.push_back(step);
            post(step);
            if (step.interrupted) {
                report.sweepEnd = tr("stopped");
                break;
            }
            const double median = step.rtt.median;
            if (run == 1)
                firstMedian = median;
            // Loopback round trips of a tenth of a millisecond would make 10x meaningless: 10 ms at least.
            const double limitMs = std::min(1000.0, std::max(10.0 * firstMedian, 10.0));
            if (step.received == 0) {
                report.sweepEnd = tr("nothing came back at %1 Hz").arg(rate, 0, 'f', 1);
                break;
            }
            if (step.lossPercent() > options.maxLossPercent) {
                report.sweepEnd
                    = tr("%1 % lost at %2 Hz").arg(step.lossPercent(), 0, 'f', 1).arg(rate, 0, 'f', 1);
                break;
            }
            if (!(median <= limitMs)) {
                report.sweepEnd = tr("median round trip %1 ms at %2 Hz (limit %3 ms)")
                                      .arg(median, 0, 'f', 2)
                                      .arg(rate, 0, 'f', 1)
                                      .arg(limitMs, 0, 'f', 1);
                break;
            }
            if (step.sentRateHz < 0.9 * rate) {
                report.sweepEnd = tr("the sender reached only %1 of %2 Hz")
                                      .arg(step.sentRateHz, 0, 'f', 1)
                                      .arg(rate, 0, 'f', 1);
                break;
            }
            report.best = int(report.steps.size()) - 1;
            if (rate >= options.maxRateHz) {
                report.sweepEnd = tr("reached the maximum rate of %1 Hz").arg(options.maxRateHz);
                break;
            }
            if (double(steadyNs() - start) / 1e9 >= options.sweepSeconds) {
                report.sweepEnd = tr("reached the time limit of %1 s").arg(options.sweepSeconds);
                break;
            }
            rate = std::min(rate * options.rateFactor, options.maxRateHz);
        }
    }

    void runEcho()
    {
        std::unique_lock<std::mutex> lock(mutex);
        while (!stop && !lost)
            changed.wait_for(lock, std::chrono::milliseconds(50));
    }

    void execute()
    {
        if (connect()) {
            LinkProbe* o = owner;
            const QString id = report.clientId;
            QMetaObject::invokeMethod(
                o, [o, id] { emit o->connected(id); }, Qt::QueuedConnection);
            if (mode == Echo)
                runEcho();
            else if (mode == Sweep)
                runSweep();
            else
                runPlain();
            std::lock_guard<std::mutex> lock(mutex);
            if (lost)
                report.error = lostWhy;
            else if (!sendError.isEmpty())
                report.error = sendError;
        }
        report.interrupted = stop;
        disconnect();
    }
};

Status LinkProbeOptions::validate() const
{
    constexpr double kMinRateHz = 0.01;
    if (payloadBytes < kHeaderBytes || payloadBytes > kMaxPayloadBytes)
        return LocatedError {
            LinkProbe::tr("--size must be between %1 and %2 bytes").arg(kHeaderBytes).arg(kMaxPayloadBytes)};
    // A rate near 0 makes the interval between messages infinite (1e9 / 1e-300 ns), and the send
    // times computed from it undefined: bounded like every number given.
    if (!(rateHz >= kMinRateHz) || !std::isfinite(rateHz) || rateHz > 1e6)
        return LocatedError {LinkProbe::tr("--rate must be from %1 to 1000000 Hz").arg(kMinRateHz)};
    if (qos < 0 || qos > 2)
        return LocatedError {LinkProbe::tr("--qos must be 0, 1 or 2")};
    if (count < 1 || count > 100'000'000)
        return LocatedError {LinkProbe::tr("--count must be between 1 and 100000000")};
    if (!(maxRateHz >= rateHz) || !std::isfinite(maxRateHz) || maxRateHz > 1e6)
        return LocatedError {LinkProbe::tr("--max-rate must be at least --rate and at most 1000000 Hz")};
    if (!(sweepSeconds > 0) || !(stepSeconds > 0) || !(rateFactor > 1) || drainMs < 0)
        return LocatedError {LinkProbe::tr("the sweep needs positive durations and a factor above 1")};
    return profile.validate();
}

qint64 LinkProbeReport::received() const
{
    qint64 n = 0;
    for (const LinkProbeStep& s : steps)
        n += s.received;
    return n;
}

const LinkProbeStep* LinkProbeReport::summary() const
{
    if (steps.empty())
        return nullptr;
    return &steps[std::size_t(std::max(best, 0))];
}

double LinkProbeReport::maxRateHz() const
{
    return best >= 0 ? steps[std::size_t(best)].rateHz : 0;
}

double LinkProbeReport::throughputMBs() const
{
    return double(payloadBytes) * maxRateHz() / 1e6;
}

LinkProbe::LinkProbe(QObject* parent)
    : QObject(parent)
{
    qRegisterMetaType<LinkProbeStep>();
    qRegisterMetaType<LinkProbeReport>();
}

LinkProbe::~LinkProbe()
{
    m_stop = true;
    join();
}

QString LinkProbe::pingTopic(const QString& clientId)
{
    return u"bridgescope/probe/%1/ping"_s.arg(clientId);
}

QString LinkProbe::pongTopic(const QString& clientId)
{
    return u"bridgescope/probe/%1/pong"_s.arg(clientId);
}

QString LinkProbe::echoFilter()
{
    return u"bridgescope/probe/+/ping"_s;
}

void LinkProbe::start(const LinkProbeOptions& options)
{
    launch(options, Plain);
}

void LinkProbe::startSweep(const LinkProbeOptions& options)
{
    launch(options, Sweep);
}

void LinkProbe::startEcho(const LinkProbeOptions& options)
{
    launch(options, Echo);
}

void LinkProbe::stop()
{
    m_stop = true;
}

void LinkProbe::launch(const LinkProbeOptions& options, int mode)
{
    m_stop = true;
    join();
    m_stop = false;
    m_done = false;
    m_echoed = 0;
    {
        std::lock_guard<std::mutex> lock(m_live.mutex);
        m_live.progress = LinkProbeProgress();
    }
    const quint64 generation = ++m_generation;
    m_worker = std::thread([this, options, mode, generation] {
        Run run(this, options, mode, m_stop, m_echoed, &m_live);
        if (const Status valid = options.validate())
            run.execute();
        else
            run.report.error = valid.error().toString();
        const LinkProbeReport report = run.report;
        QMetaObject::invokeMethod(
            this,
            [this, report, generation] {
                if (generation != m_generation) // a newer run replaced this one
                    return;
                join();
                m_done = true;
                emit finished(report);
            },
            Qt::QueuedConnection);
    });
}

LinkProbeProgress LinkProbe::takeProgress()
{
    std::vector<std::pair<int, qint64>> rtts;
    std::lock_guard<std::mutex> lock(m_live.mutex);
    rtts.swap(m_live.progress.rttNs);
    LinkProbeProgress out = m_live.progress; // the counts; the round trips were swapped out
    out.rttNs = std::move(rtts);
    return out;
}

void LinkProbe::join()
{
    if (m_worker.joinable())
        m_worker.join();
}
