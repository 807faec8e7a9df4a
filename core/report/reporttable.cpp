// SPDX-License-Identifier: MIT
#include "reporttable.h"

#include "text/nameelider.h"

using namespace Qt::StringLiterals;

QString ReportTable::latexEscape(const QString& s)
{
    QString out;
    for (const QChar c : s) {
        switch (c.unicode()) {
        case u'\\':
            out += u"\\textbackslash{}"_s;
            break;
        case u'&':
        case u'%':
        case u'$':
        case u'#':
        case u'_':
        case u'{':
        case u'}':
            out += u'\\';
            out += c;
            break;
        case u'~':
            out += u"\\textasciitilde{}"_s;
            break;
        case u'^':
            out += u"\\textasciicircum{}"_s;
            break;
        case 0x2192:
            out += u"$\\rightarrow$"_s;
            break; // →
        case 0x2194:
            out += u"$\\leftrightarrow$"_s;
            break; // ↔
        case 0x2013:
            out += u"--"_s;
            break; // –
        default:
            out += c;
        }
    }
    return out;
}

QString ReportTable::shown(const QString& text, qsizetype max)
{
    QString out = NameElider::elideTail(text, max);
    for (QChar& c : out) {
        const char16_t u = c.unicode();
        if (u == u'\n' || u == u'\r' || u == u'\t' || u == 0x2028 || u == 0x2029)
            c = u' ';
        else if (u < 0x20 || (u >= 0x7f && u < 0xa0))
            c = QChar::ReplacementCharacter;
    }
    return out;
}

QString ReportTable::mdEscape(const QString& s)
{
    QString out;
    out.reserve(s.size());
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s.at(i);
        switch (c.unicode()) {
        case u'\\':
        case u'|':
        case u'`':
        case u'<':
        case u'>':
            out += u'\\';
            break;
        case u']':
            if (i + 1 < s.size() && s.at(i + 1) == u'(')
                out += u'\\';
            break;
        default:
            break;
        }
        out += c;
    }
    return out;
}

QString ReportTable::markdown() const
{
    QStringList head;
    for (const QString& h : header)
        head << mdEscape(h);
    QString out = u"| "_s + head.join(u" | "_s) + u" |\n|"_s;
    for (qsizetype i = 0; i < header.size(); ++i)
        out += isNumeric(i) ? u" ---: |"_s : u" --- |"_s;
    out += u'\n';
    for (const Row& c : rows) {
        QString label = mdEscape(c.label);
        if (c.emphasized)
            label = u"**"_s + label + u"**"_s;
        else if (c.crossing || c.derived)
            label = u"*"_s + label + u"*"_s;
        QStringList values;
        for (const QString& v : c.values)
            values << (c.emphasized && !v.isEmpty() ? u"**"_s + mdEscape(v) + u"**"_s : mdEscape(v));
        out += u"| "_s + label + u" | "_s + values.join(u" | "_s) + u" |\n"_s;
    }
    return out + u'\n';
}

QString ReportTable::latex() const
{
    QString columns;
    for (qsizetype i = 0; i < header.size(); ++i)
        columns += isNumeric(i) ? u'r' : u'l';
    QString out = u"\\begin{tabular}{"_s + columns + u"}\n\\toprule\n"_s;
    QStringList head;
    for (const QString& h : header)
        head << latexEscape(h);
    out += head.join(u" & "_s) + u" \\\\\n\\midrule\n"_s;
    bool derivedStarted = false;
    for (const Row& c : rows) {
        if ((c.emphasized || c.derived) && !derivedStarted) {
            out += u"\\midrule\n"_s;
            derivedStarted = true;
        }
        QString label = latexEscape(c.label);
        if (c.emphasized)
            label = u"\\textbf{"_s + label + u'}';
        else if (c.crossing || c.derived)
            label = u"\\textit{"_s + label + u'}';
        QStringList cells {label};
        for (const QString& v : c.values)
            cells << (c.emphasized && !v.isEmpty() ? u"\\textbf{"_s + latexEscape(v) + u'}' : latexEscape(v));
        out += cells.join(u" & "_s) + u" \\\\\n"_s;
    }
    return out + u"\\bottomrule\n\\end{tabular}\n"_s;
}

QString ReportTable::html(const QString& attributes) const
{
    QString out = u"<table class=\"stats\""_s + attributes + u">\n<tr>"_s;
    for (qsizetype i = 0; i < header.size(); ++i)
        out += (i == 0 ? u"<th class=\"label\" align=\"left\">"_s
                       : (isNumeric(i) ? u"<th align=\"right\">"_s : u"<th align=\"left\">"_s))
            + header[i].toHtmlEscaped() + u"</th>"_s;
    out += u"</tr>\n"_s;
    for (const Row& c : rows) {
        QString label = c.label.toHtmlEscaped();
        if (c.emphasized)
            label = u"<b>"_s + label + u"</b>"_s;
        else if (c.crossing || c.derived)
            label = u"<i>"_s + label + u"</i>"_s;
        out += u"<tr><td class=\"label\">"_s + label + u"</td>"_s;
        for (qsizetype i = 0; i < c.values.size(); ++i) {
            const QString v = c.values[i].toHtmlEscaped();
            out += (isNumeric(i + 1) ? u"<td align=\"right\">"_s : u"<td>"_s)
                + (c.emphasized ? u"<b>"_s + v + u"</b>"_s : v) + u"</td>"_s;
        }
        out += u"</tr>\n"_s;
    }
    return out + u"</table>\n"_s;
}
