// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

class Report;

/// The formats of a report: JSON, CSV, Markdown, LaTeX, HTML and (through ReportPdf) PDF, behind
/// one call.
///
/// One run: its stage table (mean, median, std, min, max, p99, count). Several: the paper's
/// Table I layout, stages as rows and runs as columns (means), a total row, and a summary of each
/// run's total. Statistics in ms; crossings between hosts and derived rows are marked.
class ReportFormats
{
    Q_DECLARE_TR_FUNCTIONS(ReportFormats)
public:
    enum class Format { Json, Csv, Markdown, Latex, Html, Pdf };
    /// A format is one row of formats(): its name (the command line's and the file suffix), the
    /// title a window offers it by, whether the preview shows it as rich text with the figure,
    /// and how it is rendered. A new format is a new row.
    struct Entry
    {
        Format format;
        QString name;
        QString title;
        bool richPreview = false;
        Result<QByteArray> (*render)(const Report& report, bool perSampleMs) = nullptr;
    };
    /// Every format, in the order a window offers them (the most wanted first).
    static const QList<Entry>& formats();
    static const Entry& entry(Format format);
    static bool parse(const QString& name, Format* format);
    static QString name(Format format) { return entry(format).name; }
    static QString suffix(Format format) { return name(format); }

    /// The report in `format`; an error when it has no such form (CSV of several runs).
    /// The PDF needs a QGuiApplication. `perSampleMs`: see csv().
    static Result<QByteArray> render(const Report& report, Format format, bool perSampleMs);

    static QByteArray json(const Report& report);
    /// The suite CSV of a single run (complete samples); with `perSampleMs`, one row per sample
    /// of stage latencies in ms instead. An error for several runs.
    static Result<QByteArray> csv(const Report& report, bool perSampleMs);
    static QByteArray markdown(const Report& report);
    static QByteArray latex(const Report& report);
    /// One self-contained file: title block, tables and the ECDF figure as inline SVG. Well-formed
    /// XML, so that it also reads as XHTML.
    static QByteArray html(const Report& report);
    /// The title block and tables as HTML that QTextDocument renders (for the PDF and previews).
    static QString htmlBody(const Report& report, bool forQtRichText);
    /// The ECDF figure: a single run's total (and its one-way communication), or every run's total.
    static QByteArray ecdfSvg(const Report& report, int width = 720, int height = 400);
};
