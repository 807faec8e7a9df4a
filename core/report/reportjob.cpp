// SPDX-License-Identifier: MIT
#include "reportjob.h"

#include <QThread>

ReportJob::ReportJob(Request request, QObject* parent)
    : QObject(parent)
    , m_request(std::move(request))
{ }

ReportJob::~ReportJob()
{
    cancel();
    if (m_worker)
        m_worker->wait();
}

void ReportJob::start()
{
    Q_ASSERT(!m_worker);
    if (m_worker)
        return;
    // The worker writes m_report, m_error and m_warnings; they are read only after it has ended.
    m_worker = QThread::create([this] {
        int last = -1;
        Result<Report> r = Report::build(m_request.inputs, m_request.pipeline, m_request.options, &m_warnings,
                                         [this, &last](int percent) {
                                             if (percent != last) {
                                                 last = percent;
                                                 emit progress(percent);
                                             }
                                             return !m_cancel.load();
                                         });
        if (!r)
            m_error = r.error().toString();
        else if (!m_cancel.load())
            m_report = std::make_shared<Report>(std::move(*r));
    });
    m_worker->setParent(this);
    connect(m_worker, &QThread::finished, this, [this] {
        if (m_cancel.load()) {
            m_report.reset();
            m_error.clear();
        }
        emit finished(m_report, m_error, m_warnings);
    });
    m_worker->start();
}

void ReportJob::cancel()
{
    m_cancel = true;
}

bool ReportJob::isRunning() const
{
    return m_worker && m_worker->isRunning();
}
