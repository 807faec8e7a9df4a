// SPDX-License-Identifier: MIT
#include "watchsession.h"

#include "base/logging.h"
#include "base/wallclock.h"
#include "ros/rosgraphpoller.h"
#include "ros/rosmonitor.h"
#include "session/livesession.h"

namespace {
constexpr qint64 kTickNs = 250'000'000LL;
constexpr qint64 kSyncNs = 1'000'000'000LL;
constexpr std::size_t kMaxRosArrivals = 500'000; ///< between two drains (30 ms): far above any lab's rate
} // namespace

WatchSession::WatchSession(LiveSession* live, QObject* parent)
    : QObject(parent)
    , m_live(live)
    , m_monitor(new LinkMonitor(this))
    , m_rosMonitor(live->rosMonitor())
{
    live->rosMonitor()->keepArrivals(kMaxRosArrivals);
    // The live session may outlive this watch: its listener then does nothing.
    live->addMqttListener(
        [monitor = QPointer<LinkMonitor>(m_monitor)](const std::vector<MqttMessage>& batch) {
            if (monitor)
                monitor->addMqtt(batch);
        });
    connect(live, &LiveSession::drained, this, &WatchSession::update);
    connect(live->rosGraph(), &RosGraphPoller::graphChanged, this, &WatchSession::syncRosTopics);
}

WatchSession::~WatchSession()
{
    // The live session may go first (siblings in a window die in the order they were made).
    if (m_rosMonitor)
        m_rosMonitor->keepArrivals(0);
}

void WatchSession::setConfigs(const QList<std::pair<QString, BridgeConfig>>& configs)
{
    QList<LinkDef> links;
    for (const auto& [name, config] : configs)
        links << LinkDef::fromConfig(config, name);
    m_monitor->setLinks(links, wallClockNs());
    qCDebug(lcWatch) << "watching" << m_monitor->linkCount() << "links of" << configs.size() << "configs";
    syncRosTopics();
}

void WatchSession::update(qint64 nowNs)
{
    m_monitor->addRos(m_live->rosMonitor()->takeArrivals());
    if (nowNs - m_lastSyncNs >= kSyncNs) {
        m_lastSyncNs = nowNs;
        // Types come with the first message: Header.seq can be read from then on.
        const QHash<QString, RosMonitorStats> stats = m_live->rosMonitor()->snapshot(nowNs);
        for (auto it = stats.cbegin(); it != stats.cend(); ++it)
            if (!it->type.isEmpty())
                m_monitor->setRosDefinition(it.key(), it->type, it->definition);
    }
    if (nowNs - m_lastTickNs >= kTickNs) {
        m_lastTickNs = nowNs;
        m_monitor->tick(nowNs);
    }
}

void WatchSession::syncRosTopics()
{
    QStringList graphTopics;
    for (const RosTopicInfo& t : m_live->rosGraph()->graph().topics)
        graphTopics << t.name;
    const QStringList wanted = m_monitor->rosTopicsToMonitor(graphTopics);
    const QSet<QString> want(wanted.cbegin(), wanted.cend());
    RosMonitor* ros = m_live->rosMonitor();
    for (const QString& t : std::as_const(m_monitored))
        if (!want.contains(t))
            ros->unmonitor(t);
    for (const QString& t : want)
        if (!m_monitored.contains(t))
            ros->monitor(t);
    m_monitored = want;
}
