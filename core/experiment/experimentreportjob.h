// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentreport.h"

#include <atomic>
#include <memory>
#include <QObject>

class QThread;

/// An experiment's report read on a worker thread (ExperimentReport::load() reads every cell's
/// run), as ReportJob does for runs: finished() on the creating thread after the worker has ended.
/// Destroying a running job cancels it and waits for the worker.
class ExperimentReportJob : public QObject
{
    Q_OBJECT
public:
    explicit ExperimentReportJob(QString directory, QObject* parent = nullptr);
    ~ExperimentReportJob() override;

    void start(); ///< once
    void cancel(); ///< from any thread; finished() follows with no report and no error
    bool isRunning() const;
    const QString& directory() const { return m_directory; }

signals:
    /// The report, or null with `error` (empty when cancelled).
    void finished(std::shared_ptr<const ExperimentReport> report, const QString& error);

private:
    QString m_directory;
    QThread* m_worker = nullptr;
    std::atomic<bool> m_cancel {false};
    std::shared_ptr<const ExperimentReport> m_report;
    QString m_error;
};
