// SPDX-License-Identifier: MIT
#pragma once

#include <QElapsedTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

/// Runs the bridgescope binary as a user would, for the command-line tests.
namespace CliRun {
struct Result
{
    int exit = -1; ///< -1: crashed or timed out
    QString out;
    QString err;
    qint64 ms = 0;
};

inline Result bridgescope(const QStringList& args, int timeoutMs = 30000)
{
    QElapsedTimer clock;
    clock.start();
    QProcess p;
    p.start(QStringLiteral(BRIDGESCOPE_BINARY), args);
    Result r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QString::fromUtf8(p.readAllStandardError());
        return r;
    }
    r.exit = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    r.ms = clock.elapsed();
    return r;
}
} // namespace CliRun
