// SPDX-License-Identifier: MIT
#pragma once

#include "base/topicmime.h"
#include "config/bridgeconfig.h"
#include "session/livesources.h"

#include <QPointer>
#include <QSet>
#include <QWidget>

class BridgedTopicsProxy;
class ConfigDocument;
class ConfigFileController;
class ConfigTabs;
class ConfigEditor;
class LiveSession;
class MqttConnection;
class MqttTopicFilter;
class MqttTopicTree;
class QAction;
class QLabel;
class QLayout;
class QLineEdit;
class QMimeData;
class QSortFilterProxyModel;
class QTableView;
class QTimer;
class QTreeView;
class QUndoStack;
class RosGraphPoller;
class RosTopicModel;
class Ros2Participant;

/// The Map page: discovered ROS topics and MQTT topics beside the config's mappings. Drag ROS
/// topics onto the MQTT tree (or the mapping table) to bridge them to MQTT, MQTT topics onto the
/// ROS topics to bridge them to ROS, a topic onto a mapping to retarget it; every mapping shows
/// whether it carries data.
class MapPage : public QWidget
{
    Q_OBJECT
public:
    /// What the page reads and drops on: the topic tables and tree, the graphs, the broker's state
    /// and the sources whose figures the health takes.
    struct Parts
    {
        LiveSources sources;
        RosTopicModel* rosTopics = nullptr;
        RosTopicModel* ros2Topics = nullptr;
        MqttTopicTree* mqttTopics = nullptr;
        const RosGraphPoller* rosGraph = nullptr;
        const Ros2Participant* ros2 = nullptr;
        const MqttConnection* mqtt = nullptr;
    };

    /// The parts of a live session the page reads.
    static Parts partsOf(LiveSession* live);

    MapPage(const Parts& parts, ConfigDocument* document, QUndoStack* undoStack, QWidget* parent = nullptr);
    ~MapPage() override;

    ConfigEditor* editor() const { return m_editor; }
    QTableView* rosView() const { return m_rosView; }
    QTreeView* mqttView() const { return m_mqttView; }
    QLineEdit* prefixEdit() const { return m_prefix; }
    QAction* bridgeToMqttAction() const { return m_toMqtt; }
    QAction* bridgeToRosAction() const { return m_toRos; }

    /// Bridges ROS topics to MQTT: onto a single MQTT topic, under a level, or under the prefix.
    QList<quint64> bridgeRosTopics(const QList<TopicMime::Topic>& topics, const QString& mqttTarget);
    /// Bridges MQTT topics to ROS: onto a single ROS topic, beside one, or at the root.
    QList<quint64> bridgeMqttTopics(const QList<TopicMime::Topic>& topics, const QString& rosTarget);
    /// Points a mapping at a dropped topic instead.
    bool retarget(quint64 mappingId, const QMimeData* data);
    /// Re-evaluates every mapping's health now (a timer does it every second otherwise), that of
    /// the shown config and of every other open one (for its tab).
    void updateHealth();
    /// Shows a tab per config `files` has open above the page, each with its health.
    void setFileController(ConfigFileController* files);
    ConfigTabs* configTabs() const { return m_tabs; }
    /// The config is in the ROS 2 layout and a ROS 2 graph is there to map it against.
    bool usesRos2() const;

private:
    /// What one bridging gesture does: new mappings, and existing ones pointed elsewhere.
    struct Plan
    {
        QList<Mapping> created;
        QList<Mapping> before;
        QList<Mapping> after;
    };
    QLayout* createBar();
    QWidget* createRosPane();
    QWidget* createMqttPane();
    void setUpDrops();
    QList<quint64> apply(const Plan& plan, const QString& description);
    static void plan(Plan& p, const BridgeConfig& config, const Mapping& proposed);
    bool dropOnMappings(const QMimeData* data, int row);
    void updateBridgedTopics();
    /// Monitors the MQTT topics of every open config's mappings on the session's MQTT source (and
    /// no other), whose figures the health takes.
    void monitorMappedMqttTopics();
    void bridgeSelectedRos();
    void bridgeSelectedMqtt();

    Parts m_parts; ///< the session may go first when the window closes (m_parts.sources.alive())
    QSet<QString> m_mqttMonitored;
    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    ConfigEditor* m_editor;
    QLineEdit* m_prefix;
    QLabel* m_hint;
    QAction* m_toMqtt;
    QAction* m_toRos;
    BridgedTopicsProxy* m_rosBridged;
    QSortFilterProxyModel* m_rosFilter;
    QTableView* m_rosView;
    BridgedTopicsProxy* m_mqttBridged;
    MqttTopicFilter* m_mqttFilter;
    QTreeView* m_mqttView;
    QTimer* m_healthTimer;
    ConfigFileController* m_files = nullptr;
    ConfigTabs* m_tabs = nullptr;
};
