// SPDX-License-Identifier: MIT
#include "remote/remoteprocess.h"

#include <QTimer>

using namespace Qt::Literals::StringLiterals;

namespace {

const QString s_startedMarker = u"bridgescope-remote: started "_s;

// Runs on the far host as `sh -c SCRIPT bridgescope-remote GRACE PROGRAM ARGS...`; no value of a
// plan is ever part of it (they arrive as the quoted positional arguments). The program runs in the
// background with stdin from /dev/null, in a process group of its own where setsid(1) exists (so
// its children end with it); a watcher reads the session's stdin (kept as fd 3) and, when it ends
// (stop(), the local ssh killed, the connection lost), sends TERM, waits up to GRACE seconds, then
// KILL. The script ends with the program's status.
const QString s_script = uR"(g=$1
shift
exec 3<&0
if command -v setsid >/dev/null 2>&1; then
    setsid -- "$@" </dev/null 3<&- &
else
    "$@" </dev/null 3<&- &
fi
p=$!
printf 'bridgescope-remote: started %s\n' "$p" >&2
(
    while IFS= read -r _; do :; done <&3
    kill -TERM "-$p" "$p" 2>/dev/null
    i=0
    while [ "$i" -lt "$g" ] && kill -0 "$p" 2>/dev/null; do sleep 1; i=$((i + 1)); done
    kill -KILL "-$p" "$p" 2>/dev/null
) >/dev/null 2>&1 &
w=$!
exec 3<&-
wait "$p"
s=$?
kill "$w" 2>/dev/null
exit "$s"
)"_s;

} // namespace

RemoteProcess::RemoteProcess(RemoteHost host, SshOptions options, QString role, QObject* parent)
    : QObject(parent)
    , m_host(std::move(host))
    , m_options(std::move(options))
    , m_role(std::move(role))
    , m_stopTimer(new QTimer(this))
{
    m_stopTimer->setSingleShot(true);
    connect(m_stopTimer, &QTimer::timeout, this, [this] {
        if (!isRunning())
            return;
        // The far side did not end the session in time: end it from here (TERM, then KILL).
        if (m_endingLocally) {
            m_ssh->kill();
            return;
        }
        m_endingLocally = true;
        m_ssh->terminate();
        m_stopTimer->start(2000);
    });
}

RemoteProcess::~RemoteProcess()
{
    if (!isRunning())
        return;
    m_ssh->disconnect(this); // no signal from a half-destroyed object
    stop();
    if (!m_ssh->waitForFinished((m_graceSeconds + 2) * 1000)) {
        m_ssh->kill();
        m_ssh->waitForFinished(2000);
    }
}

void RemoteProcess::setGracePeriod(int seconds)
{
    m_graceSeconds = qBound(0, seconds, 600);
}

bool RemoteProcess::start(const QStringList& argv)
{
    if (isRunning()) {
        m_error = tr("%1 (%2) already runs a program").arg(m_role, m_host.url());
        return false;
    }
    m_error.clear();
    m_remotePid = 0;
    m_exitCode = -1;
    m_stopRequested = false;
    m_endingLocally = false;
    m_stdout = OutputTail();
    m_stderr = OutputTail();
    const Result<QString> command = SshCommand::commandLine(
        QStringList {u"sh"_s, u"-c"_s, s_script, u"bridgescope-remote"_s, QString::number(m_graceSeconds)}
        + argv);
    if (!command) {
        m_error = SshCommand::cannotRun(m_role, m_host, command.error().toString());
        return false;
    }
    const Result<QStringList> args = SshCommand::arguments(m_host, m_options, *command);
    if (!args) {
        m_error = SshCommand::cannotRun(m_role, m_host, args.error().toString());
        return false;
    }
    m_ssh = std::make_unique<QProcess>();
    connect(m_ssh.get(), &QProcess::readyReadStandardOutput, this, [this] {
        for (const QString& line : m_stdout.append(m_ssh->readAllStandardOutput()))
            emit standardOutputLine(line);
    });
    connect(m_ssh.get(), &QProcess::readyReadStandardError, this, &RemoteProcess::readStandardError);
    connect(m_ssh.get(), &QProcess::finished, this, &RemoteProcess::onFinished);
    m_ssh->start(m_options.program, *args);
    if (!m_ssh->waitForStarted(5000)) {
        m_error = SshCommand::cannotStart(m_options.program, m_role, m_host, m_ssh->errorString());
        m_ssh.reset();
        return false;
    }
    return true;
}

void RemoteProcess::readStandardError()
{
    for (const QString& line : m_stderr.append(m_ssh->readAllStandardError())) {
        if (m_remotePid == 0 && line.startsWith(s_startedMarker)) {
            m_remotePid = line.mid(s_startedMarker.size()).toLongLong();
            if (m_remotePid > 0)
                emit started(m_remotePid);
        }
    }
}

QStringList RemoteProcess::lastErrorLines() const
{
    // The far program writes while the script reports its start: the report may come after it.
    QStringList lines;
    for (const QString& line : m_stderr.lines())
        if (!line.startsWith(s_startedMarker) && !line.trimmed().isEmpty())
            lines << line;
    return lines;
}

void RemoteProcess::stop()
{
    if (!isRunning() || m_stopTimer->isActive())
        return;
    m_stopRequested = true;
    m_ssh->closeWriteChannel();
    m_stopTimer->start((m_graceSeconds + 2) * 1000);
}

bool RemoteProcess::waitForFinished(int timeoutMs)
{
    return !isRunning() || m_ssh->waitForFinished(timeoutMs);
}

bool RemoteProcess::isRunning() const
{
    return m_ssh && m_ssh->state() != QProcess::NotRunning;
}

qint64 RemoteProcess::localPid() const
{
    return isRunning() ? m_ssh->processId() : 0;
}

void RemoteProcess::onFinished(int exitCode, QProcess::ExitStatus status)
{
    m_stopTimer->stop();
    readStandardError();
    m_stdout.append(m_ssh->readAllStandardOutput());
    m_stdout.flush();
    m_stderr.flush();
    m_exitCode = status == QProcess::NormalExit ? exitCode : -1;
    const QStringList errors = lastErrorLines();
    const QString message = errors.isEmpty() ? QString() : errors.last().trimmed();
    if (status != QProcess::NormalExit) {
        if (!m_endingLocally)
            m_error = tr("ssh to %1 (%2) ended unexpectedly").arg(m_role, m_host.url());
    } else if (exitCode == 255 && m_remotePid == 0) {
        m_error = SshCommand::cannotReach(m_role, m_host, message);
    } else if (exitCode == 255 && !m_stopRequested) {
        m_error = tr("lost %1 (%2): %3").arg(m_role, m_host.url(), message);
    } else if (m_remotePid == 0 && exitCode != 0) {
        m_error = tr("could not start the program on %1 (%2): %3").arg(m_role, m_host.url(), message);
    } else if (exitCode != 0 && !m_stopRequested) {
        m_error = tr("the program on %1 (%2) ended with status %3: %4")
                      .arg(m_role, m_host.url())
                      .arg(exitCode)
                      .arg(message);
    }
    emit finished(m_exitCode);
}
