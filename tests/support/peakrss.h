// SPDX-License-Identifier: MIT
#pragma once

// A process's peak resident set (VmHWM), for the tests that hold a memory bound.
#include <QByteArray>
#include <QFile>
#include <QString>

namespace PeakRss {
/// The peak resident set of process `pid` (0: this one) in bytes; -1 if unknown.
inline qint64 of(qint64 pid = 0)
{
    QFile f(pid > 0 ? QStringLiteral("/proc/%1/status").arg(pid) : QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').first().toLongLong() * 1024;
    return -1;
}

/// Starts the peak of this process over from its present resident set (Linux: 5 to clear_refs).
inline bool reset()
{
    QFile f(QStringLiteral("/proc/self/clear_refs"));
    return f.open(QIODevice::WriteOnly) && f.write("5") == 1;
}
} // namespace PeakRss
