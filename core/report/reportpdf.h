// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QRectF>
#include <QString>

class Report;

/// The PDF report: A4, a title block and the tables (laid out by QTextDocument, paginated), then
/// the ECDF figure drawn as vectors from the same SVG the HTML report embeds.
class ReportPdf
{
    Q_DECLARE_TR_FUNCTIONS(ReportPdf)
public:
    /// The PDF's bytes (written by the caller, atomically). Needs a QGuiApplication.
    static QByteArray render(const Report& report);
    /// Any report as such a PDF: `bodyHtml` (Qt rich text) paginated, then each SVG figure drawn
    /// full width below it (on a new page when it does not fit).
    static QByteArray render(const QString& title, const QString& bodyHtml, const QList<QByteArray>& figures);

    /// Where a figure of `natural` size goes below content that ends at `y` on a page of `page`
    /// size: full width when it fits; shrunk into the room left (centred) when that is at least
    /// kMinShrink of its full-width height, since a page left two-thirds blank for want of a few
    /// lines reads worse; else at the top of a new page (`newPage` set).
    static QRectF placeFigure(double y, const QSizeF& page, const QSizeF& natural, bool* newPage);
    static constexpr double kMinShrink = 0.35; // a vector ECDF at a third of the text width still reads
};
