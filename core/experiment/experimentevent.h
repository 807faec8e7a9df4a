// SPDX-License-Identifier: MIT
#pragma once

#include "experiment/experimentstate.h"

#include <optional>
#include <utility>
#include <QByteArray>
#include <QList>
#include <QString>

/// How `bridgescope experiment` ends: its exit status, as the command returns it and the
/// Experiments page reads it (Crashed: the child died of a signal, no status).
enum class ExperimentExit : int {
    Complete = 0, ///< every cell complete
    CellFailed = 1, ///< done, but a cell failed
    Usage = 2, ///< bad options or plan: nothing ran (the command's message says why)
    Stopped = 130, ///< stopped by Ctrl+C or SIGTERM after cleaning up; --resume goes on
    Crashed = -1,
};

/// One JSON line that `bridgescope experiment` writes on its standard output (a cell started or
/// finished, progress with the totals since the last line, a throughput step). One codec serves
/// both ends: the command writes its lines with toLine(), the Experiments page reads them with
/// parse(). The child is a process like any other: its lines are input, read here with every value
/// checked and bounded (fuzzed by fuzz_experimentevents), so that the page only lays out.
struct ExperimentEvent
{
    enum class Kind { Started, Progress, Finished, Throughput };
    Kind kind = Kind::Started;
    int index = -1; ///< the cell; -1 for a throughput step
    QString cell; ///< the cell's id as the line names it (empty: not named)
    QList<std::pair<QString, QString>> levels; ///< started, finished: the cell's (factor, level)
    CellStatus::State state = CellStatus::Pending; ///< started, finished
    qint64 samples = 0; ///< recorded (progress, finished), never negative
    qint64 of = 0; ///< the plan's samples (progress)
    QList<double> totalMs; ///< progress: finite totals within ±kMaxTotalMs, at most kMaxTotals
    qint64 remainingS = 0; ///< progress: never negative
    bool warmingUp = false;
    QString reason; ///< finished: why it failed, at most kMaxReasonChars
    QString run; ///< finished: the run file the command names (the page trusts its own path)
    CellStatus::Link link; ///< finished: the link profile's relays (written when bytes > 0)
    double rateHz = 0; ///< throughput
    double throughputSamples = 0;
    double expected = 0;
    double dropped = 0;
    double p50Ms = 0;
    bool sustainable = true;

    static constexpr qsizetype kMaxLineBytes = 4 * 1024 * 1024;
    static constexpr double kMaxTotalMs = 1e9; ///< beyond ±11 days a total is no measurement
    static constexpr qsizetype kMaxTotals = 100'000;
    static constexpr qsizetype kMaxReasonChars = 2000;
    static constexpr qsizetype kMaxCellChars = 1000;
    static constexpr qsizetype kMaxLevels = 64;

    /// Whether a finished cell is complete (else it failed).
    bool complete() const { return state == CellStatus::Complete; }

    /// The event as one compact JSON line, without its newline (progress totals to the µs).
    QByteArray toLine() const;
    /// The event a line says, or nothing for a line that is not one (not JSON, an unknown event,
    /// a cell index that is not a number, a line over kMaxLineBytes). Values out of range are
    /// clamped or dropped, never taken as they are.
    static std::optional<ExperimentEvent> parse(const QByteArray& line);
};

/// The events in a child's standard output as it comes, in pieces: complete lines are parsed, the
/// rest waits for its end. A line that is no event, or one longer than kMaxLineBytes, is refused
/// and counted (never taken in part).
class ExperimentEventReader
{
public:
    QList<ExperimentEvent> feed(const QByteArray& bytes);
    /// Lines refused so far (not JSON, no known event, out of bounds, too long).
    qint64 refused() const { return m_refused; }

private:
    QByteArray m_rest;
    bool m_skipping = false; ///< the rest of an over-long line is being dropped
    qint64 m_refused = 0;
};
