// SPDX-License-Identifier: MIT
#pragma once

#include "latency/pipeline.h"
#include "report/report.h"

#include <atomic>
#include <memory>
#include <optional>
#include <QObject>
#include <QStringList>

class QThread;

/// One report computed on a worker thread: the inputs read (bags in the helper process), replayed
/// and summed up, with progress on the way and a cancel that takes effect within one step.
///
/// The object lives on the thread that creates it, and so do its signals' receivers: progress()
/// is emitted from the worker (queued to them), finished() on the creating thread after the worker
/// has ended. Destroying a running job cancels it and waits for the worker.
class ReportJob : public QObject
{
    Q_OBJECT
public:
    struct Request
    {
        QStringList inputs;
        std::optional<Pipeline> pipeline; ///< nullopt: each input's own
        Report::Options options;
    };

    explicit ReportJob(Request request, QObject* parent = nullptr);
    ~ReportJob() override;

    void start(); ///< once
    void cancel(); ///< from any thread; finished() follows with no report
    bool isRunning() const;
    bool isCancelled() const { return m_cancel.load(); }

signals:
    void progress(int percent); ///< 0..100, each value once
    /// The report, or null with `error` (empty when cancelled); `warnings` are skipped rows.
    void finished(std::shared_ptr<Report> report, const QString& error, const QStringList& warnings);

private:
    Request m_request;
    QThread* m_worker = nullptr;
    std::atomic<bool> m_cancel {false};
    std::shared_ptr<Report> m_report;
    QString m_error;
    QStringList m_warnings;
};
