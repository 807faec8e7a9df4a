// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "latency/rundata.h"

#include <optional>
#include <QCoreApplication>

/// Reads the stamps of a ROS 1 bag (rosbag's own library, read-only: the bag is never changed).
///
/// Every `benchmarking_suite/TimeStamped` connection becomes a stamp topic (checked by md5), every
/// `std_msgs/Float64` topic under `…/latencies/` a single-stage series; the time a message was
/// recorded stands for when it arrived. Bags carry no pipeline: the stamps propose one.
class RosbagImport
{
    Q_DECLARE_TR_FUNCTIONS(RosbagImport)
public:
    /// The bag as a run; the error names the file.
    static Result<RunData> read(const QString& path, const Progress& progress = {});
};
