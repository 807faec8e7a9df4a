// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>

/// The first check on a file that claims to be a ROS 1 bag, before rosbag's library (which can
/// crash on damaged input) is given it in a process of its own.
class BagHeader
{
    Q_DECLARE_TR_FUNCTIONS(BagHeader)
public:
    /// Whether the file starts with "#ROSBAG V2.0".
    static bool looksLikeBag(const QString& path);
    /// Why the file is not read at all (unreadable, no bag header); empty when it may be read.
    static QString refusal(const QString& path);
};
