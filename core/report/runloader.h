// SPDX-License-Identifier: MIT
#pragma once

#include "record/runfile.h"

#include <QCoreApplication>
#include <QStringList>

/// Reads any measurement input into a run: a run file, the suite's timestamp CSV, or a ROS bag
/// (told apart by their first bytes, not their names). Inputs are only read, never changed.
class RunLoader
{
    Q_DECLARE_TR_FUNCTIONS(RunLoader)
public:
    enum class Kind { Run, Bag, SuiteCsv };
    static Kind kindOf(const QString& path);
    /// Whether a file is a measurement input at all: a run or a bag (by their first bytes, or by
    /// their suffix: a damaged one is still one, for load() to say what is wrong) or a `.csv` file
    /// (the suite's, to be checked when read).
    static bool isMeasurement(const QString& path);
    static QString kindName(Kind kind);

    struct Options
    {
        /// A suite CSV row that does not read is an error; with this, it is skipped and reported.
        bool skipBadRows = false;
    };

    /// The input as a run. `warnings` gets what was skipped ("FILE:LINE: what").
    static Result<RunData> load(const QString& path, const Options& options, QStringList* warnings = nullptr,
                                const Progress& progress = {});
    /// Several inputs as one run: their events one after the other (same stamp topics expected).
    static RunData join(std::vector<RunData> runs);
};
