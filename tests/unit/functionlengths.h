// SPDX-License-Identifier: MIT
#pragma once

// The functions of a C++ source text and their lengths, for tst_architecture's length rule: free
// functions, members defined outside their class, and members defined inside a class body (inline
// members in headers, members of classes local to a .cpp). Not a C++ parser: comments, strings,
// character literals and preprocessor lines are blanked, then every brace at namespace or class
// scope is classified by the text before it. A lambda or local class is part of its function.
#include <algorithm>
#include <QList>
#include <QRegularExpression>
#include <QString>

namespace FunctionLengths {

struct Function
{
    QString name; ///< the name before the parameters, as written ("Checker::add", "operator==")
    int line = 0; ///< of the first line of its head (a template line included), from 1
    int lines = 0; ///< from that line to its closing brace, both counted
};

struct Scan
{
    QList<Function> functions;
    QString error; ///< empty, or where the braces did not balance
};

namespace Detail {

inline bool isIdentifierChar(QChar c)
{
    return c.isLetterOrNumber() || c == u'_';
}

/// Blanks from `from` to the end of a // comment, keeping the newline.
inline qsizetype blankLineComment(QString& s, qsizetype from)
{
    qsizetype i = from;
    while (i < s.size() && s[i] != u'\n')
        s[i++] = u' ';
    return i;
}

/// Blanks a /* */ comment starting at `from`, keeping its newlines.
inline qsizetype blankBlockComment(QString& s, qsizetype from)
{
    const qsizetype end = s.indexOf(u"*/", from + 2);
    const qsizetype stop = end < 0 ? s.size() : end + 2;
    for (qsizetype i = from; i < stop; ++i)
        if (s[i] != u'\n')
            s[i] = u' ';
    return stop;
}

/// Blanks the inside of a quoted literal ('…' or "…") that opens at `from`; returns past its end.
inline qsizetype blankQuoted(QString& s, qsizetype from)
{
    const QChar quote = s[from];
    qsizetype i = from + 1;
    while (i < s.size() && s[i] != quote && s[i] != u'\n') {
        if (s[i] == u'\\' && i + 1 < s.size())
            s[i++] = u' ';
        s[i++] = u' ';
    }
    return i + 1;
}

/// Blanks a raw string R"delim( … )delim" whose quote is at `from`; returns past its end.
inline qsizetype blankRaw(QString& s, qsizetype from)
{
    const qsizetype open = s.indexOf(u'(', from);
    if (open < 0)
        return s.size();
    const QString close = u')' + s.mid(from + 1, open - from - 1) + u'"';
    const qsizetype end = s.indexOf(close, open);
    const qsizetype stop = end < 0 ? s.size() : end + close.size();
    for (qsizetype i = from + 1; i < stop - 1; ++i)
        if (s[i] != u'\n')
            s[i] = u' ';
    return stop;
}

/// Whether the ' at `at` separates digits (1'000'000) rather than opening a character literal.
inline bool isDigitSeparator(const QString& s, qsizetype at)
{
    qsizetype start = at;
    while (start > 0 && (isIdentifierChar(s[start - 1]) || s[start - 1] == u'\''))
        --start;
    return start < at && s[start].isDigit();
}

/// The text with comments, the insides of strings and character literals, and preprocessor lines
/// blanked (newlines kept, so that positions and line numbers stay).
inline QString code(QString s)
{
    bool lineStart = true;
    for (qsizetype i = 0; i < s.size();) {
        const QChar c = s[i];
        const QChar next = i + 1 < s.size() ? s[i + 1] : QChar();
        if (lineStart && c == u'#') {
            while (i < s.size() && s[i] != u'\n') {
                if (s[i] == u'\\' && i + 1 < s.size() && s[i + 1] == u'\n')
                    ++i; // a continued directive
                else
                    s[i++] = u' ';
            }
            continue;
        }
        if (c == u'\n')
            lineStart = true;
        else if (!c.isSpace())
            lineStart = false;
        if (c == u'/' && next == u'/')
            i = blankLineComment(s, i);
        else if (c == u'/' && next == u'*')
            i = blankBlockComment(s, i);
        else if (c == u'"' && i > 0 && s[i - 1] == u'R')
            i = blankRaw(s, i);
        else if (c == u'"' || (c == u'\'' && !isDigitSeparator(s, i)))
            i = blankQuoted(s, i);
        else
            ++i;
    }
    return s;
}

/// Where the brace group opening at `open` closes, or -1.
inline qsizetype closing(const QString& s, qsizetype open)
{
    int depth = 0;
    for (qsizetype i = open; i < s.size(); ++i) {
        if (s[i] == u'{')
            ++depth;
        else if (s[i] == u'}' && --depth == 0)
            return i;
    }
    return -1;
}

/// `head` without what precedes the declaration itself: access labels and Qt's statement-less
/// macros (Q_OBJECT, Q_DECLARE_TR_FUNCTIONS(X), Q_ENUM(X)). Returns the offset cut.
inline qsizetype declarationStart(const QString& head)
{
    static const QRegularExpression label(
        QStringLiteral("\\b(public|protected|private|signals|Q_SIGNALS)(\\s+(slots|Q_SLOTS))?\\s*:(?!:)"));
    static const QRegularExpression macros(QStringLiteral("^(\\s*Q_[A-Z_]+(\\s*\\([^()]*\\))?)*\\s*"));
    qsizetype from = 0;
    for (QRegularExpressionMatchIterator it = label.globalMatch(head); it.hasNext();)
        from = it.next().capturedEnd();
    return from + macros.match(head.mid(from)).capturedLength();
}

/// `text` with every brace group and its contents taken out (an initializer list's members).
inline QString withoutBraceGroups(const QString& text)
{
    QString out;
    int depth = 0;
    for (const QChar c : text) {
        if (c == u'{')
            ++depth;
        else if (c == u'}')
            --depth;
        else if (depth == 0)
            out += c;
    }
    return out;
}

enum class Kind { Scope, Function, InInitializers, Other };

/// What the brace after `head` (a declaration, trimmed of labels) opens.
inline Kind classify(const QString& head, QChar before)
{
    static const QRegularExpression scope(QStringLiteral(
        "^(template\\s*<[^{]*>\\s*)?(namespace|class|struct|union|enum)\\b|^namespace$|^extern\\b"));
    static const QRegularExpression operatorName(QStringLiteral("\\boperator\\s*(\\(\\)|\\[\\]|[^\\s(]+)"));
    static const QRegularExpression initializers(QStringLiteral("\\)\\s*(noexcept\\s*)?:(?!:)"));
    static const QRegularExpression qualifiers(QStringLiteral(
        "^\\s*((const|override|final|noexcept|mutable|volatile|try)\\b\\s*|&&?\\s*)*(->[^;=]*)?$"));
    const QString plain
        = withoutBraceGroups(head).replace(operatorName, QStringLiteral("operator_")).trimmed();
    if (plain.isEmpty())
        return Kind::Other;
    if (scope.match(plain).hasMatch() && !plain.contains(u'('))
        return Kind::Scope;
    const qsizetype paren = plain.indexOf(u'(');
    if (paren < 0 || plain.left(paren).contains(u'='))
        return Kind::Other; // an initializer, a variable holding a lambda
    if (initializers.match(plain).hasMatch())
        return before == u')' || before == u'}' ? Kind::Function : Kind::InInitializers;
    return qualifiers.match(plain.mid(plain.lastIndexOf(u')') + 1)).hasMatch() ? Kind::Function : Kind::Other;
}

/// The function's name in its head: the qualified name before its parameters.
inline QString nameOf(const QString& head)
{
    static const QRegularExpression name(
        QStringLiteral("((?:[A-Za-z_]\\w*\\s*::\\s*)*~?(?:operator\\s*[^\\s(]*|[A-Za-z_]\\w*))\\s*\\("));
    const QRegularExpressionMatch m = name.match(withoutBraceGroups(head));
    return m.hasMatch() ? m.captured(1).remove(QRegularExpression(QStringLiteral("\\s"))) : QString();
}

inline int lineAt(const QString& text, qsizetype at)
{
    return int(QStringView(text).left(at).count(u'\n')) + 1;
}

} // namespace Detail

/// Every function body of `text` (a .cpp or .h), with its length in lines.
inline Scan scan(const QString& text)
{
    using namespace Detail;
    const QString s = code(text);
    Scan out;
    qsizetype headStart = 0;
    int open = 0; // namespaces and classes
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s[i];
        if (c == u';') {
            headStart = i + 1;
        } else if (c == u'}') {
            if (--open < 0) {
                out.error = QStringLiteral("line %1: a } that closes nothing").arg(lineAt(s, i));
                return out;
            }
            headStart = i + 1;
        } else if (c == u'{') {
            const QString head = s.mid(headStart, i - headStart);
            const qsizetype from = declarationStart(head);
            qsizetype before = std::max<qsizetype>(i - 1, 0);
            while (before > headStart && s[before].isSpace())
                --before;
            const Kind kind = classify(head.mid(from), s[before]);
            if (kind == Kind::Scope) {
                ++open;
                headStart = i + 1;
                continue;
            }
            const qsizetype end = closing(s, i);
            if (end < 0) {
                out.error = QStringLiteral("line %1: a { that does not close").arg(lineAt(s, i));
                return out;
            }
            if (kind == Kind::Function) {
                qsizetype first = headStart + from;
                while (first < i && s[first].isSpace())
                    ++first;
                const int line = lineAt(s, first);
                out.functions << Function {nameOf(head.mid(from)), line, lineAt(s, end) - line + 1};
            }
            if (kind != Kind::InInitializers)
                headStart = end + 1;
            i = end;
        }
    }
    if (open != 0)
        out.error = QStringLiteral("%1 namespaces or classes do not close").arg(open);
    return out;
}

} // namespace FunctionLengths
