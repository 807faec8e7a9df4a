// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

/// The colours of series, the same on screen, in SVG and in PDF: distinct, print-friendly hues
/// (Tableau 10), as "#rrggbb".
inline QString seriesColor(int index)
{
    static const QStringList colors {QStringLiteral("#4e79a7"), QStringLiteral("#f28e2b"),
                                     QStringLiteral("#e15759"), QStringLiteral("#76b7b2"),
                                     QStringLiteral("#59a14f"), QStringLiteral("#edc948"),
                                     QStringLiteral("#b07aa1"), QStringLiteral("#ff9da7"),
                                     QStringLiteral("#9c755f"), QStringLiteral("#bab0ac")};
    return colors[(index % colors.size() + colors.size()) % colors.size()];
}
