// SPDX-License-Identifier: MIT
#include "remote/sshcommand.h"

#include <QRegularExpression>

using namespace Qt::Literals::StringLiterals;

SshOptions SshOptions::fromEnvironment()
{
    SshOptions options;
    const QString program = qEnvironmentVariable("BRIDGESCOPE_SSH");
    if (!program.isEmpty())
        options.program = program;
    return options;
}

QString SshCommand::shellQuote(const QString& word)
{
    QString quoted = word;
    quoted.replace(u'\'', u"'\\''"_s);
    return u'\'' + quoted + u'\'';
}

Result<QString> SshCommand::commandLine(const QStringList& words)
{
    if (words.isEmpty())
        return LocatedError {tr("no program to run on the far host")};
    QStringList quoted;
    quoted.reserve(words.size());
    for (const QString& word : words) {
        if (word.contains(QChar(0)))
            return LocatedError {tr("a word for the far host holds a NUL character")};
        quoted << shellQuote(word);
    }
    return quoted.join(u' ');
}

Result<QStringList> SshCommand::arguments(const RemoteHost& host, const SshOptions& options,
                                          const QString& remoteCommand)
{
    QStringList args = {u"-o"_s, u"BatchMode=yes"_s,
                        u"-o"_s, u"PasswordAuthentication=no"_s,
                        u"-o"_s, u"KbdInteractiveAuthentication=no"_s,
                        u"-o"_s, u"ConnectTimeout=%1"_s.arg(qBound(1, options.connectTimeoutSeconds, 600)),
                        u"-o"_s, u"ServerAliveInterval=2"_s,
                        u"-o"_s, u"ServerAliveCountMax=3"_s};
    if (!options.identityFile.isEmpty())
        args << u"-i"_s << options.identityFile;
    if (!options.knownHostsFile.isEmpty()) {
        // ssh splits this option's value at white space and reads quotes and '%' tokens in it.
        static const QRegularExpression plain(uR"(^[^\s"'%\\]+$)"_s);
        if (!plain.match(options.knownHostsFile).hasMatch())
            return LocatedError {tr("the known-hosts file \"%1\" has white space, quotes, '%' or '\\' in its "
                                    "name, which ssh's options cannot carry")
                                     .arg(options.knownHostsFile)};
        args << u"-o"_s << u"UserKnownHostsFile="_s + options.knownHostsFile;
    }
    args << u"-p"_s << QString::number(host.port) << host.destination() << u"--"_s << remoteCommand;
    return args;
}

QString SshCommand::cannotReach(const QString& role, const RemoteHost& host, const QString& sshMessage)
{
    return tr("cannot reach %1 (%2): %3").arg(role, host.url(), sshMessage);
}

QString SshCommand::cannotRun(const QString& role, const RemoteHost& host, const QString& why)
{
    return tr("cannot run on %1 (%2): %3").arg(role, host.url(), why);
}

QString SshCommand::cannotStart(const QString& program, const QString& role, const RemoteHost& host,
                                const QString& why)
{
    return tr("cannot start %1 for %2 (%3): %4").arg(program, role, host.url(), why);
}
