// SPDX-License-Identifier: MIT
#include "reportpdf.h"

#include "report/report.h"
#include "report/reportformats.h"

#include <algorithm>
#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgRenderer>
#include <QTextDocument>

using namespace Qt::StringLiterals;

QByteArray ReportPdf::render(const Report& report)
{
    QList<QByteArray> figures;
    if (report.hasPipeline())
        figures << ReportFormats::ecdfSvg(report);
    // The body's texts are cut where they are laid out (ReportFormats); the title is the document's.
    return render(report.title().left(1000), ReportFormats::htmlBody(report, true), figures);
}

QByteArray ReportPdf::render(const QString& title, const QString& bodyHtml, const QList<QByteArray>& figures)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(18, 16, 18, 16), QPageLayout::Millimeter);
        pdf.setResolution(300);
        pdf.setTitle(title);
        pdf.setCreator(u"Bridgescope "_s + QStringLiteral(BRIDGESCOPE_VERSION));
        QPainter painter(&pdf);
        const QRectF page(QPointF(0, 0), QSizeF(pdf.pageLayout().paintRectPixels(pdf.resolution()).size()));

        QTextDocument doc;
        doc.documentLayout()->setPaintDevice(&pdf);
        QFont font(u"DejaVu Sans"_s);
        font.setPointSizeF(8.5);
        doc.setDefaultFont(font);
        doc.setDefaultStyleSheet(u"h1 { font-size: 15pt; } h2 { font-size: 11pt; margin-top: 10px; } "
                                 "h3 { font-size: 10pt; } th { color: #444; } "
                                 ".note { color: #555; font-size: 7.5pt; }"_s);
        doc.setHtml(bodyHtml);
        doc.setPageSize(page.size());
        const int pages = doc.pageCount();
        for (int i = 0; i < pages; ++i) {
            if (i > 0)
                pdf.newPage();
            painter.save();
            painter.translate(0, -page.height() * i);
            doc.drawContents(&painter, QRectF(0, page.height() * i, page.width(), page.height()));
            painter.restore();
        }

        // The figures below the tables, each on a new page when it does not fit.
        double y = doc.size().height() - page.height() * (pages - 1) + page.height() * 0.02;
        for (const QByteArray& svg : figures) {
            QSvgRenderer renderer(svg);
            const QSizeF natural = renderer.defaultSize();
            if (natural.isEmpty())
                continue;
            bool newPage = false;
            const QRectF at = placeFigure(y, page.size(), natural, &newPage);
            if (newPage)
                pdf.newPage();
            renderer.render(&painter, at);
            y = at.bottom() + page.height() * 0.02;
        }
    }
    return buffer.data();
}

QRectF ReportPdf::placeFigure(double y, const QSizeF& page, const QSizeF& natural, bool* newPage)
{
    const double height = page.width() * natural.height() / natural.width();
    const double room = page.height() - y;
    *newPage = false;
    if (height <= room)
        return QRectF(0, y, page.width(), height);
    if (room >= kMinShrink * height) {
        const double width = page.width() * room / height;
        return QRectF((page.width() - width) / 2, y, width, room);
    }
    *newPage = true;
    return QRectF(0, 0, page.width(), std::min(height, page.height()));
}
