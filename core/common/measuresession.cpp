// SPDX-License-Identifier: MIT
#include "measuresession.h"

#include "latency/latencystatsmodel.h"
#include "latency/stampcodec.h"
#include "livesession.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosstampsource.h"

#include <QThread>

using namespace Qt::StringLiterals;

MeasureSession::MeasureSession(LiveSession* live, QObject* parent)
    : QObject(parent)
    , m_live(live)
    , m_ros(new RosStampSource(this))
    , m_stats(new LatencyStatsModel(this))
{
    // The MQTT batch comes before drained() in the same tick: collect it, ingest on drained().
    live->addMqttListener([this](const std::vector<MqttMessage>& batch) {
        m_mqttDecoder.decode(batch, m_pendingStamps, m_pendingLatencies);
    });
    connect(live, &LiveSession::drained, this, &MeasureSession::onDrained);
    connect(live->rosGraph(), &RosGraphPoller::graphChanged, this, &MeasureSession::onGraph);
    connect(live->rosGraph(), &RosGraphPoller::masterRestarted, m_ros, &RosStampSource::resubscribeAll);
    m_ros->setMasterUri(live->rosMasterUri());
    m_stats->refresh(m_engine);
}

MeasureSession::~MeasureSession() = default;

void MeasureSession::onGraph(const RosGraph& graph)
{
    QSet<QString> stamps;
    QSet<QString> latencies;
    for (const RosTopicInfo& t : graph.topics) {
        if (t.type == QLatin1StringView(StampCodec::typeName()))
            stamps.insert(t.name);
        else if (t.type == u"std_msgs/Float64"_s && t.name.contains(u"/latencies/"_s))
            latencies.insert(t.name);
    }
    m_graphStampTopics = stamps;
    m_graphLatencyTopics = latencies;
    updateSubscriptions();
}

void MeasureSession::updateSubscriptions()
{
    QSet<QString> stamps = m_graphStampTopics;
    // The pipeline's topics too, before the master lists them (ROS names start with '/').
    for (const QString& t : m_engine.pipeline().topics())
        stamps.insert(t.startsWith(u'/') ? t : u'/' + t);
    m_ros->setTopics(stamps, m_graphLatencyTopics);
}

void MeasureSession::onDrained(qint64 nowNs)
{
    Q_ASSERT(QThread::currentThread() == thread());
    std::vector<StampEvent> stamps = m_ros->takeStamps();
    stamps.insert(stamps.end(), std::make_move_iterator(m_pendingStamps.begin()),
                  std::make_move_iterator(m_pendingStamps.end()));
    m_pendingStamps.clear();
    std::vector<LatencyValue> latencies = m_ros->takeLatencies();
    latencies.insert(latencies.end(), m_pendingLatencies.begin(), m_pendingLatencies.end());
    m_pendingLatencies.clear();

    const int topicsBefore = int(m_discovery.topics().size());
    for (const StampEvent& e : stamps)
        m_discovery.add(e);
    if (m_automatic)
        proposeIfNew();
    m_engine.ingest(stamps);
    for (const LatencyValue& v : latencies)
        m_engine.ingest(v);
    m_engine.expire(nowNs);
    if (int(m_discovery.topics().size()) != topicsBefore)
        emit stampTopicsChanged();
    if (!m_paused)
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
    m_stats->refresh(m_engine);
    emit updated();
}

void MeasureSession::setPipeline(const Pipeline& pipeline)
{
    m_automatic = false;
    m_engine.setPipeline(pipeline);
    updateSubscriptions();
    emit pipelineChanged();
    publish();
}

void MeasureSession::setAutomatic()
{
    m_automatic = true;
    m_proposedTopics = 0;
    m_proposedWithCompleteSamples = false;
    proposeIfNew();
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
    return m_mqttDecoder.malformed() + m_ros->malformed();
}
