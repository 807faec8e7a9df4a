// SPDX-License-Identifier: MIT
#pragma once

// The bridgescope-dds child of a process, found in /proc, for the tests that make it crash (a
// signal, as a datagram that takes the DDS library down would) and check that it comes back.
#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QString>
#include <signal.h>

namespace DdsChild {

/// The pid of `parent`'s (0: this process's) running bridgescope-dds child; 0 when there is none.
inline qint64 of(qint64 parent = 0)
{
    if (parent <= 0)
        parent = QCoreApplication::applicationPid();
    const QStringList pids = QDir(QStringLiteral("/proc")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString& pid : pids) {
        QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
        if (pid.toLongLong() <= 0 || !stat.open(QIODevice::ReadOnly))
            continue;
        // pid (comm) state ppid ...: comm may hold spaces and parentheses, so from the last ')'
        const QByteArray line = stat.readAll();
        const qsizetype open = line.indexOf('('), close = line.lastIndexOf(')');
        if (open < 0 || close < open)
            continue;
        const QList<QByteArray> rest = line.mid(close + 2).split(' ');
        if (line.mid(open + 1, close - open - 1) == "bridgescope-dds" && rest.size() > 1
            && rest.at(0) != "Z" && rest.at(1).toLongLong() == parent)
            return pid.toLongLong();
    }
    return 0;
}

/// Sends `signal` to `parent`'s bridgescope-dds child; its pid, or 0 when there was none.
inline qint64 kill(int signal, qint64 parent = 0)
{
    const qint64 pid = of(parent);
    if (pid > 0 && ::kill(pid_t(pid), signal) != 0)
        return 0;
    return pid;
}

} // namespace DdsChild
