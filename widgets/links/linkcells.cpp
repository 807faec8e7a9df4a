// SPDX-License-Identifier: MIT
#include "linkcells.h"

#include <cmath>

using namespace Qt::StringLiterals;

QString LinkCells::figure(double value, int decimals, const QLocale& locale)
{
    return std::isfinite(value) ? locale.toString(value, 'f', decimals) : u"–"_s;
}

QString LinkCells::levelText(LinkLevel level)
{
    switch (level) {
    case LinkLevel::Ok:
        return tr("ok");
    case LinkLevel::Warning:
        return tr("warning");
    case LinkLevel::Alert:
        return tr("alert");
    }
    return {};
}

QString LinkCells::stateText(const LinkJudge::Verdict& verdict)
{
    return verdict.unknown ? tr("unknown") : levelText(verdict.level);
}
