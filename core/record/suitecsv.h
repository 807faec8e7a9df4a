// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "record/readbudgets.h"

#include <functional>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QStringList>
#include <vector>

/// What one read may take: the budgets of a run file (record/readbudgets.h). Past one the read
/// is refused with the reason, never cut short silently.
struct SuiteCsvLimits
{
    qint64 maxCells = ReadBudgets::kMaxRows; ///< cells of the rows after the header
    qint64 maxRowBytes = ReadBudgets::kMaxValueBytes; ///< one record, the header row included
    int maxSeconds = ReadBudgets::kMaxReadSeconds;
};

/// The benchmarking suite's timestamp CSV: a header row of stamp topics in pipeline order, then
/// one row per sample, each cell "sec.nsec" with nine digits of nanoseconds.
///
/// Written exactly as the suite's Python csv writer does (CRLF line ends, quoting only where
/// needed). Reading is forgiving about line ends, a BOM and short fractions, and strict about
/// everything else: a row with a cell that is not a time (or holds a NUL byte, or a time outside
/// what a ROS stamp can hold), or with too many or too few cells, is skipped and reported with its
/// line; a row with empty cells is an incomplete sample.
class SuiteCsv
{
    Q_DECLARE_TR_FUNCTIONS(SuiteCsv)
public:
    struct Data
    {
        QStringList topics;
        std::vector<std::vector<qint64>> samples; ///< complete rows, ns since the epoch
        qint64 incomplete = 0; ///< rows with empty cells
        qint64 malformed = 0; ///< rows skipped
        QStringList problems; ///< "FILE:LINE: what", one per skipped row (the first 100)
    };

    /// What one read may take (outside the class only so that it can be a default argument).
    using Limits = SuiteCsvLimits;

    /// Unreadable files, files that are no regular file (a FIFO, a device), files without a header
    /// row and files past `limits` give an error. The file is read 1 MiB at a time up to
    /// its size at the open, one record at a time. `progress` (0..100, false to cancel) is polled
    /// while reading, and RegularFile::stopRequested() (Ctrl+C); cancelling gives an error.
    using Progress = std::function<bool(int percent)>;
    static Result<Data> read(const QString& path, const Progress& progress = {}, const Limits& limits = {});
    static Result<Data> parse(const QByteArray& bytes, const QString& name, const Progress& progress = {},
                              const Limits& limits = {});
    /// parse() with the bytes handed over in slices of the given sizes, in turn (the fuzz target
    /// checks that any slicing reads the same as one piece).
    static Result<Data> parseInSlices(const QByteArray& bytes, const QString& name,
                                      const std::vector<qsizetype>& slices, const Limits& limits = {});

    static QByteArray header(const QStringList& topics);
    static QByteArray row(const std::vector<qint64>& times);
    static QByteArray write(const QStringList& topics, const std::vector<std::vector<qint64>>& samples);
};
