// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/linkprobe.h"
#include "mqtt/mqttprofile.h"

#include <memory>
#include <QDialog>
#include <QTimer>
#include <vector>

class EcdfChart;
class LatencySeriesSet;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLayout;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

/// `bridgescope probe` as a window: round trips through a broker (or a rate sweep) with the
/// counts, the round-trip statistics and their ECDF growing while it runs.
///
/// LinkProbe measures on its own threads; a 200 ms timer takes its progress (counts and the new
/// round trips) and feeds a LatencySeriesSet whose series the ECDF chart draws, one series
/// per step. Widgets are touched on the GUI thread only.
class ProbeDialog : public QDialog
{
    Q_OBJECT
public:
    /// The figures the dialog shows, as label texts.
    enum Figure { Sent, Received, Lost, OutOfOrder, Mean, Median, Std, Min, Max, P99, FigureCount };

    explicit ProbeDialog(QWidget* parent = nullptr);
    ~ProbeDialog() override;

    /// The broker to probe (its TLS and credentials are used while the URL stays unchanged).
    void setProfile(const MqttProfile& profile);
    bool isRunning() const { return m_running; }

    QSpinBox* sizeBox() const { return m_size; }
    QCheckBox* viaEchoBox() const { return m_viaEcho; }
    QLabel* figure(Figure f) const { return m_figures[f]; }
    EcdfChart* chart() const { return m_chart; }

    void start();
    void stop();

public slots:
    void reject() override;

signals:
    void probeFinished(const LinkProbeReport& report);

private:
    QLayout* createSettingsColumn();
    QLayout* createSettingsForm();
    QLayout* createResultsColumn();
    void connectProbe();
    LinkProbeOptions options() const;
    void setRunning(bool running);
    void poll();
    void onStepFinished(const LinkProbeStep& step);
    void onFinished(const LinkProbeReport& report);
    QString seriesOf(int step, double rateHz);
    void showChart(const QStringList& ids);
    void showCounts(qint64 sent, qint64 received, const QString& lost, qint64 outOfOrder);
    void showStats(const LatencyStats& stats);
    void addStepRow(const LinkProbeStep& step, bool best);
    void showTitles(const QString& rate);
    void showError(const QString& error);
    QString hz(double value) const;
    QString ms(double value) const;

    LinkProbe* m_probe;
    MqttProfile m_profile;
    std::unique_ptr<LatencySeriesSet> m_series; ///< one series per step
    std::vector<QString> m_stepSeries; ///< engine series name per step
    int m_step = -1; ///< the step the counts and the chart show
    quint64 m_drawn = ~quint64(0); ///< engine revision the chart shows
    QTimer m_poll;
    bool m_running = false;
    bool m_sweepRun = false;

    QLineEdit* m_broker;
    QSpinBox* m_size;
    QDoubleSpinBox* m_rate;
    QComboBox* m_qos;
    QSpinBox* m_count;
    QCheckBox* m_sweep;
    QCheckBox* m_viaEcho;
    QPushButton* m_start;
    QPushButton* m_stop;
    QLabel* m_status;
    QLabel* m_error;
    QLabel* m_countsTitle;
    QLabel* m_statsTitle;
    QLabel* m_figures[FigureCount] = {};
    QGroupBox* m_sweepGroup;
    QTableWidget* m_steps;
    QLabel* m_sweepResult;
    EcdfChart* m_chart;
};
