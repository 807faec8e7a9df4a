// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"
#include "mqtt/mqttsource.h"
#include "ros/rosmasterapi.h"
#include "ros/rosmonitor.h"
#include "ros2/ros2participant.h"
#include "session/livesources.h"
#include "session/sessioncontrols.h"

#include <functional>
#include <memory>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <vector>

class GraphStatus;
class MqttTopicTree;
class RosGraphPoller;
class RosMonitor;
class TopicTableModel;
class RosTypeRegistry;

/// The live side of the application: the ROS master poller, the roscpp monitor, the ROS 2
/// participant (when a ROS 2 graph is asked for), the MQTT connection, and the models they feed,
/// drained on one GUI-thread timer (about 30 Hz).
///
/// Network threads never touch a model: every tick takes what the buffers collected, hands the
/// MQTT batch to listeners (the latency engine, mapping health) and then to the topic tree, and
/// refreshes monitor figures. Nothing is emitted per network message.
class LiveSession : public QObject, public SessionControls
{
    Q_OBJECT
public:
    using MqttListener = LiveSources::MqttListener;

    explicit LiveSession(QObject* parent = nullptr);
    ~LiveSession() override;

    void setRosMasterUri(const QString& uri) override;
    QString rosMasterUri() const override;
    void connectBroker(const MqttProfile& profile) override;
    void disconnectBroker() override;

    /// Joins a ROS 2 domain (leaving the one before); the ROS 2 topics fill ros2Topics().
    Status startRos2(const Ros2Options& options) override;
    void stopRos2() override;
    bool isRos2Running() const override { return m_ros2->isRunning(); }
    Ros2Participant* ros2() const { return m_ros2; }
    TopicTableModel* ros2Topics() const { return m_ros2Topics; }
    /// The ROS 2 definitions ROS 2 samples decode with (bundled, and those under the folders of
    /// setRos2DefinitionFolders()).
    const RosTypeRegistry& ros2Types() const { return *m_ros2Types; }
    void setRos2DefinitionFolders(const QStringList& folders, QStringList* errors = nullptr);

    RosGraphPoller* rosGraph() const { return m_poller; }
    /// Both ROS graphs as the pages show them, whichever transport holds each.
    const GraphStatus* graphStatus() const { return m_graphStatus; }
    RosMonitor* rosMonitor() const { return m_monitor; }
    TopicTableModel* rosTopics() const { return m_rosTopics; }
    /// A graph's topics as a MessageSource: the ROS 1 monitor, the ROS 2 participant, or the
    /// broker's topics (fed with every drain's batch before the listeners have it).
    MessageSource* source(SourceGraph graph) const;
    /// The three sources with this session as their owner and drain, for a consumer to be handed.
    LiveSources sources() const { return m_sources; }
    MqttConnection* mqtt() const { return m_mqtt; }
    MqttTopicTree* mqttTopics() const { return m_tree; }

    /// Adds a listener for every tick's MQTT batch; the id removes it again.
    int addMqttListener(MqttListener listener);
    void removeMqttListener(int id);
    /// Runs one drain now (tests; the timer does it otherwise).
    void drainNow();
    int drainIntervalMs() const { return m_timer.interval(); }
    /// Figures read by eye (the topic tree's, the ROS topics' rates) go to their models at most
    /// once per `ms` (0, the default: at every drain); what is measured is not touched by it.
    void setFiguresInterval(int ms);
    /// No view reads those figures at all (a watch): neither the topic tree's rates nor the ROS
    /// topics' statistics are worked out, each an O(topics) walk a second (perf: a fifth of an idle
    /// watch's CPU at 10,000 links).
    void setNoTopicViews() { m_topicViews = false; }

signals:
    /// After every drain, with the wall-clock time it used.
    void drained(qint64 nowNs);

private:
    RosGraphPoller* m_poller;
    RosMonitor* m_monitor;
    TopicTableModel* m_rosTopics;
    MqttConnection* m_mqtt;
    MqttTopicTree* m_tree;
    Ros2Participant* m_ros2;
    GraphStatus* m_graphStatus;
    TopicTableModel* m_ros2Topics;
    std::unique_ptr<MqttSource> m_mqttSource;
    LiveSources m_sources;
    std::shared_ptr<const RosTypeRegistry> m_ros2Types;
    std::vector<std::pair<int, MqttListener>> m_listeners;
    int m_nextListener = 1;
    QTimer m_timer;
    qint64 m_figuresIntervalNs = 0;
    qint64 m_figuresSetNs = 0;
    bool m_topicViews = true;
};
