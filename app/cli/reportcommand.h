// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope report INPUT... [--pipeline PIPE.yaml] [--format json] [--window N] [-o OUT]`
int runReportCommand(const QStringList& arguments);
