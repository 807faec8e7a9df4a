// SPDX-License-Identifier: MIT
#pragma once

#include "ros/demonodes.h"
#include "ros2/ros2types.h"

#include <functional>
#include <QCoreApplication>
#include <QString>

/// The demo lab's nodes on ROS 2 (`bridgescope demo-node vehicle|cloud --ros 2`): the same
/// pipeline, topics and stamps as DemoNodes on ROS 1, as DDS nodes through Ros2Participant (each
/// process its own `bridgescope-dds` child), announced in ros_discovery_info as `/demo_vehicle`
/// and `/demo_object_detection`. Messages are ROS 2's (sensor_msgs/msg/PointCloud2,
/// geometry_msgs/msg/PoseArray), stamps the suite's `benchmarking_suite/msg/TimeStamped` in its
/// ROS 2 form (a Header without seq, and the time of the stamp). Every message keeps the scan's
/// header, so all stamps of one scan join into one sample on `header.stamp`. The stamps and the
/// header's stamp are written and read as the ROS 2 reference bridge does (Ros2BridgeWire).
class Ros2DemoNodes
{
    Q_DECLARE_TR_FUNCTIONS(Ros2DemoNodes)
public:
    /// DemoNodes' options (its masterUri unused), and the domain.
    struct Options : DemoNodes::Options
    {
        Ros2Options dds {0, true};
    };
    /// Runs until `stop` returns true (asked every 50 ms); an error when the participant cannot be
    /// started or does not join the domain.
    static Status runVehicle(const Options& options, const std::function<bool()>& stop);
    static Status runCloud(const Options& options, const std::function<bool()>& stop);
};
