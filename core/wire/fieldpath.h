// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <optional>
#include <QCoreApplication>
#include <QJsonValue>
#include <QStringList>

struct RosValue;

/// A field of a decoded ROS message or a JSON document as its parts: names and "[i]" indices,
/// and the number it holds (ints, floats, bools as 0/1, times in seconds) for plots.
class FieldPath
{
    Q_DECLARE_TR_FUNCTIONS(FieldPath)
public:
    /// "pose.position.x", "ranges[3]".
    static QString text(const QStringList& parts);
    /// The largest array index the path names, or -1.
    static int maxIndex(const QStringList& parts);
    /// Whether a ROS builtin type (or a JSON "number"/"bool") is plotted as a number.
    static bool isNumericType(const QString& type);
    static Result<double> number(const RosValue& message, const QStringList& parts);
    static Result<double> number(const QJsonValue& document, const QStringList& parts);
};
