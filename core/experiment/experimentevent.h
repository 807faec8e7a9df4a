// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QByteArray>
#include <QList>
#include <QString>

/// One JSON line that `bridgescope experiment` writes on its standard output (a cell started or
/// finished, progress with the totals since the last line, a throughput step), as the Experiments
/// page reads it. The child is a process like any other: its lines are input, read here with every
/// value checked and bounded (fuzzed by fuzz_experimentevents), so that the page only lays out.
struct ExperimentEvent
{
    enum class Kind { Started, Progress, Finished, Throughput };
    Kind kind = Kind::Started;
    int index = -1; ///< the cell; -1 for a throughput step
    QString cell; ///< the cell's id as the line names it (empty: not named)
    qint64 samples = 0; ///< recorded (progress, finished), never negative
    qint64 of = 0; ///< the plan's samples (progress)
    QList<double> totalMs; ///< progress: finite totals within ±kMaxTotalMs, at most kMaxTotals
    qint64 remainingS = 0; ///< progress: never negative
    bool warmingUp = false;
    bool complete = false; ///< finished: the cell is complete (else failed)
    QString reason; ///< finished: why it failed, at most kMaxReasonChars
    double rateHz = 0; ///< throughput
    double throughputSamples = 0;
    double expected = 0;
    bool sustainable = true;

    static constexpr qsizetype kMaxLineBytes = 4 * 1024 * 1024;
    static constexpr double kMaxTotalMs = 1e9; ///< beyond ±11 days a total is no measurement
    static constexpr qsizetype kMaxTotals = 100'000;
    static constexpr qsizetype kMaxReasonChars = 2000;

    /// The event a line says, or nothing for a line that is not one (not JSON, an unknown event,
    /// a cell index that is not a number, a line over kMaxLineBytes). Values out of range are
    /// clamped or dropped, never taken as they are.
    static std::optional<ExperimentEvent> parse(const QByteArray& line);
};
