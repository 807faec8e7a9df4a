// SPDX-License-Identifier: MIT
#pragma once

#include "wire/rosmessage.h"

#include <QStringList>

/// Where the ROS 2 message definitions come from: those bundled with Bridgescope (std_msgs,
/// builtin_interfaces, geometry_msgs, sensor_msgs; resources/ros2) and `.msg` files under folders
/// the user names, laid out as ROS 2 installs them (`<package>/msg/<Type>.msg`, at any depth).
namespace Ros2Definitions {

/// Files read from one folder at most, and the largest definition read.
constexpr int kMaxFiles = 20'000;
constexpr qint64 kMaxFileBytes = 256 * 1024;

/// Adds every definition under `folder` (a folder of the bundled resources works too); a user's
/// definition replaces a bundled one of the same name. Returns how many were added; each file that
/// could not be read or parsed is one line in `errors`.
int addFolder(RosTypeRegistry& registry, const QString& folder, QStringList* errors = nullptr);

/// The bundled definitions, then those under `folders`.
RosTypeRegistry registry(const QStringList& folders = {}, QStringList* errors = nullptr);

/// `pkg/msg/Type` for a path `.../pkg/msg/Type.msg`, or an empty string.
QString typeOfPath(const QString& path);

} // namespace Ros2Definitions
