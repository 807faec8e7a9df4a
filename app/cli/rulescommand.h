// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

/// `bridgescope rules`: prints the Prometheus recording and alerting rules for the metrics of
/// `watch --metrics` (resources/prometheus/bridgescope-rules.yml, embedded; the package installs
/// the same file as share/bridgescope/prometheus/bridgescope-rules.yml).
int runRulesCommand(const QStringList& arguments);
