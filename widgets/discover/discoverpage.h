// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttconnection.h"

#include <QWidget>

class DetailPane;
class PublishDialog;
class QAction;
class LiveSession;
class MqttTopicFilter;
class PasswordStore;
class QCheckBox;
class QComboBox;
class QLabel;
class QLayout;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;
class QTreeView;

/// The Discover page: the ROS graph on the left, the broker's topic tree in the middle, and what
/// the selected topic carries on the right, all live.
class DiscoverPage : public QWidget
{
    Q_OBJECT
public:
    explicit DiscoverPage(LiveSession* session, QWidget* parent = nullptr);

    /// Connects to `profile` (and remembers it as the last one used).
    void connectBroker(const MqttProfile& profile);
    void setRosMasterUri(const QString& uri);

    QTableView* rosView() const { return m_rosView; }
    QTreeView* mqttView() const { return m_mqttView; }
    DetailPane* detail() const { return m_detail; }
    QLineEdit* rosFilter() const { return m_rosFilter; }
    QLineEdit* mqttFilter() const { return m_mqttFilter; }
    MqttTopicFilter* mqttFilterModel() const { return m_mqttProxy; }
    QSortFilterProxyModel* rosFilterModel() const { return m_rosProxy; }
    QLabel* mqttStatus() const { return m_mqttState; }
    QLabel* rosStatus() const { return m_rosState; }
    QAction* publishAction() const { return m_publishAction; }
    QAction* clearRetainedAction() const { return m_clearRetainedAction; }

    /// Opens a publish dialog for the selected MQTT topic (or level), beside the page.
    PublishDialog* openPublishDialog();
    /// Clears the retained messages at or below the selected MQTT topic or level after asking;
    /// how many were cleared.
    int clearRetained();

signals:
    /// The user entered a master URI (not a program setting one, as the demo does).
    void rosMasterChosen(const QString& uri);

private:
    QLayout* createConnectionBar();
    QWidget* createRosPane();
    QWidget* createMqttPane();
    void createMqttActions();
    void connectSelection();
    void connectSession();
    void updateRosStatus();
    void updateMqttStatus();
    void reloadProfiles(const QString& select);
    void editProfile(bool asNew);
    void toggleConnection();

    LiveSession* m_session;
    PasswordStore* m_passwords;
    QList<MqttProfile> m_profiles;
    QLineEdit* m_masterUri;
    QLabel* m_rosState;
    QComboBox* m_profileBox;
    QPushButton* m_connect;
    QLabel* m_mqttState;
    QLabel* m_counters;
    QLineEdit* m_rosFilter;
    QSortFilterProxyModel* m_rosProxy;
    QTableView* m_rosView;
    QLineEdit* m_mqttFilter;
    QCheckBox* m_searchPayloads;
    MqttTopicFilter* m_mqttProxy;
    QTreeView* m_mqttView;
    QAction* m_publishAction = nullptr;
    QAction* m_clearRetainedAction = nullptr;
    DetailPane* m_detail;
};
