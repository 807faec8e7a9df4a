// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstdio>
#include <functional>
#include <QElapsedTimer>
#include <QList>
#include <QString>

/// Small helpers shared by the benchmarks: repeat, take the median, print a table row.
namespace Bench {

/// Median wall time of `runs` calls, in milliseconds.
inline double medianMs(int runs, const std::function<void()>& work)
{
    QList<double> times;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer t;
        t.start();
        work();
        times << t.nsecsElapsed() / 1e6;
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

inline void header(const char* valueTitle)
{
    std::printf("| %-58s | %12s | %s\n", "measure", valueTitle, "note");
    std::printf("|%s|%s|%s\n", QByteArray(60, '-').constData(), QByteArray(14, '-').constData(), "------");
}

inline void row(const QString& what, double value, const QString& note = QString())
{
    std::printf("| %-58s | %12.1f | %s\n", qPrintable(what), value, qPrintable(note));
    std::fflush(stdout);
}
} // namespace Bench
