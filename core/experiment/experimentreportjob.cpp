// SPDX-License-Identifier: MIT
#include "experimentreportjob.h"

#include <QThread>

ExperimentReportJob::ExperimentReportJob(QString directory, QObject* parent)
    : QObject(parent)
    , m_directory(std::move(directory))
{ }

ExperimentReportJob::~ExperimentReportJob()
{
    cancel();
    if (m_worker)
        m_worker->wait();
}

void ExperimentReportJob::start()
{
    Q_ASSERT(!m_worker);
    if (m_worker)
        return;
    // The worker writes m_report and m_error; they are read only after it has ended.
    m_worker = QThread::create([this] {
        Result<ExperimentReport> r
            = ExperimentReport::load(m_directory, [this](int) { return !m_cancel.load(); });
        if (!r)
            m_error = r.error().toString();
        else if (!m_cancel.load())
            m_report = std::make_shared<const ExperimentReport>(std::move(*r));
    });
    m_worker->setParent(this);
    connect(m_worker, &QThread::finished, this, [this] {
        if (m_cancel.load()) {
            m_report.reset();
            m_error.clear();
        }
        emit finished(m_report, m_error);
    });
    m_worker->start();
}

void ExperimentReportJob::cancel()
{
    m_cancel = true;
}

bool ExperimentReportJob::isRunning() const
{
    return m_worker && m_worker->isRunning();
}
