// SPDX-License-Identifier: MIT
#include "measuresession.h"

#include "base/logging.h"
#include "latency/clocktext.h"
#include "session/clockwatch.h"
#include "models/latencystatsmodel.h"
#include "mqtt/mqttconnection.h"
#include "record/runrecorder.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosstampsource.h"
#include "ros2/ros2participant.h"
#include "ros2/ros2stampsource.h"
#include "wire/sourcemessage.h"

#include <algorithm>
#include <QDateTime>
#include <QThread>

using namespace Qt::StringLiterals;

MeasureSession::MeasureSession(const Parts& parts, QObject* parent)
    : QObject(parent)
    , m_parts(parts)
    , m_ros(new RosStampSource(this))
    , m_ros2(new Ros2StampSource(parts.ros2, this))
    , m_stats(new LatencyStatsModel(this))
    , m_recorder(new RunRecorder(this))
{
    m_publishTimer.setSingleShot(true);
    connect(&m_publishTimer, &QTimer::timeout, this, [this] {
        if (!m_paused && m_shown)
            publish();
    });
    connect(m_recorder, &RunRecorder::failed, this, [this](const QString& why) {
        static_cast<void>(m_recorder->stop()); // `why` says what went wrong
        emit recordingChanged(false);
        emit recordingFailed(why);
    });
    // The MQTT batch comes before drained() in the same tick: collect it, ingest on drained().
    parts.sources.everyMqttBatch([this](const std::vector<MqttMessage>& batch) { m_mqttDecoder.collect(batch); });
    m_sources = {m_ros, m_ros2, &m_mqttDecoder};
    parts.sources.everyDrain(this, [this](qint64 nowNs) { onDrained(nowNs); });
    connect(parts.rosGraph, &RosGraphPoller::graphChanged, this, &MeasureSession::onGraph);
    connect(parts.rosGraph, &RosGraphPoller::masterRestarted, m_ros, &RosStampSource::resubscribeAll);
    connect(parts.ros2, &Ros2Participant::graphChanged, this, &MeasureSession::onRos2Graph);
    if (parts.ros2->isRunning())
        onRos2Graph(parts.ros2->graph());
    m_ros->setMasterUri(parts.rosGraph->masterUri());
    if (parts.mqtt) {
        // The clocks of the live pipeline's hosts, probed on the measured broker while it is connected.
        m_clockWatch = new ClockWatch([this](const ClockEstimate& e) { setClock(e); }, this);
        connect(m_clockWatch, &ClockWatch::problemsChanged, this,
                [this] { setClockProblems(m_clockWatch->problems()); });
        connect(parts.mqtt, &MqttConnection::stateChanged, this, &MeasureSession::updateClockWatch);
    }
    m_stats->refresh(m_engine);
}

MeasureSession::~MeasureSession() = default;

QString MeasureSession::brokerUrl() const
{
    return m_parts.mqtt->profile().url;
}

QString MeasureSession::rosMasterUri() const
{
    return m_parts.rosGraph->masterUri();
}

void MeasureSession::onGraph(const TopicGraph& graph)
{
    QSet<QString> stamps;
    QSet<QString> latencies;
    for (const TopicInfo& t : graph.topics) {
        if (t.type == SourceMessage::stampType(SourceGraph::Ros1))
            stamps.insert(t.name);
        else if (t.type == u"std_msgs/Float64"_s && t.name.contains(u"/latencies/"_s))
            latencies.insert(t.name);
    }
    m_graphStampTopics = stamps;
    m_graphLatencyTopics = latencies;
    updateSubscriptions();
}

void MeasureSession::onRos2Graph(const Ros2Graph& graph)
{
    QSet<QString> stamps;
    QSet<QString> latencies;
    for (const Ros2Topic& t : graph.topics) {
        if (t.types.contains(SourceMessage::stampType(SourceGraph::Ros2)))
            stamps.insert(t.name);
        else if (t.types.contains(u"std_msgs/msg/Float64"_s) && t.name.contains(u"/latencies/"_s))
            latencies.insert(t.name);
    }
    if (stamps == m_ros2StampTopics && latencies == m_ros2LatencyTopics)
        return;
    m_ros2StampTopics = stamps;
    m_ros2LatencyTopics = latencies;
    updateSubscriptions();
}

