// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QCoreApplication>

class Report;

/// The PDF report: A4, a title block and the tables (laid out by QTextDocument, paginated), then
/// the ECDF figure drawn as vectors from the same SVG the HTML report embeds.
class ReportPdf
{
    Q_DECLARE_TR_FUNCTIONS(ReportPdf)
public:
    /// The PDF's bytes (written by the caller, atomically). Needs a QGuiApplication.
    static QByteArray render(const Report& report);
};
