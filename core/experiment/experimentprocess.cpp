// SPDX-License-Identifier: MIT
#include "experimentprocess.h"

#include <QProcess>

using namespace Qt::StringLiterals;

namespace {
/// A line of standard error longer than this is not the command's and is dropped.
constexpr qsizetype kMaxErrorLineBytes = ExperimentEvent::kMaxLineBytes;
} // namespace

ExperimentProcess::ExperimentProcess(QObject* parent)
    : QObject(parent)
{ }

ExperimentProcess::~ExperimentProcess()
{
    if (!isRunning())
        return;
    // The child stops its lab's servers and bridges; a window closing waits for that, briefly.
    m_process->disconnect(this);
    m_process->terminate();
    if (!m_process->waitForFinished(15000))
        m_process->kill();
    m_process->waitForFinished(2000);
}

bool ExperimentProcess::start(const QString& program, const QString& plan, const QString& directory,
                              bool resume)
{
    if (isRunning())
        return false;
    m_arguments = {u"experiment"_s, plan, u"-o"_s, directory};
    if (resume)
        m_arguments << u"--resume"_s;
    delete m_process;
    m_process = new QProcess(this);
    m_process->setProgram(program);
    m_process->setArguments(m_arguments);
    connect(m_process, &QProcess::readyReadStandardOutput, this, &ExperimentProcess::readOutput);
    connect(m_process, &QProcess::readyReadStandardError, this, &ExperimentProcess::readErrors);
    connect(m_process, &QProcess::finished, this, [this](int exitCode, QProcess::ExitStatus status) {
        readOutput();
        readErrors();
        const bool crashed = status == QProcess::CrashExit;
        emit finished(exitOf(exitCode, crashed), crashed ? -1 : exitCode);
    });
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e == QProcess::FailedToStart)
            emit failedToStart(m_process->errorString());
    });
    m_events = ExperimentEventReader();
    m_stderrRest.clear();
    m_process->start();
    return true;
}

void ExperimentProcess::stop()
{
    if (isRunning())
        m_process->terminate();
}

bool ExperimentProcess::isRunning() const
{
    return m_process && m_process->state() != QProcess::NotRunning;
}

ExperimentExit ExperimentProcess::exitOf(int exitCode, bool crashed)
{
    if (crashed)
        return ExperimentExit::Crashed;
    for (auto s : {ExperimentExit::Complete, ExperimentExit::CellFailed, ExperimentExit::Usage, ExperimentExit::Stopped})
        if (int(s) == exitCode)
            return s;
    return ExperimentExit::Usage; // another status: the command's own message says why
}

void ExperimentProcess::readOutput()
{
    for (const ExperimentEvent& e : m_events.feed(m_process->readAllStandardOutput()))
        emit event(e);
}

void ExperimentProcess::readErrors()
{
    m_stderrRest += m_process->readAllStandardError();
    qsizetype start = 0;
    for (qsizetype end; (end = m_stderrRest.indexOf('\n', start)) >= 0; start = end + 1) {
        const QString line = QString::fromUtf8(m_stderrRest.sliced(start, end - start)).trimmed();
        if (!line.isEmpty())
            emit logLine(line);
    }
    m_stderrRest.remove(0, start);
    if (m_stderrRest.size() > kMaxErrorLineBytes)
        m_stderrRest.clear();
}