QString MeasureSession::ros2StampName(const QString& topic, const QSet<QString>& ros1Stamps,
                                      const Pipeline& pipeline)
{
    const QString prefixed = ros2Prefix() + topic;
    return ros1Stamps.contains(topic) || pipeline.indexOf(prefixed) >= 0 ? prefixed : topic;
}

void MeasureSession::setClock(const ClockEstimate& estimate)
{
    // One pending estimate per host: a newer one replaces it (a tick applies the latest).
    for (ClockEstimate& pending : m_pendingClocks)
        if (pending.host == estimate.host) {
            pending = estimate;
            return;
        }
    constexpr std::size_t kMaxPendingHosts = 256;
    if (m_pendingClocks.size() < kMaxPendingHosts)
        m_pendingClocks.push_back(estimate);
}

QString MeasureSession::clocksText() const
{
    const QString measured = ClockText::measured(m_engine.pipelineSeries(), m_engine.pipeline());
    QStringList parts;
    if (!measured.isEmpty())
        parts << tr("Clocks measured: %1.").arg(measured);
    if (!m_clockProblems.isEmpty())
        parts << m_clockProblems;
    else if (parts.isEmpty() && m_clockWatch && !m_clockWatch->hosts().isEmpty())
        parts << tr("Measuring the clocks of %1 through the broker (bridgescope clock serve on each host)…")
                     .arg(m_clockWatch->hosts().join(u", "_s));
    return parts.join(u' ');
}

QString MeasureSession::clockSyncText() const
{
    return m_clockWatch ? m_clockWatch->syncText() : QString();
}

void MeasureSession::setClockProblems(const QString& problems)
{
    if (problems == m_clockProblems)
        return;
    m_clockProblems = problems;
    emit clocksChanged();
}

void MeasureSession::setRos1(bool on)
{
    m_ros1On = on;
    updateSubscriptions();
}

void MeasureSession::updateSubscriptions()
{
    QSet<QString> stamps = m_graphStampTopics;
    // The pipeline's topics too, before the master lists them (ROS names start with '/'); those
    // named for the ROS 2 graph only ("ros2:/topic") are not asked of the master.
    for (const QString& t : m_engine.pipeline().topics())
        if (!t.startsWith(ros2Prefix()))
            stamps.insert(t.startsWith(u'/') ? t : u'/' + t);
    if (m_ros1On)
        m_ros->setTopics(stamps, m_graphLatencyTopics);
    else
        m_ros->setTopics({}, {});
    QHash<QString, QString> ros2;
    for (const QString& t : std::as_const(m_ros2StampTopics))
        ros2.insert(t, ros2StampName(t, m_graphStampTopics, m_engine.pipeline()));
    m_ros2->setTopics(ros2, m_ros2LatencyTopics);
    updateClockWatch();
}

void MeasureSession::updateClockWatch()
{
    if (!m_clockWatch)
        return;
    const Pipeline& p = m_showingRun ? m_livePipeline : m_engine.pipeline();
    const bool automatic = m_showingRun ? m_liveAutomatic : m_automatic;
    QStringList hosts;
    // The user's pipeline only (loaded, edited, given to record): one proposed from what is seen
    // probes nothing by itself. On two clocks, while the broker is connected.
    if (!automatic && !p.oneClock() && m_parts.mqtt->state() == MqttConnection::State::Connected)
        for (int t = 0; t < p.topicCount(); ++t)
            hosts << p.host(t);
    m_clockWatch->watch(hosts, m_parts.mqtt->profile());
    emit clocksChanged();
}

void MeasureSession::onDrained(qint64 nowNs)
{
    Q_ASSERT(QThread::currentThread() == thread());
    std::vector<StampEvent> stamps;
    std::vector<LatencyValue> latencies;
    for (StampSource* source : m_sources)
        source->takeStamps(stamps, latencies);
    if (m_showingRun)
        return; // a recorded run is on screen: live stamps are not measured meanwhile
    if (!m_pendingClocks.empty()) {
        for (const ClockEstimate& clock : std::exchange(m_pendingClocks, {})) {
            m_engine.setClock(clock);
            m_recorder->addClock(clock, nowNs);
        }
        emit clocksChanged();
    }
    m_recorder->add(stamps, latencies, nowNs);

    const int topicsBefore = int(m_discovery.topics().size());
    for (const StampEvent& e : stamps)
        m_discovery.add(e);
    if (m_automatic && !m_recorder->isRecording())
        proposeIfNew();
    m_engine.ingest(stamps);
    for (const LatencyValue& v : latencies)
        m_engine.ingest(v);
    m_engine.expire(nowNs);
    if (int(m_discovery.topics().size()) != topicsBefore)
        emit stampTopicsChanged();
    if (!m_firstSampleSaid && m_engine.counters().complete > 0) {
        m_firstSampleSaid = true; // when a measurement starts to show (bench_startup reads it)
        qCDebug(lcSession) << "first complete sample";
    }
    if (!m_paused)
        publishSoon();
}

