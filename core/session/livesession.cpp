// SPDX-License-Identifier: MIT
#include "livesession.h"

#include "base/logging.h"
#include "yaml/secrets.h"
#include "base/wallclock.h"
#include "models/mqtttopictree.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosmonitor.h"
#include "session/graphstatus.h"
#include "topics/topictablemodel.h"
#include "wire/ros2definitions.h"

#include <algorithm>
#include <chrono>

LiveSession::LiveSession(QObject* parent)
    : QObject(parent)
    , m_poller(new RosGraphPoller(this))
    , m_monitor(new RosMonitor(this))
    , m_rosTopics(new TopicTableModel(this))
    , m_mqtt(new MqttConnection(this))
    , m_tree(new MqttTopicTree(this))
    , m_ros2(new Ros2Participant(this))
    , m_graphStatus(new GraphStatus(m_poller, m_ros2, this))
    , m_ros2Topics(new TopicTableModel(this))
    , m_mqttSource(std::make_unique<MqttSource>(&m_tree->topicData()))
    , m_ros2Types(std::make_shared<RosTypeRegistry>(Ros2Definitions::registry()))
{
    m_tree->setRos2Registry(m_ros2Types); // mqtt_client's ROS 2 payloads decode as ROS 2 samples do
    m_mqttSource->setRos2Registry(m_ros2Types);
    m_sources.ros1 = m_monitor;
    m_sources.ros2 = m_ros2;
    m_sources.mqtt = m_mqttSource.get();
    m_sources.owner = this;
    // A copy of the sources may outlive the session: then nothing is tied to it.
    m_sources.everyDrain = [self = QPointer<LiveSession>(this)](QObject* context, std::function<void(qint64)> tick) {
        if (self)
            connect(self, &LiveSession::drained, context, std::move(tick));
    };
    m_sources.everyMqttBatch = [self = QPointer<LiveSession>(this)](MqttListener listener) {
        return self ? self->addMqttListener(std::move(listener)) : -1;
    };
    m_sources.setMqttJsonTypes = [self = QPointer<LiveSession>(this)](const QHash<QString, QString>& types) {
        if (self)
            self->m_mqttSource->setJsonTypes(types);
    };
    connect(m_ros2, &Ros2Participant::graphChanged, m_ros2Topics,
            [this](const Ros2Graph& graph) { m_ros2Topics->setGraph(graph.topicGraph()); });
    // Mon in a topic table subscribes through its graph's source, counted.
    const auto monitorFrom = [this](TopicTableModel* model, MessageSource* source) {
        connect(model, &TopicTableModel::monitorRequested, this, [source](const QString& topic, bool on) {
            if (on)
                source->monitor(topic);
            else
                source->unmonitor(topic);
        });
    };
    monitorFrom(m_ros2Topics, m_ros2);
    monitorFrom(m_rosTopics, m_monitor);
    connect(m_ros2, &Ros2Participant::monitorFailed, this, [this](const QString& topic, const QString& why) {
        qCWarning(lcSession).noquote() << "ROS 2 topic" << topic << "not monitored:" << why;
        m_ros2Topics->setMonitored(topic, false);
    });
    connect(m_poller, &RosGraphPoller::graphChanged, m_rosTopics, &TopicTableModel::setGraph);
    connect(m_poller, &RosGraphPoller::masterRestarted, m_monitor, &RosMonitor::resubscribeAll);
    connect(m_poller, &RosGraphPoller::graphChanged, m_monitor, &RosMonitor::setGraph);
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(33);
    connect(&m_timer, &QTimer::timeout, this, &LiveSession::drainNow);
    m_timer.start();
    m_poller->start(1000);
}

LiveSession::~LiveSession() = default;

MessageSource* LiveSession::source(SourceGraph graph) const
{
    return m_sources.of(graph);
}

void LiveSession::setRosMasterUri(const QString& uri)
{
    qCDebug(lcSession).noquote() << "ROS master" << Secrets::urlWithoutCredentials(uri);
    m_poller->setMasterUri(uri);
    m_monitor->setMasterUri(uri);
}

QString LiveSession::rosMasterUri() const
{
    return m_poller->masterUri();
}

Status LiveSession::startRos2(const Ros2Options& options)
{
    qCDebug(lcSession) << "ROS 2 domain" << options.domain << (options.localhostOnly ? "on this host" : "");
    stopRos2();
    return m_ros2->start(options);
}

void LiveSession::stopRos2()
{
    m_ros2->stop();
    m_ros2Topics->setGraph({});
}

void LiveSession::setRos2DefinitionFolders(const QStringList& folders, QStringList* errors)
{
    m_ros2Types = std::make_shared<RosTypeRegistry>(Ros2Definitions::registry(folders, errors));
    m_tree->setRos2Registry(m_ros2Types);
    m_mqttSource->setRos2Registry(m_ros2Types);
}

void LiveSession::connectBroker(const MqttProfile& profile)
{
    qCDebug(lcSession).noquote() << "broker" << Secrets::urlWithoutCredentials(profile.url) << "history"
                                 << profile.historyDepth;
    m_tree->setHistoryDepth(profile.historyDepth);
    m_mqtt->open(profile);
}

void LiveSession::disconnectBroker()
{
    m_mqtt->close();
}

int LiveSession::addMqttListener(MqttListener listener)
{
    m_listeners.emplace_back(m_nextListener, std::move(listener));
    return m_nextListener++;
}

void LiveSession::removeMqttListener(int id)
{
    m_listeners.erase(
        std::remove_if(m_listeners.begin(), m_listeners.end(), [id](const auto& l) { return l.first == id; }),
        m_listeners.end());
}

void LiveSession::drainNow()
{
    const qint64 now = wallClockNs();
    std::vector<MqttMessage> batch = m_mqtt->takeMessages();
    if (!batch.empty()) {
        m_mqttSource->add(batch);
        for (const auto& [id, listener] : m_listeners)
            listener(batch);
        m_tree->apply(std::move(batch));
    }
    if (!m_topicViews) {
        emit drained(now);
        return;
    }
    m_tree->tick(now);
    if (now - m_figuresSetNs >= m_figuresIntervalNs) {
        m_figuresSetNs = now;
        m_rosTopics->setMonitorStats(m_monitor->snapshot(now), now);
        if (m_ros2->isRunning())
            m_ros2Topics->setMonitorStats(topicStatsOf(m_ros2->snapshot(now)), now);
    }
    emit drained(now);
}

void LiveSession::setFiguresInterval(int ms)
{
    m_figuresIntervalNs = qint64(ms) * 1'000'000;
    m_tree->setFiguresInterval(ms);
}
