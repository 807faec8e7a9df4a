// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <QJsonDocument>
#include <QJsonObject>
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

/// Whether `ours` has the reference's statistics (the same keys), each to the last digit that
/// float64 arithmetic on ms values can hold.
inline bool sameStats(const QJsonObject& ours, const QJsonObject& reference)
{
    for (auto it = reference.begin(); it != reference.end(); ++it) {
        const double x = ours.value(it.key()).toDouble();
        const double y = it.value().toDouble();
        if (std::abs(x - y) > 1e-9 + 1e-10 * std::abs(y))
            return false;
    }
    return ours.keys() == reference.keys();
}
} // namespace PythonRef
