// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <functional>
#include <QCoreApplication>
#include <QString>

/// The ROS nodes of the demo lab, shaped like the paper's experiment (see docs/user-guide.md,
/// "The demo lab"). Each runs in a process of its own (`bridgescope demo-node vehicle|cloud`).
///
/// - vehicle: publishes a sensor_msgs/PointCloud2 of `payloadBytes` (a VelodyneScan's 0.18 MB by
///   default) on /vehicle/pointcloud at `rateHz`, stamping `…/timestamps/pointcloud`; receives the
///   object list on /vehicle/object_list and stamps `…/timestamps/object_list`.
/// - cloud: "object detection": receives /cloud/pointcloud, stamps
///   `…/timestamps/object_detection/pointcloud`, works for about `detectionMs` (varying), publishes
///   a geometry_msgs/PoseArray with the scan's header on /cloud/object_list and stamps
///   `…/timestamps/object_detection/object_list`.
///
/// Every message keeps the scan's header, so all stamps of one scan join into one sample.
class DemoNodes
{
    Q_DECLARE_TR_FUNCTIONS(DemoNodes)
public:
    struct Options
    {
        QString masterUri;
        int payloadBytes = 180'000;
        double rateHz = 10;
        double detectionMs = 40;
        qint64 clockOffsetNs = 0; ///< this host's clock error
    };
    /// Runs until `stop` returns true (asked every 50 ms). An error when the master is not there or
    /// a topic cannot be used.
    static Status runVehicle(const Options& options, const std::function<bool()>& stop);
    static Status runCloud(const Options& options, const std::function<bool()>& stop);

    static QString stampPrefix() { return QStringLiteral("/benchmarking_suite/timestamps/"); }
};
