// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope record --pipeline PIPE.yaml [--broker URL] [--ros-master URI] [--samples N | --seconds S] -o
/// RUN`
int runRecordCommand(const QStringList& arguments);
