// SPDX-License-Identifier: MIT
#include "livesession.h"

#include "base/logging.h"
#include "base/secrets.h"
#include "base/wallclock.h"
#include "mqtt/mqtttopictree.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosmonitor.h"
#include "ros/rostopicmodel.h"

#include <algorithm>
#include <chrono>

LiveSession::LiveSession(QObject* parent)
    : QObject(parent)
    , m_poller(new RosGraphPoller(this))
    , m_monitor(new RosMonitor(this))
    , m_rosTopics(new RosTopicModel(this))
    , m_mqtt(new MqttConnection(this))
    , m_tree(new MqttTopicTree(this))
{
    connect(m_poller, &RosGraphPoller::graphChanged, m_rosTopics, &RosTopicModel::setGraph);
    connect(m_poller, &RosGraphPoller::masterRestarted, m_monitor, &RosMonitor::resubscribeAll);
    connect(m_rosTopics, &RosTopicModel::monitorRequested, this, [this](const QString& topic, bool on) {
        if (on)
            m_monitor->monitor(topic);
        else
            m_monitor->unmonitor(topic);
    });
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(33);
    connect(&m_timer, &QTimer::timeout, this, &LiveSession::drainNow);
    m_timer.start();
    m_poller->start(1000);
}

LiveSession::~LiveSession() = default;

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
        for (const auto& [id, listener] : m_listeners)
            listener(batch);
        m_tree->apply(std::move(batch));
    }
    m_tree->tick(now);
    m_rosTopics->setMonitorStats(m_monitor->snapshot(now), now);
    emit drained(now);
}
