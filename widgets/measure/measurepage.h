// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QWidget>

class NameDelegate;
class EcdfChart;
class MeasureSession;
class Pipeline;
class PipelineModel;
class RunBar;
class QAbstractItemModel;
class QAction;
class QCheckBox;
class LiveText;
class QLabel;
class QLayout;
class QListView;
class QSpinBox;
class QTableView;
class StampTopicModel;
class TimelineChart;

/// The Measure page: the pipeline (loaded, found in the stamps, or dragged together, with a host
/// per stamp), live ECDFs of the selected series beside the total latency over time, and the
/// paper's Table I with sample counts: its total and derived rows pinned above the charts, the
/// stages below them.
class MeasurePage : public QWidget
{
    Q_OBJECT
public:
    MeasurePage(MeasureSession* measure, QWidget* parent = nullptr);

    Status loadPipeline(const QString& path);
    Status savePipeline(const QString& path);

    EcdfChart* chart() const { return m_chart; }
    RunBar* runBar() const { return m_runBar; }
    /// Saves the chart as PNG or SVG (by the suffix).
    Status saveChart(const QString& path);

    /// How often the page shows new figures while they come (MeasureSession::setPublishInterval).
    static constexpr int kRefreshMs = 500;

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    QLayout* createControls();
    void setUpWindowAndActions();
    QWidget* createPipelinePane();
    void setUpPipelineView();
    QWidget* createChartPane();
    void setUpSummaryView(QAbstractItemModel* styled);
    void updatePinnedRows();
    void showColumnMenu(const QPoint& at);
    void layOut(QLayout* controls, QWidget* pipelinePane, QWidget* chartPane);
    void connectSession();
    void applyEdit(const Pipeline& pipeline);
    void onUpdated();
    void onPipelineChanged();
    void updateCounts();
    void updateWarning();
    void updateClocks();
    void onWarningLink(const QString& link);
    void choosePipelineFile();
    void chooseSaveFile();
    void removeSelectedStamps();
    void moveSelectedStamp(int delta);
    void addSeenTopic(const QModelIndex& index);
    void chooseChartFile();
    void updateEditable();

    MeasureSession* m_measure;
    PipelineModel* m_pipeline;
    StampTopicModel* m_seen;
    EcdfChart* m_chart;
    QTableView* m_statsView;
    /// The total and the derived rows (round trip, one way, clock offset), pinned above the charts.
    QTableView* m_summaryView;
    TimelineChart* m_timeline;
    QTableView* m_pipelineView;
    QListView* m_seenView;
    NameDelegate* m_seenNames = nullptr;
    QSpinBox* m_window;
    QCheckBox* m_log;
    QCheckBox* m_multiples;
    QAction* m_pause;
    QAction* m_reset;
    QLabel* m_mode;
    /// Above the pinned rows: which figures contradict the pipeline, why, and what to do.
    QLabel* m_warning;
    /// Above the pinned rows: the hosts' clocks as measured, and the clock services that do not answer.
    LiveText* m_clocks;
    QString m_clocksTip; ///< what the clocks line is; the hosts' own sync states follow it
    LiveText* m_counts;
    RunBar* m_runBar;
    QList<QWidget*> m_pipelineControls; ///< disabled while recording or showing a run
    QString m_pipelineFile;
};
