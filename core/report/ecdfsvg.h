// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

class LatencySeries;

/// An ECDF figure as standalone SVG, the paper's Fig. 5 in style: one curve per series, its mean
/// dashed and its median dotted, a ms axis with round ticks up to a high quantile (values beyond it
/// marked at its end, Ecdf::shownRange), a legend below. For HTML reports
/// (inline), PDF reports (rendered as vectors) and "save chart as SVG" of reports.
class EcdfSvg
{
    Q_DECLARE_TR_FUNCTIONS(EcdfSvg)
public:
    struct Curve
    {
        QString label;
        QString color; ///< "#rrggbb"
        const LatencySeries* series = nullptr;
    };
    static QByteArray render(const QList<Curve>& curves, int width = 720, int height = 400,
                             const QString& title = QString());
    /// The marks of values beyond the axis' end `hi`: a dot per curve at the plot's right edge
    /// and a line "label: N beyond hi ms" per curve with any.
    static QString beyondMarks(const QList<Curve>& curves, double hi, double right, double top, double plotH);
    /// "Nice" tick positions (1, 2, 2.5 or 5 times a power of ten) covering [lo, hi].
    static QList<double> ticks(double lo, double hi, int wanted = 6);
};
