// SPDX-License-Identifier: MIT
#pragma once

#include "procstats.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QList>
#include <QString>
#include <QtGlobal>
#include <QTimer>
#include <unistd.h>
#include <vector>

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

/// The p-quantile (0..1) of `v`, interpolated linearly.
inline double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const double rank = p * double(v.size() - 1);
    const size_t lo = size_t(rank);
    const size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (v[hi] - v[lo]) * (rank - double(lo));
}

/// An integer of at least `minimum` from the environment, or `fallback` when it is unset. A count
/// takes the default minimum of 1; a switch (BENCH_SWEEP=0 turns the sweep off) a minimum of 0. A
/// value that is not such a number is said on stderr, and the fallback taken.
inline int envInt(const char* name, int fallback, int minimum = 1)
{
    if (!qEnvironmentVariableIsSet(name))
        return fallback;
    bool ok = false;
    const int v = qEnvironmentVariableIntValue(name, &ok);
    if (ok && v >= minimum)
        return v;
    std::fprintf(stderr, "%s=%s is not an integer of at least %d: %d taken\n", name,
                 qgetenv(name).constData(), minimum, fallback);
    return fallback;
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
/// A figure that scripts/bench.sh --gate checks against bench/gate.txt: one line "GATE name value".
inline void gate(const char* name, double value)
{
    std::printf("GATE %s %.6g\n", name, value);
    std::fflush(stdout);
}

/// How late a 10 ms timer fires in this (GUI) thread while `running` says so, in ms.
inline std::vector<double> measureLag(const std::function<bool()>& running)
{
    std::vector<double> lags;
    QElapsedTimer clock;
    qint64 expected = 10'000'000;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        lags.push_back(double(std::max<qint64>(0, now - expected)) / 1e6);
        expected = now + 10'000'000;
    });
    clock.start();
    probe.start(10);
    while (running())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return lags;
}

/// User + system CPU seconds of a running process so far (/proc/PID/stat), or -1.
inline double processCpuSeconds(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray s = f.readAll();
    const QList<QByteArray> fields = s.mid(s.lastIndexOf(')') + 2).split(' ');
    // After the command: state is field 3; utime and stime are fields 14 and 15.
    return double(fields.value(11).toLongLong() + fields.value(12).toLongLong())
        / double(::sysconf(_SC_CLK_TCK));
}
} // namespace Bench
