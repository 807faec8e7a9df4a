// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTest>

/// Paths of the real config files tests read (../shared/fixtures, or the copy in tests/data).
namespace Fixtures {
inline QString path(const QString& relative)
{
    return QDir(QStringLiteral(BRIDGESCOPE_FIXTURES_DIR)).filePath(relative);
}

inline QByteArray read(const QString& relative)
{
    QFile f(path(relative));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("fixture %s missing", qPrintable(path(relative)));
    return f.readAll();
}

/// A file of every mqtt_client release's example configs (issue 45), kept in this repository:
/// "v2.5.0/params.json.yaml".
inline QString release(const QString& relative)
{
    return QDir(QStringLiteral(BRIDGESCOPE_SOURCE_DIR "/tests/data/fixtures/mqtt_client/releases"))
        .filePath(relative);
}

/// Every bridge config among the fixtures (mqtt_client, the suite's bridge configs, mqtt_bridge).
inline QStringList bridgeConfigs()
{
    QStringList out;
    const QDir root(QStringLiteral(BRIDGESCOPE_FIXTURES_DIR));
    for (const QString& dir : {QStringLiteral("mqtt_client"), QStringLiteral("benchmarking_suite"),
                               QStringLiteral("mqtt_bridge")}) {
        const QStringList files
            = QDir(root.filePath(dir)).entryList({QStringLiteral("*.yaml")}, QDir::Files, QDir::Name);
        for (const QString& f : files) {
            if (!f.startsWith(QStringLiteral("metrics_logger")))
                out << dir + u'/' + f;
        }
    }
    return out;
}
} // namespace Fixtures
