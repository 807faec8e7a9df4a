// SPDX-License-Identifier: MIT
#include "clocktext.h"

#include "clock/clockestimate.h"
#include "latency/pipeline.h"
#include "latency/pipelineseries.h"

#include <QStringList>

using namespace Qt::StringLiterals;

namespace {
QString signedMs(double ms)
{
    return (ms >= 0 ? u"+"_s : QString()) + QString::number(ms, 'f', 2);
}
} // namespace

QString ClockText::measured(const PipelineSeries& series, const Pipeline& pipeline)
{
    const QString home = pipeline.host(0);
    QStringList parts;
    for (auto c = series.clocks().cbegin(); c != series.clocks().cend(); ++c) {
        if (c.key() == home)
            continue;
        const ClockEstimate between = series.clockBetween(home, c.key());
        if (!between.isValid())
            continue;
        parts << tr("%1 %2 ms ± %3 ms against %4")
                     .arg(c.key(), signedMs(double(between.offsetNs) / 1e6),
                          QString::number(double(between.uncertaintyNs) / 1e6, 'f', 2), home);
    }
    parts.sort();
    return parts.join(u"; "_s);
}
