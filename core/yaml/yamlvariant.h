// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QVariant>

/// YAML text (and so JSON) as a plain value tree: maps, lists, scalars as their text, null as an
/// invalid QVariant. Checked against YamlLimits first; what a scalar means is left to the reader
/// (RosMessageEncoder reads numbers, bools and times from text).
class YamlVariant
{
    Q_DECLARE_TR_FUNCTIONS(YamlVariant)
public:
    /// The tree of `text`; a syntax error or a limit passed is located ("line 2, column 5: …").
    static Result<QVariant> read(const QByteArray& text);
};
