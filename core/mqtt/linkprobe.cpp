// SPDX-License-Identifier: MIT
#include "linkprobe.h"

#include "latency/latencyseries.h"
#include "pahooptions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mqtt/async_client.h>
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

qint64 wallNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::system_clock::now().time_since_epoch())
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

QString connectError(const QString& url, const mqtt::exception& e)
{
    if (e.get_return_code() == -1)
        return LinkProbe::tr("no broker answers at %1").arg(url);
    return LinkProbe::tr("cannot connect to %1: %2").arg(url, QString::fromStdString(e.what()));
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
    std::unique_ptr<mqtt::async_client> client;

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

    void onArrival(const mqtt::const_message_ptr& msg)
    {
        const qint64 now = steadyNs();
        const mqtt::binary_ref& data = msg->get_payload_ref();
        if (data.size() < std::size_t(LinkProbeOptions::kHeaderBytes)
            || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0)
            return;
        const auto* bytes = reinterpret_cast<const uchar*>(data.data());
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

    void onEcho(const mqtt::const_message_ptr& msg)
    {
        const std::string& topic = msg->get_topic();
        static const std::string ping = "/ping";
        if (topic.size() <= ping.size() || topic.compare(topic.size() - ping.size(), ping.size(), ping) != 0)
            return;
        const std::string pong = topic.substr(0, topic.size() - 4) + "pong";
        try {
            client->publish(pong, msg->get_payload_ref(), msg->get_qos(), false);
            echoed.fetch_add(1, std::memory_order_relaxed);
        } catch (const mqtt::exception&) { }
    }

    bool connect()
    {
        const MqttProfile& p = options.profile;
        report.clientId = QString::fromStdString(PahoOptions::clientId(p));
        const QString id = report.clientId;
        report.sendTopic = pingTopic(id);
        report.receiveTopic = mode == Echo ? echoFilter() : (options.viaEcho ? pongTopic(id) : pingTopic(id));
        report.payloadBytes = options.payloadBytes;
        report.sweep = mode == Sweep;
        try {
            mqtt::create_options createOpts(p.mqttVersion == 5 ? MQTTVERSION_5 : MQTTVERSION_3_1_1);
            client = std::make_unique<mqtt::async_client>(p.pahoUri().toStdString(), id.toStdString(),
                                                          createOpts, nullptr);
            client->set_message_callback([this](const mqtt::const_message_ptr& msg) {
                if (mode == Echo)
                    onEcho(msg);
                else
                    onArrival(msg);
            });
            client->set_connection_lost_handler([this](const std::string& cause) {
                std::lock_guard<std::mutex> lock(mutex);
                lost = true;
                lostWhy = cause.empty()
                    ? tr("the connection to the broker was lost")
                    : tr("the connection to the broker was lost: %1").arg(QString::fromStdString(cause));
                changed.notify_all();
            });
            // A probe reports a broken link rather than hiding it behind reconnects.
            const mqtt::connect_options connectOptions
                = PahoOptions::connectOptions(p).automatic_reconnect(false).max_inflight(65535).finalize();
            if (!client->connect(connectOptions)->wait_for(std::chrono::seconds(10))) {
                report.error = tr("no answer from the broker at %1").arg(p.url);
                return false;
            }
        } catch (const mqtt::exception& e) {
            report.error = connectError(p.url, e);
            return false;
        }
        try {
            if (!client->subscribe(report.receiveTopic.toStdString(), options.qos)
                     ->wait_for(std::chrono::seconds(5))) {
                report.error = tr("the broker at %1 does not confirm the subscription to %2")
                                   .arg(p.url, report.receiveTopic);
                return false;
            }
        } catch (const mqtt::exception& e) {
            report.error = tr("the broker at %1 refuses the subscription to %2: %3")
                               .arg(p.url, report.receiveTopic, QString::fromStdString(e.what()));
            return false;
        }
        return true;
    }

    void disconnect()
    {
        if (!client)
            return;
        try {
            if (client->is_connected())
                client->disconnect(std::chrono::milliseconds(500))->wait_for(std::chrono::seconds(2));
        } catch (const mqtt::exception&) { }
        client.reset();
    }

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
        const std::string topic = report.sendTopic.toStdString();
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
            qToLittleEndian<qint64>(wallNs(), payload.data() + 16);
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

    bool publish(const std::string& topic, const std::string& payload)
    {
        // With QoS 1 and 2 Paho refuses more than max_inflight unacknowledged messages: wait for room.
        for (;;) {
            try {
                client->publish(topic, payload.data(), payload.size(), options.qos, false);
                return true;
            } catch (const mqtt::exception& e) {
                if (e.get_return_code() != MQTTASYNC_MAX_MESSAGES_INFLIGHT) {
                    sendError = tr("cannot publish on %1: %2")
                                    .arg(QString::fromStdString(topic), QString::fromStdString(e.what()));
                    return false;
                }
                if (stop)
                    return false;
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
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

bool LinkProbeOptions::validate(QString* error) const
{
    auto fail = [error](const QString& why) {
        if (error)
            *error = why;
        return false;
    };
    if (payloadBytes < kHeaderBytes || payloadBytes > kMaxPayloadBytes)
        return fail(
            LinkProbe::tr("--size must be between %1 and %2 bytes").arg(kHeaderBytes).arg(kMaxPayloadBytes));
    if (!(rateHz > 0) || !std::isfinite(rateHz) || rateHz > 1e6)
        return fail(LinkProbe::tr("--rate must be above 0 and at most 1000000 Hz"));
    if (qos < 0 || qos > 2)
        return fail(LinkProbe::tr("--qos must be 0, 1 or 2"));
    if (count < 1 || count > 100'000'000)
        return fail(LinkProbe::tr("--count must be between 1 and 100000000"));
    if (!(maxRateHz >= rateHz) || !std::isfinite(maxRateHz) || maxRateHz > 1e6)
        return fail(LinkProbe::tr("--max-rate must be at least --rate and at most 1000000 Hz"));
    if (!(sweepSeconds > 0) || !(stepSeconds > 0) || !(rateFactor > 1) || drainMs < 0)
        return fail(LinkProbe::tr("the sweep needs positive durations and a factor above 1"));
    return profile.validate(error);
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
        QString why;
        if (options.validate(&why))
            run.execute();
        else
            run.report.error = why;
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
