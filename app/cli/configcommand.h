// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope config validate|convert|peer ...`; returns the process exit code.
int runConfigCommand(const QStringList& arguments);
