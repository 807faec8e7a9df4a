// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

class LatencyEngine;

/// A figure of the engine that cannot be a measurement: the data contradict the pipeline.
struct LatencyWarning
{
    QString seriesId; ///< SeriesId::toString() of the figure it is pinned to
    QString label; ///< that series' label
    QString reason; ///< what is wrong, with the figure: "median -9.86 ms: a latency cannot be negative"
};

/// Contradictions in the figures, stated where the figures are (the Measure page, reports,
/// `record`), never drawn as a result: a stage on one clock, the total on one host, or a derived
/// communication figure whose median is negative; an order that leaves and re-enters hosts more
/// often than going there and back does. A crossing between two clocks may be negative (its raw
/// value holds the clock offset), and so may the clock offset.
class LatencyWarnings
{
    Q_DECLARE_TR_FUNCTIONS(LatencyWarnings)
public:
    static QList<LatencyWarning> of(const LatencyEngine& engine);
    /// What to do about them in the window: set the hosts, or load a pipeline.
    static QString fixInWindow();
    /// What to do about them on the command line.
    static QString fixOnCommandLine();
    /// "communication, round trip: median -9.86 ms: a latency cannot be negative …"; figures wrong
    /// for the same reason share a line.
    static QStringList lines(const QList<LatencyWarning>& warnings);
};
