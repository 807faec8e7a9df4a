// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class MqttConnection;
class MqttTopicTree;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

/// Publishes one message to an MQTT topic: text, JSON (checked before sending), or a ROS message
/// of the type mqtt_client announced for the topic, typed as YAML or JSON and prefilled from the
/// last message. Stays open for the next message; publishing never waits for the broker.
class PublishDialog : public QDialog
{
    Q_OBJECT
public:
    enum Format { Text, Json, RosMessage };

    PublishDialog(MqttConnection* connection, MqttTopicTree* topics, const QString& topic,
                  QWidget* parent = nullptr);

    /// Builds the payload and sends it; false (and the status says why) when nothing was sent.
    bool publish();

private:
    void topicChanged();
    void formatChanged();
    void setStatus(const QString& text, bool error);

    MqttConnection* m_connection;
    MqttTopicTree* m_topics;
    QLineEdit* m_topic;
    QComboBox* m_qos;
    QCheckBox* m_retained;
    QComboBox* m_format;
    QPlainTextEdit* m_payload;
    QLabel* m_note;
    QLabel* m_status;
    QPushButton* m_publish;
    int m_shownFormat = -1;
};
