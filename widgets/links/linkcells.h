// SPDX-License-Identifier: MIT
#pragma once

#include "watch/linkjudge.h"

#include <QCoreApplication>
#include <QLocale>
#include <QString>

/// The cell texts both tables of the Links page show alike: the window's own watch (LinkModel)
/// and the fleet's (FleetModel).
class LinkCells
{
    Q_DECLARE_TR_FUNCTIONS(LinkCells)
public:
    /// A rate or a latency with `decimals`, "–" for a figure the link does not have (NaN).
    static QString figure(double value, int decimals, const QLocale& locale = QLocale::c());
    /// "ok", "warning" or "alert".
    static QString levelText(LinkLevel level);
    /// A verdict's state: its level, or "unknown" when it has none.
    static QString stateText(const LinkJudge::Verdict& verdict);
    /// The alignment of the figure columns (rates, loss, latencies).
    static int figureAlignment() { return int(Qt::AlignRight | Qt::AlignVCenter); }
};
