// SPDX-License-Identifier: MIT
#pragma once

#include "latency/shiftestimate.h"

#include <optional>
#include <QCoreApplication>
#include <QStringList>

class ExperimentReport;
class LatencySeries;

/// What an experiment's report found, in sentences: failed and unfinished cells, throughput, and
/// per factor the levels with the lowest and the highest total mean, with the shift of their
/// totals and its 95 % interval (ShiftEstimate).
class ExperimentFindings
{
    Q_DECLARE_TR_FUNCTIONS(ExperimentFindings)
public:
    /// Every finding of `report`, in the order of its cells, throughput and factor tables.
    static QStringList of(const ExperimentReport& report);
    /// The shift of `high`'s values against `low`'s (each series' window), nullopt when too few.
    static std::optional<ShiftEstimate> shiftOf(const LatencySeries& low, const LatencySeries& high);
    /// "3.2 ms [-1.0, 7.5] ms, 95 %".
    static QString shiftText(const ShiftEstimate& shift);
    /// A factor's finding: the levels with the lowest and the highest total mean, with the shift of
    /// their totals; "no significant difference" when its interval holds zero.
    static QString differenceFinding(const QString& factor, const QString& lowLevel, double lowMs,
                                     const QString& highLevel, double highMs,
                                     const std::optional<ShiftEstimate>& shift);
};
