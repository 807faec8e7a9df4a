// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentplan.h"
#include "experiment/experimentreport.h"
#include "experiment/experimentrunner.h"

class ExperimentProcess;
class ExperimentReportJob;
struct ExperimentEvent;
enum class ExperimentExit : int;

#include <memory>
#include <optional>
#include <QWidget>

class ColumnFitter;
class EcdfChart;
class LatencySeriesSet;
class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;
class QTextBrowser;
class QTimer;

/// The Experiments page: a plan (opened, an example, or typed) checked as it is edited, its cells
/// in a grid coloured by state, the running cell's totals as a live ECDF beside those of the cells
/// before it, any finished cell opened on the Measure page, and the experiment's report.
///
/// The experiment runs as `bridgescope experiment` in a child process (ExperimentProcess); its
/// events drive the page, its progress lines go to the log, and the report is read by an
/// ExperimentReportJob. The page lays out and draws. Stopping lets the child clean up; Resume goes on.
class ExperimentPage : public QWidget
{
    Q_OBJECT
public:
    explicit ExperimentPage(QWidget* parent = nullptr);
    ~ExperimentPage() override;

    /// Opens a plan file into the editor (and proposes a folder beside it).
    Status openPlan(const QString& path);
    /// Opens an experiment's folder: its plan, the state of its cells, its report.
    Status openFolder(const QString& directory);
    void setPlanText(const QString& text);
    QString planText() const;
    void setPlanPath(const QString& path);
    QString planPath() const { return m_planPath; }
    void setFolder(const QString& directory);
    QString folder() const;

    /// The bridgescope binary that runs the experiment (default: this program).
    void setProgram(const QString& path) { m_program = path; }
    /// Saves the plan (when edited) and starts the experiment; an error when it cannot.
    Status run(bool resume);
    /// Asks the running experiment to stop after cleaning up.
    void stop();
    bool isRunning() const;
    /// Computes the report of the folder again (on a worker thread).
    void refreshReport();

    /// The plan's cells as the grid shows them, and their states.
    const QList<ExperimentCell>& cells() const { return m_cells; }
    const QList<CellStatus>& statuses() const { return m_statuses; }
    /// Of the last report computed (nullopt before the first).
    const std::optional<ExperimentReport>& report() const { return m_report; }

    /// The cell grid's (object name "cellGrid") columns: a level per factor, then this one (the
    /// state), samples, total median, total p99, the cell's id.
    int stateColumn() const;
    /// The running and finished cells' totals the chart draws, per cell label.
    const LatencySeriesSet* liveSeries() const { return m_series.get(); }
    /// Exports the report in `format` ("md", "html", "tex", "csv", "json" or "pdf", by the suffix
    /// when empty); Markdown gets its ECDF figures beside it as SVG.
    Status exportReport(const QString& path, const QString& format = QString());

signals:
    /// The user asked to see a finished cell's run on the Measure page.
    void openRunRequested(const QString& path);
    /// The experiment's child process ended (exit status as the command's).
    void experimentFinished(int exitCode);
    /// A report of the folder was computed (or failed: report() is then nullopt).
    void reportUpdated();

private:
    QWidget* createPlanPane();
    QWidget* createCellsPane();
    QWidget* createViewsPane();
    QLayout* createRunBar();
    void checkPlan();
    void rebuildGrid();
    void updateRow(int row);
    void updateButtons();
    void showCounts();
    void showLogLine(const QString& line);
    void handleEvent(const ExperimentEvent& event);
    void processFinished(ExperimentExit status, int exitCode);
    void takeReport();
    void loadState();
    void showReport();
    void openCell(int row);
    void chooseFolder();
    void choosePlan();
    void savePlanAs();
    void chooseExport();
    void loadExample(int index);
    QString seriesName(int cell) const;

    QPlainTextEdit* m_editor;
    QLabel* m_planStatus;
    QLineEdit* m_folder;
    QComboBox* m_examples;
    QTableWidget* m_grid;
    ColumnFitter* m_gridFitter; ///< the state and the figures whole as they come
    QTabWidget* m_views;
    EcdfChart* m_chart;
    QTextBrowser* m_reportView;
    QComboBox* m_statistic;
    QPushButton* m_run;
    QPushButton* m_resume;
    QPushButton* m_stop;
    QPushButton* m_export;
    QProgressBar* m_progress;
    QLabel* m_status;
    QPlainTextEdit* m_log;
    QTimer* m_check; ///< the plan is checked once the typing pauses
    QTimer* m_redraw; ///< the live ECDF at most 4 times a second
    ExperimentProcess* m_process;
    ExperimentReportJob* m_reportJob = nullptr;
    bool m_reportAgain = false;
    QString m_planPath;
    QString m_program;
    bool m_planEdited = false;
    std::optional<ExperimentPlan> m_plan; ///< the editor's text, when it is a plan
    QList<ExperimentCell> m_cells;
    QStringList m_cellIds; ///< of the grid as built, and its factors: rebuilt when they change
    QStringList m_gridFactors;
    QString m_reportFolder; ///< the folder m_report was (or is being) read from
    QList<CellStatus> m_statuses;
    std::unique_ptr<LatencySeriesSet> m_series; ///< per cell, its totals in ns
    quint64 m_drawn = ~quint64(0);
    std::optional<ExperimentReport> m_report;
    QString m_reportError;
};
