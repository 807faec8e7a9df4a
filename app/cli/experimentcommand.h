// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope experiment PLAN.yaml -o DIR [--resume] [--dry-run]`
int runExperimentCommand(const QStringList& arguments);
