// SPDX-License-Identifier: MIT
#pragma once

#include "report/reportformats.h"
#include "report/reportjob.h"

#include <memory>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLayout;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QProgressBar;
class QSpinBox;
class QStackedWidget;
class QTextBrowser;
class QTimer;
class Report;

/// The Reports page: pick runs, suite CSV files or bags, see the report as it will be written,
/// export it in any format. Several inputs compare side by side (or join into one run).
///
/// Reports are computed on a worker thread (a run of a million stamps takes a moment) with
/// progress and cancel; the file is written in one step, never half.
class ReportsPage : public QWidget
{
    Q_OBJECT
public:
    explicit ReportsPage(QWidget* parent = nullptr);
    ~ReportsPage() override;

    void addInputs(const QStringList& paths);
    QStringList inputs() const;
    void setFormat(ReportFormats::Format format);
    ReportFormats::Format format() const;
    void setPipelineFile(const QString& path);

    /// Builds the report and writes it to `path` (in the selected format), with a progress dialog.
    Status exportTo(const QString& path);
    /// What the preview shows now (plain text, or the HTML of rich previews).
    QString previewText() const;
    bool isBusy() const;

    QCheckBox* perSampleBox() const { return m_perSample; }

signals:
    /// The preview shows the report of the current inputs and options.
    void previewUpdated();
    /// Measurements were dropped on the page (from a file manager): the window opens them here,
    /// through its one way of opening files, which adds them as inputs.
    void measurementsDropped(const QStringList& paths);

protected:
    /// Measurements dropped on the page are compared here; anything else goes on to the window.
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    QWidget* createSettingsPane();
    QLayout* createInputButtons();
    QLayout* createForm();
    QWidget* createPreviewPane();
    void chooseInputs();
    void choosePipeline();
    void chooseExport();
    void removeSelected();
    void moveSelected(int delta);
    void schedulePreview();
    void startPreview();
    void showPreview(const std::shared_ptr<Report>& report, const QString& error);
    /// What the page's fields ask for; an error when the pipeline file does not load.
    Result<ReportJob::Request> request() const;
    Result<QByteArray> render(const Report& report, ReportFormats::Format format) const;

    QListWidget* m_inputs;
    QComboBox* m_format;
    QLineEdit* m_pipeline;
    QSpinBox* m_window;
    QCheckBox* m_join;
    QCheckBox* m_perSample;
    QLineEdit* m_title;
    QStackedWidget* m_previewStack;
    QPlainTextEdit* m_text;
    QTextBrowser* m_rich;
    QProgressBar* m_progress;
    QLabel* m_status;
    QTimer* m_debounce;
    ReportJob* m_job = nullptr; ///< the preview being computed
    bool m_again = false; ///< the fields changed meanwhile: compute again when it ends
    QString m_preview;
};
