// SPDX-License-Identifier: MIT
#pragma once

#include "session/fieldplotter.h"
#include "wire/payloadtext.h"

#include <QWidget>

class FieldPlotChart;
class GraphStatus;
class QAction;
class QListWidget;
class QComboBox;
class QBoxLayout;
class QSpinBox;
class QLabel;
class QPlainTextEdit;
class QStandardItemModel;
class QTabWidget;
class QTableWidget;
class QTreeView;
class RateChart;
class TopicTableModel;
struct RosValue;

/// What one selected topic carries: its fields (decoded ROS message or JSON), the raw payload
/// as text, JSON or hex, its recent history, its rate, and the broker's statistics.
class DetailPane : public QWidget
{
    Q_OBJECT
public:
    enum FieldRole {
        FieldPathRole = Qt::UserRole + 1, ///< QStringList: the field's path (FieldPath)
        NumericRole, ///< bool: the field can be plotted
    };

    /// What the pane reads: the plotter's parts (the sources, the MQTT tree, the ROS 2 graph and
    /// definitions, the ROS topics), and the ROS 2 topics' figures.
    struct Parts
    {
        FieldPlotter::Parts live;
        const TopicTableModel* ros2Topics = nullptr;
        const GraphStatus* graphs = nullptr; ///< a ROS 2 topic's endpoints and their QoS
    };

    explicit DetailPane(const Parts& parts, QWidget* parent = nullptr);

    void showRosTopic(const QString& topic);
    /// A ROS 2 topic: its samples decode as CDR with the session's ROS 2 definitions.
    void showRos2Topic(const QString& topic);
    void showMqttTopic(const QString& topic);
    /// Updates from the latest data, if the topic got anything new.
    void refresh();

    QString topic() const { return m_topic; }
    QLabel* title() const { return m_title; }
    /// Plots the numeric field at `index` of the fields view over time; false if it is none.
    bool plotField(const QModelIndex& index);
    /// What a legend entry's icon and the margins around its text take of its width.
    static constexpr int kLegendMargins = 16;
    /// The height of `text` wrapped to `width` as the legend wraps it (whole, never cut).
    static int wrappedHeight(const QString& text, const QFont& font, int width);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* createPlotTab();
    QBoxLayout* createBufferRow(QWidget* page);
    void showPlots();
    /// Each legend entry as tall as its name wrapped to the list's width.
    void fitLegend();
    void refreshMqtt(bool force);
    void refreshRos(bool force);
    void refreshBroker();
    void showFields(const RosValue& value);
    void showJsonFields(const QByteArray& json);
    void showPayload(const QByteArray& payload);
    void showNoFields(const QString& why);
    QStringList clearFields();
    void restoreCurrentField(const QStringList& path);

    Parts m_parts;
    enum class Kind { None, Ros, Ros2, Mqtt } m_kind = Kind::None;
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
    FieldPlotter* m_plotter;
    FieldPlotChart* m_plotChart;
    QListWidget* m_plotList;
    QSpinBox* m_plotSeconds;
    QSpinBox* m_plotPoints;
    QLabel* m_plotNote;
    QAction* m_plotAction;
};
