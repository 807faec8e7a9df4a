// SPDX-License-Identifier: MIT
#include "throughputstep.h"

#include "files/atomicfile.h"
#include "base/logging.h"
#include "experiment/experimentfolder.h"
#include "experiment/experimentlab.h"
#include "latency/latencyengine.h"
#include "session/livesession.h"
#include "session/measuresession.h"

#include <algorithm>
#include <cmath>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

using namespace Qt::StringLiterals;

namespace {
/// A probe's samples time out after this (not the 5 s default): the window waits for it.
constexpr qint64 kProbeTimeoutMs = 2000;
} // namespace

/// A rate being measured: measuring since windowStartMs (-1: warming up).
struct ThroughputStep::Probe : ExperimentLab
{
    QTimer timer;
    double rateHz = 0;
    qint64 windowStartMs = -1;
    qint64 resetAtMs = -1; ///< when the warm-up's samples were forgotten
    qint64 samplesBefore = 0; ///< complete samples when the window opened, and dropped ones
    qint64 droppedBefore = 0;
};

ThroughputStep::ThroughputStep(ExperimentPlan plan, QString directory, QString program, QObject* parent)
    : QObject(parent)
    , m_plan(std::move(plan))
    , m_dir(std::move(directory))
    , m_program(std::move(program))
{ }

ThroughputStep::~ThroughputStep() = default;

void ThroughputStep::start()
{
    m_stopping = false;
    nextProbe();
}

void ThroughputStep::stop()
{
    m_stopping = true;
    m_probe.reset();
    m_size = -1;
}

