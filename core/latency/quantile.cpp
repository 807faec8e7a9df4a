// SPDX-License-Identifier: MIT
#include "quantile.h"

#include <algorithm>
#include <cmath>
#include <limits>

std::pair<qint64, double> Quantile::rank(qint64 n, double q)
{
    const double index = q * double(n - 1);
    const qint64 lo = std::clamp<qint64>(qint64(std::floor(index)), 0, n - 1);
    return {lo, index - double(lo)};
}

double Quantile::lerp(double atRank, double atNextRank, double t)
{
    const double diff = atNextRank - atRank;
    return t >= 0.5 ? atNextRank - diff * (1 - t) : atRank + diff * t;
}

double Quantile::of(std::vector<double>& values, double q)
{
    if (values.empty())
        return std::numeric_limits<double>::quiet_NaN();
    const auto [lo, t] = rank(qint64(values.size()), q);
    const auto at = values.begin() + std::ptrdiff_t(lo);
    std::nth_element(values.begin(), at, values.end());
    const double next = at + 1 == values.end() ? *at : *std::min_element(at + 1, values.end());
    return lerp(*at, next, t);
}
