// SPDX-License-Identifier: MIT
#pragma once

// A process's peak resident set (VmHWM), for the tests that hold a memory bound.
#include <QByteArray>
#include <QFile>
#include <QString>

namespace PeakRss {
/// What an AddressSanitizer build adds to a peak on its own: freed blocks wait in its quarantine
/// (256 MiB by default) before their memory is used again, and every byte has its shadow. The
/// tests add this to their bounds there; the bound itself is what a normal build holds (and the
/// normal build is where the tests judge it).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr qint64 kSanitizerSlack = qint64(320) << 20;
#else
inline constexpr qint64 kSanitizerSlack = 0;
#endif
/// For bounds over many small blocks (a topic tree of long names): under ASan each block also
/// carries its redzones, which took 30,000 announced topics from 157 to 789 MiB. The factor keeps
/// a runaway caught there (the old code took 641 MiB in a normal build).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr qint64 kSanitizerFactor = 6;
#else
inline constexpr qint64 kSanitizerFactor = 1;
#endif

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

/// Starts the peak of process `pid` (0: this one; another of this user's) over from its present
/// resident set (Linux: 5 to clear_refs).
inline bool reset(qint64 pid = 0)
{
    QFile f(pid > 0 ? QStringLiteral("/proc/%1/clear_refs").arg(pid) : QStringLiteral("/proc/self/clear_refs"));
    return f.open(QIODevice::WriteOnly) && f.write("5") == 1;
}
} // namespace PeakRss
