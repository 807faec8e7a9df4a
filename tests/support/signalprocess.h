// SPDX-License-Identifier: MIT
#pragma once

#include <csignal>
#include <QtGlobal>
#include <sys/types.h>

/// Sends `signal` to the process `pid`, and to nothing else: a QProcess that has already ended
/// has processId() 0, and kill(0, …) signals the caller's whole process group (ctest, the CI
/// script, every sibling test). False when there was no process to signal.
inline bool signalProcess(qint64 pid, int signal)
{
    if (pid <= 0) {
        qWarning("not signalling pid %lld: the process has ended", static_cast<long long>(pid));
        return false;
    }
    return ::kill(pid_t(pid), signal) == 0;
}
