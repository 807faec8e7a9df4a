// SPDX-License-Identifier: MIT
#pragma once

// What `bridgescope bridge` logged, for the tests that flood it: the counts of its memory-bound line.
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <utility>

namespace BridgeLog {

/// Stops `p` (which logged to a pipe) and returns the figures of its last memory-bound line:
/// dropped to MQTT, to ROS; {0, 0} without one (its log is shown), {-1, -1} if it did not stop.
inline std::pair<qint64, qint64> droppedOf(QProcess& p)
{
    p.terminate();
    if (!p.waitForFinished(10000))
        return {-1, -1};
    const QString log = QString::fromUtf8(p.readAllStandardError());
    static const QRegularExpression line(
        QStringLiteral("memory bound .*: (\\d+) messages to MQTT and (\\d+) to ROS dropped"));
    QRegularExpressionMatch m;
    for (const QString& l : log.split(u'\n'))
        if (const QRegularExpressionMatch found = line.match(l); found.hasMatch())
            m = found; // the last
    if (!m.hasMatch()) {
        qWarning("%s", qPrintable(log.right(3000)));
        return {0, 0};
    }
    qInfo("%s", qPrintable(m.captured(0)));
    return {m.captured(1).toLongLong(), m.captured(2).toLongLong()};
}

} // namespace BridgeLog
