// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"

#include <functional>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <vector>

class MqttTopicTree;
class RosGraphPoller;
class RosMonitor;
class RosTopicModel;

/// The live side of the application: the ROS master poller, the roscpp monitor, the MQTT
/// connection, and the models they feed, drained on one GUI-thread timer (about 30 Hz).
///
/// Network threads never touch a model: every tick takes what the buffers collected, hands the
/// MQTT batch to listeners (the latency engine, mapping health) and then to the topic tree, and
/// refreshes monitor figures. Nothing is emitted per network message.
class LiveSession : public QObject
{
    Q_OBJECT
public:
    using MqttListener = std::function<void(const std::vector<MqttMessage>& batch)>;

    explicit LiveSession(QObject* parent = nullptr);
    ~LiveSession() override;

    void setRosMasterUri(const QString& uri);
    QString rosMasterUri() const;
    void connectBroker(const MqttProfile& profile);
    void disconnectBroker();

    RosGraphPoller* rosGraph() const { return m_poller; }
    RosMonitor* rosMonitor() const { return m_monitor; }
    RosTopicModel* rosTopics() const { return m_rosTopics; }
    MqttConnection* mqtt() const { return m_mqtt; }
    MqttTopicTree* mqttTopics() const { return m_tree; }

    /// Adds a listener for every tick's MQTT batch; the id removes it again.
    int addMqttListener(MqttListener listener);
    void removeMqttListener(int id);
    /// Runs one drain now (tests; the timer does it otherwise).
    void drainNow();
    int drainIntervalMs() const { return m_timer.interval(); }

signals:
    /// After every drain, with the wall-clock time it used.
    void drained(qint64 nowNs);

private:
    RosGraphPoller* m_poller;
    RosMonitor* m_monitor;
    RosTopicModel* m_rosTopics;
    MqttConnection* m_mqtt;
    MqttTopicTree* m_tree;
    std::vector<std::pair<int, MqttListener>> m_listeners;
    int m_nextListener = 1;
    QTimer m_timer;
};
