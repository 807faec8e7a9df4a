// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"
#include "session/sessioncontrols.h"
#include "widgets/discover/detailpane.h"

#include <QWidget>

class GraphStatus;
class MqttTopicTree;
class PublishDialog;
class QAction;
class TopicTableModel;
class MqttTopicFilter;
class PasswordStore;
class QCheckBox;
class QComboBox;
class LiveText;
class QLabel;
class QLayout;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTabWidget;
class QSortFilterProxyModel;
class QTableView;
class QTreeView;

/// The Discover page: the ROS graph on the left (ROS 1 through the master, ROS 2 through DDS, or
/// both as two tabs), the broker's topic tree on the right, and what the selected topic carries
/// below them, all live.
class DiscoverPage : public QWidget
{
    Q_OBJECT
public:
    /// Which ROS graphs the page shows.
    enum class RosGraphs { Ros1, Ros2, Both };

    /// What the page shows and drives of a live session: its controls (master, broker, ROS 2
    /// domain), the topic models, the connection (publishing, clearing retained messages), the
    /// graphs' states and what the detail pane reads.
    struct Parts
    {
        SessionControls* controls = nullptr;
        TopicTableModel* rosTopics = nullptr;
        TopicTableModel* ros2Topics = nullptr;
        MqttTopicTree* mqttTopics = nullptr;
        MqttConnection* mqtt = nullptr;
        const GraphStatus* graphs = nullptr;
        DetailPane::Parts detail;
    };
    explicit DiscoverPage(const Parts& parts, QWidget* parent = nullptr);

    /// Shows ROS 1, ROS 2 or both; joins or leaves the ROS 2 domain as needed.
    void setRosGraphs(RosGraphs graphs);
    RosGraphs rosGraphs() const { return m_graphs; }
    /// The ROS 2 domain (and whether discovery stays on this host); joins it again when ROS 2 is shown.
    void setRos2Options(const Ros2Options& options);
    Ros2Options ros2Options() const;
    QComboBox* rosGraphsBox() const { return m_graphsBox; }

    /// Connects to `profile` (and remembers it as the last one used).
    void connectBroker(const MqttProfile& profile);
    void setRosMasterUri(const QString& uri);

    QTreeView* mqttView() const { return m_mqttView; }
    QLineEdit* rosFilter() const { return m_rosFilter; }

    /// Opens a publish dialog for the selected MQTT topic (or level), beside the page.
    PublishDialog* openPublishDialog();
    /// Clears the retained messages at or below the selected MQTT topic or level after asking;
    /// how many were cleared.
    int clearRetained();

signals:
    /// The user entered a master URI (not a program setting one, as the demo does).
    void rosMasterChosen(const QString& uri);
    /// The user picked the graphs to show or the ROS 2 domain (for the window's memory).
    void rosGraphsChosen(RosGraphs graphs, const Ros2Options& options);

private:
    QLayout* createConnectionBar();
    QWidget* createRosPane();
    QWidget* createMqttPane();
    void setUpMqttColumns();
    void createMqttActions();
    void connectSelection();
    /// Opens the detail pane for a selected topic, if it is left as a line.
    void selectTopic();
    void connectSession();
    void updateRosStatus();
    void updateRos2Status();
    void applyRos2();
    void updateMqttStatus();
    void reloadProfiles(const QString& select);
    void editProfile(bool asNew);
    void toggleConnection();

    Parts m_parts;
    PasswordStore* m_passwords;
    QList<MqttProfile> m_profiles;
    QLineEdit* m_masterUri;
    QLabel* m_rosState;
    QComboBox* m_profileBox;
    QPushButton* m_connect;
    QLabel* m_mqttState;
    LiveText* m_counters;
    QLineEdit* m_rosFilter;
    QSortFilterProxyModel* m_rosProxy;
    QTableView* m_rosView;
    QTableView* m_ros2View;
    QTabWidget* m_rosTabs;
    QComboBox* m_graphsBox;
    QSpinBox* m_domain;
    QCheckBox* m_localhostOnly;
    QLabel* m_ros2State;
    QString m_ros2Error;
    RosGraphs m_graphs = RosGraphs::Ros1;
    QLineEdit* m_mqttFilter;
    QCheckBox* m_searchPayloads;
    MqttTopicFilter* m_mqttProxy;
    QTreeView* m_mqttView;
    QAction* m_publishAction = nullptr;
    QAction* m_clearRetainedAction = nullptr;
    DetailPane* m_detail;
    QSplitter* m_split; ///< the lists over the detail pane
    bool m_detailOpened = false;
};