void ThroughputStep::nextProbe()
{
    if (m_stopping)
        return;
    if (m_settings.isEmpty()) {
        // The sizes in the order the cells have them; results of an earlier start are kept.
        const QList<ThroughputResult> earlier = ExperimentFolder(m_dir).readThroughput();
        m_results.clear();
        for (const ExperimentCell& c : std::as_const(m_plan.cells)) {
            if (std::any_of(m_settings.cbegin(), m_settings.cend(), [&c](const CellSettings& s) {
                    return s.payloadBytes == c.settings.payloadBytes;
                }))
                continue;
            m_settings << c.settings;
            ThroughputResult r;
            r.payloadBytes = c.settings.payloadBytes;
            r.level = QString::number(r.payloadBytes);
            for (const auto& [factor, level] : c.levels)
                if (factor == u"payload"_s)
                    r.level = level;
            for (const ThroughputResult& e : earlier)
                if (e.payloadBytes == r.payloadBytes && e.complete)
                    r = e;
            m_results << r;
        }
    }
    for (int i = 0; i < int(m_results.size()); ++i) {
        ThroughputResult& r = m_results[i];
        if (r.complete)
            continue;
        if (r.points.size() >= m_plan.throughput->ratesHz.size()) {
            r.complete = true;
            continue;
        }
        m_size = i;
        CellSettings s = m_settings[i];
        s.rateHz = m_plan.throughput->ratesHz[r.points.size()];
        s.detectionMs = 0; // the bridges' limit, not the detection's (40 ms caps it at 25 Hz)
        emit probeStarted(s.payloadBytes, s.rateHz);
        qCDebug(lcDemo).noquote() << "throughput" << s.payloadBytes << "bytes at" << s.rateHz << "Hz";
        m_probe = std::make_unique<Probe>();
        m_probe->rateHz = s.rateHz;
        if (const Status started
            = m_probe->start(m_plan, s, 100'000 + i * 100 + int(r.points.size()), m_dir, m_program);
            !started) {
            qCWarning(lcDemo).noquote() << started.error().toString();
            ThroughputPoint failed;
            failed.rateHz = s.rateHz;
            endProbe(failed);
            return;
        }
        m_probe->measure->setWindow(0);
        m_probe->measure->setTimeoutNs(kProbeTimeoutMs * 1'000'000);
        connect(&m_probe->timer, &QTimer::timeout, this, &ThroughputStep::poll);
        m_probe->timer.start(ExperimentLab::kPollMs);
        return;
    }
    writeResults();
    emit finished();
}

void ThroughputStep::poll()
{
    Probe& c = *m_probe;
    const LatencyEngine& engine = c.measure->engine();
    const qint64 now = c.clock.elapsed();
    ThroughputPoint p;
    p.rateHz = c.rateHz;
    if (c.windowStartMs < 0) {
        // Warm: a second's worth of samples (at least three), then a reset that forgets the lab's
        // start (samples from before every stamp subscription existed never complete). The reset
        // cuts the sample in flight, whose later stamps then time out as a "dropped" sample: the
        // window opens once that has happened, and counts from there.
        if (c.resetAtMs < 0 && engine.samples() >= std::max<qint64>(3, qint64(c.rateHz))) {
            c.measure->reset();
            c.resetAtMs = now;
        } else if (c.resetAtMs >= 0 && now - c.resetAtMs >= kProbeTimeoutMs + 500) {
            c.live->drainNow();
            c.samplesBefore = engine.samples();
            c.droppedBefore = qint64(engine.counters().dropped());
            c.windowStartMs = now;
        } else if (now > 60'000 || !c.lab.isRunning()) {
            endProbe(p); // nothing came through: not sustained
        }
        return;
    }
    const double seconds = m_plan.throughput->secondsPerRate;
    if (now - c.windowStartMs < qint64(seconds * 1000) && c.lab.isRunning())
        return;
    c.live->drainNow();
    p.samples = engine.samples() - c.samplesBefore;
    p.expected = qint64(c.rateHz * seconds);
    p.dropped = qint64(engine.counters().dropped()) - c.droppedBefore;
    // The window's totals: the last p.samples values of the total series.
    const LatencySeries& series = engine.series(engine.totalSeries());
    LatencySeries window(series.msPerUnit());
    window.setWindow(0);
    const std::vector<qint64>& values = series.values();
    for (auto v = values.end() - std::min<qint64>(std::max<qint64>(p.samples, 0), qint64(values.size()));
         v != values.end(); ++v)
        window.append(*v);
    const LatencyStats total = window.stats();
    p.p50Ms = std::isfinite(total.median) ? total.median : 0;
    p.p99Ms = std::isfinite(total.p99) ? total.p99 : 0;
    // Sustained: (almost) every sample through, none dropped, and the latency not running away
    // from the lowest rate's (a queue that grows shows there first).
    const QList<ThroughputPoint>& before = m_results[m_size].points;
    const double base = before.isEmpty() ? p.p50Ms : before.first().p50Ms;
    p.sustainable = c.lab.isRunning() && p.samples >= qint64(0.95 * double(p.expected)) && p.dropped == 0
        && p.p50Ms <= 2 * base + 5;
    endProbe(p);
}

void ThroughputStep::endProbe(const ThroughputPoint& point)
{
    m_probe.reset();
    ThroughputResult& r = m_results[m_size];
    r.points << point;
    // Rates go up: after the first one not sustained, the higher ones are not tried.
    if (!point.sustainable || r.points.size() >= m_plan.throughput->ratesHz.size())
        r.complete = true;
    m_size = -1;
    writeResults();
    emit probeFinished(point);
    if (!m_stopping)
        QTimer::singleShot(0, this, &ThroughputStep::nextProbe);
}

bool ThroughputStep::writeResults() const
{
    QJsonArray sizes;
    for (const ThroughputResult& r : m_results)
        sizes.append(r.toJson());
    const Status written
        = AtomicFile::write(ExperimentFolder(m_dir).throughputPath(),
                            QJsonDocument(QJsonObject {{u"sizes"_s, sizes}}).toJson(), false);
    if (!written)
        qCWarning(lcDemo).noquote() << written.error().toString();
    return written.ok();
}
