// SPDX-License-Identifier: MIT
#pragma once

#include <QJsonDocument>
#include <QProcess>
#include <QTest>

/// Runs one of the independent reference scripts in tests/scripts with Debian's Python (the one
/// that has numpy) and returns its JSON output.
namespace PythonRef {
inline QJsonDocument run(const QString& script, const QStringList& args)
{
    QProcess p;
    p.start(QStringLiteral("/usr/bin/python3"),
            QStringList {QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/tests/scripts/") + script} + args);
    if (!p.waitForFinished(120000) || p.exitCode() != 0) {
        qWarning("%s failed: %s", qPrintable(script), p.readAllStandardError().constData());
        return {};
    }
    return QJsonDocument::fromJson(p.readAllStandardOutput());
}
} // namespace PythonRef
