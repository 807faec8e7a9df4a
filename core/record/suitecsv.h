// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QStringList>
#include <vector>

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

    /// Unreadable files and files without a header row give nullopt and `error`.
    /// `progress` (0..100, false to cancel) is polled while reading; cancelling gives nullopt.
    using Progress = std::function<bool(int percent)>;
    static std::optional<Data> read(const QString& path, QString* error = nullptr,
                                    const Progress& progress = {});
    static std::optional<Data> parse(const QByteArray& bytes, const QString& name, QString* error = nullptr,
                                     const Progress& progress = {});

    static QByteArray header(const QStringList& topics);
    static QByteArray row(const std::vector<qint64>& times);
    static QByteArray write(const QStringList& topics, const std::vector<std::vector<qint64>>& samples);
};
