// SPDX-License-Identifier: MIT
#pragma once

#include "record/runfile.h"

#include <QCoreApplication>

/// Reads a ROS bag in a child process (`bridgescope-bagreader`), never in this one.
///
/// rosbag's library trusts the file: a damaged bag can make it crash or allocate gigabytes. The
/// child converts the bag to a run file under limits of memory and of time without progress, and
/// this process reads that; a crash of the child is a clear error about the bag.
class BagReaderProcess
{
    Q_DECLARE_TR_FUNCTIONS(BagReaderProcess)
public:
    /// The bag as a run; the error names the file.
    static Result<RunData> read(const QString& path, const Progress& progress = {});
    /// The helper program: $BRIDGESCOPE_BAGREADER, beside this program, in ../libexec/bridgescope,
    /// or in the build tree.
    static QString program();
};
