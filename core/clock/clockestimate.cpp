// SPDX-License-Identifier: MIT
#include "clock/clockestimate.h"

ClockEstimate ClockEstimate::between(const ClockEstimate& from, const ClockEstimate& to)
{
    ClockEstimate e;
    if (!from.isValid() || !to.isValid())
        return e;
    e.host = to.host;
    e.offsetNs = to.offsetNs - from.offsetNs;
    e.uncertaintyNs = to.uncertaintyNs + from.uncertaintyNs;
    e.driftPpm = to.driftPpm - from.driftPpm;
    e.bestRoundTripNs = qMax(to.bestRoundTripNs, from.bestRoundTripNs);
    e.atNs = qMax(to.atNs, from.atNs);
    e.probes = qMin(to.probes, from.probes);
    return e;
}