void MeasureSession::addObserved(std::vector<LatencyValue>&& values, int linksLeftOut, quint64 dropped,
                                 qint64 nowNs)
{
    Q_ASSERT(QThread::currentThread() == thread());
    m_observedLeftOut = linksLeftOut;
    m_observedDropped = dropped;
    if (m_showingRun)
        return; // as the stamps: a recorded run is on screen
    m_recorder->add({}, values, nowNs);
    for (const LatencyValue& v : values)
        m_engine.ingest(v);
    if (!m_paused)
        publishSoon();
}

void MeasureSession::publishSoon()
{
    if (!m_shown || m_engine.revision() == m_publishedRevision)
        return;
    const qint64 since = m_sincePublished.isValid() ? m_sincePublished.elapsed() : m_publishIntervalMs;
    if (since >= m_publishIntervalMs) {
        publish();
    } else if (!m_publishTimer.isActive()) {
        m_publishTimer.start(int(m_publishIntervalMs - since));
    }
}

void MeasureSession::setShown(bool shown)
{
    m_shown = shown;
    if (shown && !m_paused)
        publish();
}

void MeasureSession::proposeIfNew()
{
    // Again only when the set of topics grew, or the first complete samples give a real order:
    // re-proposing on every small change of order would reset the figures again and again.
    const int topics = int(m_discovery.topics().size());
    const bool complete = m_discovery.completeSamples() > 0;
    if (topics < 2 || (topics == m_proposedTopics && (complete == m_proposedWithCompleteSamples)))
        return;
    m_proposedTopics = topics;
    m_proposedWithCompleteSamples = complete;
    const Pipeline proposal = m_discovery.propose(int(m_engine.window()));
    if (proposal == m_engine.pipeline())
        return;
    m_engine.setPipeline(proposal);
    updateSubscriptions();
    emit pipelineChanged();
}

void MeasureSession::publish()
{
    if (m_engine.revision() == m_publishedRevision)
        return;
    m_publishedRevision = m_engine.revision();
    m_publishTimer.stop();
    m_sincePublished.start();
    m_stats->refresh(m_engine);
    emit updated();
}

void MeasureSession::setPipeline(const Pipeline& pipeline)
{
    if (m_recorder->isRecording() || m_showingRun) {
        emit pipelineChanged(); // the views go back to the pipeline in force
        return;
    }
    m_automatic = false;
    m_engine.setPipeline(pipeline);
    updateSubscriptions();
    emit pipelineChanged();
    publish();
}

void MeasureSession::setAutomatic()
{
    if (m_recorder->isRecording() || m_showingRun)
        return;
    m_automatic = true;
    m_proposedTopics = 0;
    m_proposedWithCompleteSamples = false;
    proposeIfNew();
    updateClockWatch();
    publish();
}

void MeasureSession::setWindow(qint64 samples)
{
    m_engine.setWindow(samples);
    publish();
}

void MeasureSession::setPaused(bool paused)
{
    m_paused = paused;
    if (!paused)
        publish();
}

void MeasureSession::reset()
{
    m_engine.reset();
    publish();
}

quint64 MeasureSession::malformedStamps() const
{
    quint64 n = 0;
    for (const StampSource* source : m_sources)
        n += source->malformedStamps();
    return n;
}

QHash<QString, quint64> MeasureSession::malformedStampsByTopic() const
{
    QHash<QString, quint64> all;
    for (const StampSource* source : m_sources) {
        const QHash<QString, quint64> more = source->malformedStampsByTopic();
        for (auto it = more.cbegin(); it != more.cend(); ++it)
            all[it.key()] += it.value();
    }
    return all;
}

