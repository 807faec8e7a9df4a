// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

/// A table of a report as every text format lays it out: a header, then rows of a label and
/// values. Run reports (ReportFormats) and experiment reports (ExperimentReport) build these and
/// render them here, so that each format has one escaper: latexEscape(), mdEscape(), and Qt's
/// toHtmlEscaped().
struct ReportTable
{
    struct Row
    {
        QString label;
        QStringList values;
        bool crossing = false; ///< italic: a crossing between hosts
        bool emphasized = false; ///< bold, after a rule: a total
        bool derived = false; ///< italic, after a rule: a figure derived from others
    };
    QStringList header;
    QList<Row> rows;
    /// Per column, whether it holds figures (right-aligned); empty: every column but the first.
    QList<bool> numeric;
    bool isNumeric(qsizetype column) const { return numeric.isEmpty() ? column > 0 : numeric.value(column); }

    /// The Markdown table and a blank line after it.
    QString markdown() const;
    /// The booktabs tabular (\begin{tabular} … \end{tabular} and its newline).
    QString latex() const;
    /// The HTML table; `attributes` go into its tag (" border=\"1\"", for Qt's rich text).
    QString html(const QString& attributes = QString()) const;

    /// A text in LaTeX: its specials (\ & % $ # _ { } ~ ^) escaped, arrows and dashes as LaTeX has them.
    static QString latexEscape(const QString& s);
    /// The Markdown characters a text could use to end a table cell (`|`), open a code span, or
    /// make an inline link (`](`) or a raw HTML tag, taken literally (emphasis characters are left:
    /// they only style; `[ms]` stays as it is).
    static QString mdEscape(const QString& s);
    /// A text as a report lays it out: on one line, without control characters (a NUL, an escape;
    /// each shown as U+FFFD), at most `max` characters keeping its tail. Every format's tables and
    /// facts take their texts through this, so a name cannot break a table or take minutes to lay out.
    static QString shown(const QString& text, qsizetype max);
};
