// SPDX-License-Identifier: MIT
#pragma once

#include <QCoreApplication>
#include <QString>

class PipelineSeries;
class Pipeline;

/// How the measured clocks of a pipeline's hosts read for people, in the window and in reports:
/// each host against the pipeline's first host, with its uncertainty.
class ClockText
{
    Q_DECLARE_TR_FUNCTIONS(ClockText)
public:
    /// "cloud +35.02 ms ± 0.41 ms against vehicle; …", sorted by host; empty when no host other
    /// than the first has an estimate against it.
    static QString measured(const PipelineSeries& series, const Pipeline& pipeline);
};
