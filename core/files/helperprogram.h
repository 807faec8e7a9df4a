// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

/// Finds one of Bridgescope's helper programs (bridgescope-bagreader, bridgescope-dds): the path in
/// the environment variable `envVar` if set, beside this program, in ../libexec/bridgescope (the
/// installed layout), or `buildPath` (the build tree). Empty when none is an executable file.
QString findHelperProgram(const QString& name, const char* envVar, const QString& buildPath = {});
