// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "remote/remotehost.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

/// How OpenSSH is run: which program, which key file and known-hosts file (by path: nothing secret
/// on a command line), how long a connection may take. Keys or an agent only, BatchMode always.
struct SshOptions
{
    QString program = QStringLiteral("ssh"); ///< OpenSSH's client, or a wrapper that runs it
    QString identityFile; ///< -i FILE when set; otherwise ssh's defaults and the agent
    QString knownHostsFile; ///< -o UserKnownHostsFile=FILE when set
    int connectTimeoutSeconds = 5;

    /// The defaults, with `program` from BRIDGESCOPE_SSH when that is set (for a wrapper, as the
    /// two-host test lab's, that runs ssh elsewhere).
    static SshOptions fromEnvironment();
};

/// The ssh command lines Bridgescope runs: every word of the remote command shell-quoted, so no
/// value from a plan can add shell syntax on the far host, and no password anywhere.
class SshCommand
{
    Q_DECLARE_TR_FUNCTIONS(SshCommand)
public:
    /// `word` in single quotes for a POSIX shell ('\'' for a quote inside).
    static QString shellQuote(const QString& word);
    /// The words as one command line for the far host's shell, each quoted. An error for no words
    /// or a word holding a NUL character.
    static Result<QString> commandLine(const QStringList& words);
    /// ssh's arguments (after the program) that run `remoteCommand` (from commandLine()) on `host`:
    /// -o BatchMode=yes -o PasswordAuthentication=no -o KbdInteractiveAuthentication=no
    /// -o ConnectTimeout=N -o ServerAliveInterval=2 -o ServerAliveCountMax=3 [-i KEY]
    /// [-o UserKnownHostsFile=FILE] -p PORT user@host -- remoteCommand.
    /// An error when a configured file name cannot be passed safely.
    static Result<QStringList> arguments(const RemoteHost& host, const SshOptions& options,
                                         const QString& remoteCommand);

    /// The messages of every ssh run, the same whichever runs it; `role` names the host ("cloud").
    /// "cannot reach ROLE (URL): ssh's message" (ssh's exit status 255).
    static QString cannotReach(const QString& role, const RemoteHost& host, const QString& sshMessage);
    /// "cannot run on ROLE (URL): why" (words that cannot be sent).
    static QString cannotRun(const QString& role, const RemoteHost& host, const QString& why);
    /// "cannot start PROGRAM for ROLE (URL): why" (no ssh here).
    static QString cannotStart(const QString& program, const QString& role, const RemoteHost& host,
                               const QString& why);
};
