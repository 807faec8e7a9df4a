// SPDX-License-Identifier: MIT
#pragma once

#include "remote/remotehost.h"
#include "remote/sshcommand.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QStringList>

/// What a short command on another host did.
struct RemoteRun
{
    bool ok() const { return error.isEmpty(); }
    int exitCode = -1; ///< the command's, or ssh's 255; -1 when it did not end in time
    QByteArray output; ///< its stdout, at most the bound asked for
    QString error; ///< empty when it ran and exited 0; else why not, naming the role and host
};

/// Short commands on another host over ssh, waited for within a deadline: the checks before a
/// cell (is the host there, is bridgescope there) and the files a side needs there (its configs).
/// The same argv as RemoteProcess (SshCommand: every word quoted, BatchMode, no password); the
/// command's stdin is `input`, then closed; on the far host it runs under coreutils' `timeout`, so
/// it ends there too a little after the deadline here.
class RemoteCommand
{
    Q_DECLARE_TR_FUNCTIONS(RemoteCommand)
public:
    static constexpr int kDefaultTimeoutMs = 15'000;
    static constexpr qsizetype kDefaultMaxOutput = 1024 * 1024;

    /// Runs `argv` on `host` and waits at most `timeoutMs` (then ends ssh: the far command's
    /// stdin closes with it). Keeps at most `maxOutput` bytes of stdout (the rest is read and
    /// dropped) and the last lines of stderr for the error.
    static RemoteRun run(const RemoteHost& host, const SshOptions& options, const QString& role,
                         const QStringList& argv, const QByteArray& input = {},
                         int timeoutMs = kDefaultTimeoutMs, qsizetype maxOutput = kDefaultMaxOutput);
    /// Writes `bytes` to `path` on `host` (mode 0600, its folder made if missing): the path is a
    /// word like any other, never shell syntax.
    static RemoteRun writeFile(const RemoteHost& host, const SshOptions& options, const QString& role,
                               const QString& path, const QByteArray& bytes,
                               int timeoutMs = kDefaultTimeoutMs);
};
