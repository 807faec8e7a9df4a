// SPDX-License-Identifier: MIT
#pragma once

// A chain of ROS 2 stamp topics published by one Cyclone DDS node (tests/ros2peer): sample N has
// the same header.stamp on every topic, `time` = header.stamp + a per-topic delay + a jitter below
// 1 ms; and numpy's figures of the stamps the node printed (tests/scripts/latency_reference.py).

#include "pythonref.h"
#include "wire/stampcodec.h"

#include <algorithm>
#include <QFile>
#include <QHash>
#include <QJsonObject>
#include <QStringList>
#include <QTemporaryDir>

namespace Ros2StampChain {
inline const QStringList& topics()
{
    static const QStringList t {QStringLiteral("/lab/vehicle/out"), QStringLiteral("/lab/cloud/in"),
                                QStringLiteral("/lab/cloud/out"), QStringLiteral("/lab/vehicle/in")};
    return t;
}

/// The peer's arguments: `count` samples at 50 Hz, stamped 0, 20, 35 and 60 ms after the sample.
inline QStringList args(int count)
{
    const QString type = QStringLiteral(":benchmarking_suite/msg/TimeStamped:50");
    QStringList a {QStringLiteral("--node"), QStringLiteral("/lab/chain"), QStringLiteral("--count"),
                   QString::number(count), QStringLiteral("--start-matched"), QStringLiteral("--duration"),
                   QStringLiteral("60")};
    const int delays[] = {0, 20, 35, 60};
    for (int i = 0; i < topics().size(); ++i)
        a << QStringLiteral("--pub") << topics()[i] + type << QStringLiteral("--stamp-delay")
          << topics()[i] + u':' + QString::number(delays[i]);
    return a;
}

/// The peer's `stamp TOPIC N SAMPLE_NS TIME_NS` lines as the suite's timestamp CSV (a row per
/// sample that every topic stamped).
inline QString suiteCsv(const QStringList& lines, int* rows)
{
    QHash<qint64, QHash<QString, qint64>> bySample;
    for (const QString& l : lines) {
        const QStringList f = l.split(u' ');
        if (f.size() == 5 && f[0] == QStringLiteral("stamp"))
            bySample[f[3].toLongLong()][f[1]] = f[4].toLongLong();
    }
    QList<qint64> samples = bySample.keys();
    std::sort(samples.begin(), samples.end());
    QString csv = topics().join(u',') + u'\n';
    *rows = 0;
    for (qint64 s : samples) {
        if (bySample[s].size() != topics().size())
            continue;
        QStringList cells;
        for (const QString& t : topics())
            cells << StampCodec::timeText(bySample[s][t]);
        csv += cells.join(u',') + u'\n';
        ++*rows;
    }
    return csv;
}

/// numpy's figures of the CSV: {"stages": [...], "total": {...}} in ms.
inline QJsonObject reference(const QTemporaryDir& dir, const QString& csv)
{
    QFile f(dir.filePath(QStringLiteral("stamps.csv")));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(csv.toUtf8());
    f.close();
    return PythonRef::run(QStringLiteral("latency_reference.py"), {f.fileName()}).object();
}
} // namespace Ros2StampChain
