// SPDX-License-Identifier: MIT
#pragma once

#include "syntheticrun.h"

#include <QByteArray>
#include <QString>
#include <string>
#include <topic_tools/shape_shifter.h>

/// ROS bags written with rosbag's own API, for the tests that import them.
namespace StampBag {
/// A message of any type from its serialized bytes.
topic_tools::ShapeShifter shaped(const char* md5, const char* type, const std::string& definition,
                                 const QByteArray& bytes);
/// A bag with the suite's stamps of `synthetic`, a latency topic and an unrelated topic.
void write(const QString& path, const SyntheticRun& synthetic);
} // namespace StampBag
