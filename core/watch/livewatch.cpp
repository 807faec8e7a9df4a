// SPDX-License-Identifier: MIT
#include "livewatch.h"

#include "base/logging.h"
#include "record/runrecorder.h"
#include "session/liveparts.h"
#include "session/livesession.h"
#include "session/measuresession.h"
#include "watch/watchsession.h"

namespace {
WatchSession::Parts watchParts(LiveSession* live)
{
    return {live->sources(), live->rosGraph(), live->ros2(), live->rosMonitor(), live->mqtt()};
}
} // namespace

LiveWatch::LiveWatch(Measuring measuring, QObject* parent)
    : QObject(parent)
    , m_live(new LiveSession(this))
    , m_measure(measuring == Measuring::Yes ? new MeasureSession(LiveParts::measure(m_live), this) : nullptr)
    , m_watch(new WatchSession(watchParts(m_live), this))
{
    // The watch shows no topic list: the topics' figures (every topic's rates, O(topics)) are
    // needed every few seconds at most (the window sets its own), not at every drain.
    m_live->setFiguresInterval(5000);
    if (m_measure) {
        // pipeline latency for the links; a recorded run lists their events
        m_watch->useMeasurement(m_measure);
        return;
    }
    m_ownRecorder = new RunRecorder(this);
    const auto add = [recorder = m_ownRecorder](const WatchEvent& e) { recorder->addEvent(e.toRecorded()); };
    connect(m_watch->monitor(), &LinkMonitor::eventStarted, m_ownRecorder, add);
    connect(m_watch->monitor(), &LinkMonitor::eventEnded, m_ownRecorder, add);
}

LiveWatch::~LiveWatch() = default;

RunRecorder* LiveWatch::recorder() const
{
    return m_measure ? m_measure->recorder() : m_ownRecorder;
}

Result<void> LiveWatch::startRecording(const QString& path, const RunInfo& info)
{
    if (m_measure)
        return m_measure->startRecording(path, info);
    Result<void> started = m_ownRecorder->start(path, info);
    if (started) // the observed hop latencies too, as the measurement records them
        m_watch->setObservedSink(
            [this](std::vector<LatencyValue>&& values, WatchSession::ObservedLeftOut leftOut, qint64 nowNs) {
                m_ownRecorder->add({}, values, nowNs);
                if (leftOut.dropped > m_observedDroppedSaid) { // said once per change, not per drain
                    m_observedDroppedSaid = leftOut.dropped;
                    qCWarning(lcSession).noquote() << "observed hop latencies dropped unrecorded, past a "
                                                      "link's bound between two drains:"
                                                   << leftOut.dropped;
                }
            });
    return started;
}

Result<void> LiveWatch::stopRecording()
{
    m_live->drainNow(); // the last stamps and events
    if (m_measure)
        return m_measure->stopRecording();
    m_watch->setObservedSink({});
    return m_ownRecorder->stop();
}
