// SPDX-License-Identifier: MIT
#include "niceticks.h"

#include <algorithm>
#include <cmath>

namespace NiceTicks {

int Axis::tickCount() const
{
    return step > 0 ? int(std::lround((hi - lo) / step)) + 1 : 2;
}

double step(double lo, double hi, int wanted)
{
    if (!(hi > lo) || !std::isfinite(hi - lo))
        return 1;
    const double raw = (hi - lo) / double(std::max(2, wanted) - 1);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double f : {1.0, 2.0, 2.5, 5.0})
        if (f * power >= raw * (1 - 1e-9))
            return f * power;
    return 10 * power;
}

int decimals(double step)
{
    for (int d = 0; d < 9; ++d) {
        const double scaled = step * std::pow(10.0, d);
        if (std::round(scaled) >= 1 && std::abs(scaled - std::round(scaled)) < 1e-6 * scaled)
            return d;
    }
    return 9;
}

Axis axis(double lo, double hi, int wanted)
{
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo)
        lo = hi = 0;
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
        lo -= 0.5;
        hi += 0.5;
    }
    Axis a;
    a.step = step(lo, hi, wanted);
    // Rounding the ends outwards adds up to a step on each side: keep the ticks at `wanted`.
    for (int i = 0; i < 3; ++i) {
        a.lo = std::floor(lo / a.step + 1e-9) * a.step;
        a.hi = std::ceil(hi / a.step - 1e-9) * a.step;
        if (a.tickCount() <= std::max(wanted, 3))
            break;
        a.step = step(a.lo, a.hi, wanted);
    }
    if (std::abs(a.lo) < a.step * 1e-9)
        a.lo = 0;
    a.decimals = decimals(a.step);
    return a;
}

QList<double> ticks(double lo, double hi, int wanted)
{
    QList<double> out;
    if (!(hi > lo) || wanted < 2)
        return out;
    const double s = step(lo, hi, wanted);
    // Multiples of the step by an integer, not sums of it: 0.1 + 0.2 is not 0.3.
    for (double k = std::ceil(lo / s - 1e-9); k * s <= hi + s * 1e-9; ++k)
        out << (k == 0 ? 0.0 : k * s);
    return out;
}

} // namespace NiceTicks
