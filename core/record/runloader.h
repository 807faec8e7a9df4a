// SPDX-License-Identifier: MIT
#pragma once

#include "latency/pipeline.h"

#include <optional>
#include <QCoreApplication>
#include <QStringList>
#include <vector>

/// Samples read from measurement files, joined into one run for a report.
struct LoadedRun
{
    Pipeline pipeline;
    std::vector<std::vector<qint64>> samples; ///< stamps in pipeline order, ns since the epoch
    qint64 incomplete = 0; ///< samples that missed stamps (dropped)
    qint64 malformed = 0; ///< unreadable rows or records, skipped
    QStringList problems; ///< "FILE:LINE: what"
};

/// Reads the inputs of `bridgescope report` (suite CSV files) into one run.
///
/// Without a pipeline, the first file's columns are the pipeline and every other file must have
/// the same topics; with one, every file must have all of its topics (in any order, other columns
/// ignored), and its hosts and window apply.
class RunLoader
{
    Q_DECLARE_TR_FUNCTIONS(RunLoader)
public:
    static std::optional<LoadedRun> load(const QStringList& inputs, const std::optional<Pipeline>& pipeline,
                                         QString* error = nullptr);
};
