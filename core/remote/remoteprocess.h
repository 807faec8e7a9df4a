// SPDX-License-Identifier: MIT
#pragma once

#include "remote/outputtail.h"
#include "remote/remotehost.h"
#include "remote/sshcommand.h"

#include <memory>
#include <QObject>
#include <QProcess>
#include <QStringList>

class QTimer;

/// A program run on another host over ssh that lives exactly as long as the ssh session: on the
/// far host a fixed POSIX sh script starts it in the background and a watcher stops it (TERM, then
/// KILL after the grace period) as soon as the session's stdin closes, so killing the local side,
/// even with SIGKILL, or losing the connection ends the far program too. stop() closes stdin the
/// same way and, should ssh not end within the grace period, ends the local ssh as well. The far
/// program runs in a process group of its own (setsid, where the host has it), and TERM and KILL go
/// to the whole group.
///
/// Every word of the program's command line is shell-quoted (SshCommand); the far host needs
/// a POSIX login shell and sh. Output is kept bounded (the last lines) for error messages.
class RemoteProcess : public QObject
{
    Q_OBJECT
public:
    /// `role` names the host in messages ("vehicle", "cloud").
    RemoteProcess(RemoteHost host, SshOptions options, QString role, QObject* parent = nullptr);
    ~RemoteProcess() override; ///< stops the far program (stop(), then waits for ssh to end)

    /// Seconds between the far program's TERM and its KILL (and the local ssh's end) on stop().
    void setGracePeriod(int seconds);
    /// Starts `argv` (program and arguments) on the far host. False with errorString() when the
    /// words cannot be sent or ssh does not start; a host that cannot be reached ends in
    /// finished() with errorString() "cannot reach ROLE (URL): ssh's message".
    bool start(const QStringList& argv);
    /// Ends the far program: its stdin closes (the watcher sends TERM, then KILL after the grace
    /// period); if ssh has not ended two seconds after that, the local ssh gets TERM, then KILL.
    void stop();
    /// Waits for the ssh session to end, for at most `timeoutMs`.
    bool waitForFinished(int timeoutMs);

    bool isRunning() const;
    /// True once the far host reported the program started (its pid known).
    bool hasStarted() const { return m_remotePid > 0; }
    qint64 remotePid() const { return m_remotePid; } ///< the program's pid on the far host, 0 before
    qint64 localPid() const; ///< the local ssh's pid, 0 when it is not running
    int exitCode() const { return m_exitCode; } ///< the far program's, or ssh's 255; -1 while running
    /// Empty, or what went wrong (unreachable host, program failed), naming the role and host URL.
    QString errorString() const { return m_error; }
    /// The last lines of the program's stdout, bounded.
    QStringList lastOutputLines() const { return m_stdout.lines(); }
    /// The last non-empty lines of the program's and ssh's stderr, bounded (without the far
    /// script's own report of the start).
    QStringList lastErrorLines() const;
    const RemoteHost& host() const { return m_host; }

signals:
    void started(qint64 remotePid); ///< the far host runs the program
    void standardOutputLine(const QString& line); ///< one line of the program's stdout (cut to the bound)
    void finished(int exitCode); ///< the session ended; errorString() says why when it failed

private:
    void readStandardError();
    void onFinished(int exitCode, QProcess::ExitStatus status);

    RemoteHost m_host;
    SshOptions m_options;
    QString m_role;
    int m_graceSeconds = 3;
    std::unique_ptr<QProcess> m_ssh;
    QTimer* m_stopTimer = nullptr;
    OutputTail m_stdout;
    OutputTail m_stderr;
    qint64 m_remotePid = 0;
    int m_exitCode = -1;
    bool m_stopRequested = false; ///< stop() closed the far program's stdin
    bool m_endingLocally = false; ///< the far side did not end in time: the local ssh is ended
    QString m_error;
};
