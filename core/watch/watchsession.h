// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkmonitor.h"

#include <QObject>
#include <QPointer>

class LiveSession;
class RosMonitor;

/// Watching links live: feeds a LinkMonitor from a LiveSession (the MQTT batches of every drain,
/// the ROS monitor's arrivals), keeps the ROS subscriptions in step with the links and the ROS
/// graph, and ticks the monitor four times a second. Broker and master restarts are the live
/// session's business (it reconnects and registers again); the links simply resume.
class WatchSession : public QObject
{
    Q_OBJECT
public:
    explicit WatchSession(LiveSession* live, QObject* parent = nullptr);
    ~WatchSession() override;

    LinkMonitor* monitor() const { return m_monitor; }
    LiveSession* live() const { return m_live; }
    /// Watches the links of these configs (name, config), replacing what was watched.
    void setConfigs(const QList<std::pair<QString, BridgeConfig>>& configs);
    void setRules(const WatchRules& rules) { m_monitor->setRules(rules); }
    /// Runs the ROS and tick work now (tests; the live session's drain does it otherwise).
    void update(qint64 nowNs);

private:
    void syncRosTopics();

    LiveSession* m_live;
    LinkMonitor* m_monitor;
    QPointer<RosMonitor> m_rosMonitor;
    qint64 m_lastTickNs = 0;
    qint64 m_lastSyncNs = 0;
    QSet<QString> m_monitored;
};
