// SPDX-License-Identifier: MIT
#include "remote/remotecommand.h"

#include "remote/outputtail.h"

#include <QDeadlineTimer>
#include <QProcess>

using namespace Qt::Literals::StringLiterals;

RemoteRun RemoteCommand::run(const RemoteHost& host, const SshOptions& options, const QString& role,
                             const QStringList& argv, const QByteArray& input, int timeoutMs,
                             qsizetype maxOutput)
{
    RemoteRun result;
    // coreutils' timeout ends the far command too when ssh is ended here at the deadline (no session
    // watcher: its stdin carries `input`).
    const int farSeconds = std::max(1, timeoutMs / 1000 + 2);
    const Result<QString> command = SshCommand::commandLine(
        QStringList {u"timeout"_s, u"-s"_s, u"KILL"_s, QString::number(farSeconds)} + argv);
    const Result<QStringList> args
        = command ? SshCommand::arguments(host, options, *command) : Result<QStringList>(command.error());
    if (!args) {
        result.error = SshCommand::cannotRun(role, host, args.error().toString());
        return result;
    }
    QProcess ssh;
    OutputTail errors;
    QObject::connect(&ssh, &QProcess::readyReadStandardOutput, [&] {
        const QByteArray bytes = ssh.readAllStandardOutput();
        result.output.append(bytes.left(std::max<qsizetype>(0, maxOutput - result.output.size())));
    });
    QObject::connect(&ssh, &QProcess::readyReadStandardError,
                     [&] { errors.append(ssh.readAllStandardError()); });
    ssh.start(options.program, *args);
    if (!ssh.waitForStarted(5000)) {
        result.error = SshCommand::cannotStart(options.program, role, host, ssh.errorString());
        return result;
    }
    ssh.write(input);
    ssh.closeWriteChannel();
    const QDeadlineTimer deadline(timeoutMs);
    while (ssh.state() != QProcess::NotRunning && !deadline.hasExpired())
        ssh.waitForFinished(int(std::min<qint64>(deadline.remainingTime(), 100)));
    if (ssh.state() != QProcess::NotRunning) {
        ssh.kill();
        ssh.waitForFinished(2000);
        result.error = tr("%1 (%2) did not finish %3 within %4 s")
                           .arg(role, host.url(), argv.value(0))
                           .arg(double(timeoutMs) / 1000);
        return result;
    }
    errors.append(ssh.readAllStandardError());
    errors.flush();
    const QByteArray rest = ssh.readAllStandardOutput();
    result.output.append(rest.left(std::max<qsizetype>(0, maxOutput - result.output.size())));
    result.exitCode = ssh.exitStatus() == QProcess::NormalExit ? ssh.exitCode() : -1;
    QString message;
    const QStringList lines = errors.lines();
    for (auto it = lines.crbegin(); it != lines.crend() && message.isEmpty(); ++it)
        message = it->trimmed();
    if (result.exitCode == 255)
        result.error = SshCommand::cannotReach(role, host, message);
    else if (result.exitCode != 0)
        result.error = tr("%1 on %2 (%3) ended with status %4: %5")
                           .arg(argv.value(0), role, host.url())
                           .arg(result.exitCode)
                           .arg(message);
    return result;
}

RemoteRun RemoteCommand::writeFile(const RemoteHost& host, const SshOptions& options, const QString& role,
                                   const QString& path, const QByteArray& bytes, int timeoutMs)
{
    // The path arrives as "$1": never read as shell syntax; "--" keeps a leading '-' a name.
    static const QString script = uR"sh(umask 077 && mkdir -p -- "$(dirname -- "$1")" && cat > "$1")sh"_s;
    return run(host, options, role, {u"sh"_s, u"-c"_s, script, u"bridgescope-write"_s, path}, bytes,
               timeoutMs, 0);
}
