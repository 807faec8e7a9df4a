// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentevent.h"

#include <QObject>
#include <QStringList>

class QProcess;

/// `bridgescope experiment PLAN -o DIR` in a child process (its labs start servers and bridges,
/// which takes seconds, and a crash of one cannot take the window along): its standard output
/// read through ExperimentEventReader into typed events, its standard error as log lines, its end
/// as an ExperimentExit. Stopping lets the child clean up; destroying a running one waits for
/// that, briefly.
class ExperimentProcess : public QObject
{
    Q_OBJECT
public:
    explicit ExperimentProcess(QObject* parent = nullptr);
    ~ExperimentProcess() override;

    /// Starts `program experiment plan -o directory [--resume]`; false when one runs already.
    bool start(const QString& program, const QString& plan, const QString& directory, bool resume);
    /// Asks the child to stop after cleaning up (SIGTERM: as on Ctrl+C).
    void stop();
    bool isRunning() const;
    /// The arguments of the last start (for the log).
    const QStringList& arguments() const { return m_arguments; }
    /// Lines of standard output that were no event (see ExperimentEventReader).
    qint64 refusedLines() const { return m_events.refused(); }

    /// The exit status of a child that ended.
    static ExperimentExit exitOf(int exitCode, bool crashed);

signals:
    void event(const ExperimentEvent& event);
    void logLine(const QString& line); ///< a line of standard error, trimmed, never empty
    void failedToStart(const QString& why);
    /// The child ended; every event and log line came before.
    void finished(ExperimentExit status, int exitCode);

private:
    void readOutput();
    void readErrors();
    QProcess* m_process = nullptr;
    QStringList m_arguments;
    ExperimentEventReader m_events;
    QByteArray m_stderrRest;
};