std::pair<std::vector<std::pair<quint64, QString>>, qsizetype>
MeasureSession::worstMalformedTopics(std::size_t count) const
{
    const QHash<QString, quint64> byTopic = malformedStampsByTopic();
    std::vector<std::pair<quint64, QString>> worst;
    worst.reserve(std::size_t(byTopic.size()));
    for (auto it = byTopic.cbegin(); it != byTopic.cend(); ++it)
        worst.emplace_back(it.value(), it.key());
    const std::size_t shown = std::min(worst.size(), count);
    std::partial_sort(worst.begin(), worst.begin() + qsizetype(shown), worst.end(),
                      [](const auto& a, const auto& b) { return a.first > b.first; });
    worst.resize(shown);
    return {std::move(worst), byTopic.size()};
}

QString MeasureSession::lastStampError() const
{
    QStringList both;
    for (const StampSource* source : m_sources)
        if (const QString e = source->lastStampError(); !e.isEmpty())
            both << e;
    return both.join(u"; ");
}

Result<void> MeasureSession::startRecording(const QString& path, RunInfo info)
{
    if (m_showingRun)
        return LocatedError {tr("a recorded run is on screen: go back to live first")};
    if (m_engine.pipeline().isEmpty())
        return LocatedError {tr("no pipeline yet: load one, or wait until stamps arrive")};
    info.pipeline = m_engine.pipeline();
    info.window = m_engine.window();
    info.timeoutNs = m_engine.timeoutNs();
    info.rosMaster = m_ros1On ? rosMasterUri() : QString();
    if (m_parts.ros2->isRunning()) {
        const Ros2Options o = m_parts.ros2->options();
        info.ros2Domain = o.localhostOnly ? tr("domain %1, this host only").arg(o.domain) : tr("domain %1").arg(o.domain);
    }
    info.broker = brokerUrl();
    info.startedNs = QDateTime::currentMSecsSinceEpoch() * 1'000'000;
    info.describeThisMachine();
    if (Result<void> started = m_recorder->start(path, info); !started)
        return started;
    // A run starts from zero, so that opening it later shows exactly what was shown live; with the
    // clocks known so far, which its replay applies before its first stamp.
    m_engine.reset();
    for (const ClockEstimate& clock : m_engine.pipelineSeries().clocks())
        m_recorder->addClock(clock, 0);
    publish();
    emit recordingChanged(true);
    return {};
}

Result<void> MeasureSession::stopRecording()
{
    if (!m_recorder->isRecording())
        return LocatedError {}; // nothing to stop
    Result<void> stopped = m_recorder->stop();
    emit recordingChanged(false);
    return stopped;
}

bool MeasureSession::isRecording() const
{
    return m_recorder->isRecording();
}

Status MeasureSession::showRun(const RunData& run)
{
    if (m_recorder->isRecording())
        return LocatedError {tr("recording: stop it before opening a run")};
    if (!m_showingRun) {
        m_livePipeline = m_engine.pipeline();
        m_liveAutomatic = m_automatic;
        m_liveTimeoutNs = m_engine.timeoutNs();
    }
    if (!m_showingRun)
        m_liveClocks = m_engine.pipelineSeries().clocks().values();
    m_showingRun = true;
    m_shownRun = run.info;
    Pipeline p = run.info.pipeline;
    p.setWindow(int(run.info.window));
    m_engine.clearClocks(); // the run's own clocks only: a run without them reads as it was recorded
    m_engine.setPipeline(p);
    m_engine.setTimeoutNs(run.info.timeoutNs > 0 ? run.info.timeoutNs : SampleJoiner::kDefaultTimeoutNs);
    run.replay(m_engine);
    emit pipelineChanged();
    emit showingRunChanged(true);
    publish();
    return {};
}

void MeasureSession::showLive()
{
    if (!m_showingRun)
        return;
    m_showingRun = false;
    m_shownRun = RunInfo();
    m_engine.setTimeoutNs(m_liveTimeoutNs);
    m_engine.clearClocks();
    m_engine.setPipeline(m_livePipeline);
    for (const ClockEstimate& clock : std::exchange(m_liveClocks, {}))
        m_engine.setClock(clock);
    m_automatic = m_liveAutomatic;
    m_proposedTopics = 0;
    m_proposedWithCompleteSamples = false;
    emit pipelineChanged();
    emit showingRunChanged(false);
    publish();
}
