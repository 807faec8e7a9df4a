// SPDX-License-Identifier: MIT
#pragma once

#include "wire/payloadtext.h"

#include <QWidget>

class LiveSession;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QStandardItemModel;
class QTabWidget;
class QTableWidget;
class QTreeView;
class RateChart;
struct RosValue;

/// What one selected topic carries: its fields (decoded ROS message or JSON), the raw payload
/// as text, JSON or hex, its recent history, its rate, and the broker's statistics.
class DetailPane : public QWidget
{
    Q_OBJECT
public:
    explicit DetailPane(LiveSession* session, QWidget* parent = nullptr);

    void showRosTopic(const QString& topic);
    void showMqttTopic(const QString& topic);
    /// Updates from the latest data, if the topic got anything new.
    void refresh();

    QString topic() const { return m_topic; }
    QTreeView* fieldsView() const { return m_fields; }
    QPlainTextEdit* payloadView() const { return m_payload; }
    QLabel* payloadNote() const { return m_payloadNote; }
    QLabel* title() const { return m_title; }

private:
    void refreshMqtt(bool force);
    void refreshRos(bool force);
    void refreshBroker();
    void showFields(const RosValue& value);
    void showJsonFields(const QByteArray& json);
    void showPayload(const QByteArray& payload);
    void showNoFields(const QString& why);

    LiveSession* m_session;
    enum class Kind { None, Ros, Mqtt } m_kind = Kind::None;
    QString m_topic;
    quint64 m_shownMessages = ~0ull;
    QByteArray m_lastPayload;
    QList<double> m_rosRates;
    qint64 m_lastRosSample = 0;
    QLabel* m_title;
    QTabWidget* m_tabs;
    QTreeView* m_fields;
    QStandardItemModel* m_fieldModel;
    QComboBox* m_mode;
    QLabel* m_payloadNote;
    QPlainTextEdit* m_payload;
    QTableWidget* m_history;
    RateChart* m_rate;
    QTableWidget* m_broker;
};
