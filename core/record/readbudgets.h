// SPDX-License-Identifier: MIT
#pragma once

#include <QtGlobal>

/// What one read of a measurement file may take, whatever its format (run files, the suite's
/// CSV; docs/formats.md): a file is input, and neither its size nor its content may ask for
/// unbounded memory or time.
namespace ReadBudgets {
/// Stamps (a run file's rows, a CSV's cells) of one file together.
inline constexpr qint64 kMaxRows = 10'000'000;
/// Names, metadata and event texts together (a CSV's header row and one row: kMaxRecordBytes).
inline constexpr qint64 kMaxTextBytes = 64 * 1024 * 1024;
/// One value of a run file (SQLite's length limit), one row of a CSV.
inline constexpr int kMaxValueBytes = 16 * 1024 * 1024;
/// The longest a read may take, in seconds.
inline constexpr int kMaxReadSeconds = 300;
} // namespace ReadBudgets
