// SPDX-License-Identifier: MIT
#pragma once

#include "text/topicmime.h"
#include "config/bridgeconfig.h"
#include "session/flowrates.h"
#include "session/livesources.h"

#include <QPointer>
#include <QSet>
#include <QWidget>

class BridgedTopicsProxy;
class ConfigDocument;
class ConfigFileController;
class ConfigTabs;
class ConfigEditor;
class GraphStatus;
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
class TopicTableModel;
class TopicTree;

/// The Map page: the config's mappings across the page, the inspector and problems below them,
/// and beside them a panel (that folds away) of the discovered topics, ROS and MQTT each as a
/// namespace tree. Drag ROS topics onto the MQTT tree (or the mapping table) to bridge them to
/// MQTT, MQTT topics onto the ROS tree to bridge them to ROS, a topic onto a mapping to retarget
/// it; every mapping shows whether it carries data.
class MapPage : public QWidget
{
    Q_OBJECT
public:
    /// What the page reads and drops on: the topic tables and tree, the graphs, the broker's state
    /// and the sources whose figures the health takes.
    struct Parts
    {
        LiveSources sources;
        TopicTableModel* rosTopics = nullptr;
        TopicTableModel* ros2Topics = nullptr;
        MqttTopicTree* mqttTopics = nullptr;
        const GraphStatus* graphs = nullptr;
        const MqttConnection* mqtt = nullptr;
    };

    MapPage(const Parts& parts, ConfigDocument* document, QUndoStack* undoStack, QWidget* parent = nullptr);
    ~MapPage() override;

    ConfigEditor* editor() const { return m_editor; }
    TopicTree* rosTree() const { return m_rosTree; }
    QAction* bridgeToMqttAction() const { return m_toMqtt; }
    QAction* bridgeToRosAction() const { return m_toRos; }

    /// Bridges ROS topics to MQTT: onto a single MQTT topic, under a level, or under the prefix.
    QList<quint64> bridgeRosTopics(const QList<TopicMime::Topic>& topics, const QString& mqttTarget);
    /// Bridges MQTT topics to ROS. `rosTarget` is where they were dropped: a namespace ("/a/",
    /// trailing slash) takes them below it; a topic takes one MQTT topic exactly (it publishes
    /// onto that topic), while several keep their own names at the root as if dropped beside the
    /// rows: a topic is not a namespace (issue 40: `plant/*` dropped on `/…/pointcloud/in` went
    /// below `/…/pointcloud/`). No target: at the root.
    QList<quint64> bridgeMqttTopics(const QList<TopicMime::Topic>& topics, const QString& rosTarget);
    /// Points a mapping at a dropped topic instead.
    bool retarget(quint64 mappingId, const QMimeData* data);
    /// Re-evaluates every mapping's health now (a timer does it every second otherwise), that of
    /// the shown config and of every other open one (for its tab).
    void updateHealth();
    /// Shows a tab per config `files` has open above the page, each with its health.
    void setFileController(ConfigFileController* files);
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
    QWidget* createTopicsPanel();
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
    Subscriptions m_mqttMonitored; ///< the mapped MQTT topics, for their health
    ConfigDocument* m_doc;
    QUndoStack* m_undo;
    ConfigEditor* m_editor;
    QLineEdit* m_prefix;
    QLabel* m_hint;
    QAction* m_toMqtt;
    QAction* m_toRos;
    BridgedTopicsProxy* m_rosBridged;
    QSortFilterProxyModel* m_rosFilter;
    TopicTree* m_rosTree;
    QTreeView* m_rosView;
    QWidget* m_topicsPanel;
    /// Shows or folds away the panel of discovered topics.
    QAction* m_showTopics;
    FlowRates m_flows;
    BridgedTopicsProxy* m_mqttBridged;
    MqttTopicFilter* m_mqttFilter;
    QTreeView* m_mqttView;
    QTimer* m_healthTimer;
    ConfigFileController* m_files = nullptr;
    ConfigTabs* m_tabs = nullptr;
};
