// SPDX-License-Identifier: MIT
#include "secrets.h"

#include <QList>
#include <QRegularExpression>
#include <QUrl>

using namespace Qt::StringLiterals;

namespace Secrets {
namespace {
qsizetype indentOf(const QString& line)
{
    qsizetype n = 0;
    while (n < line.size() && line[n].isSpace())
        ++n;
    return n;
}
} // namespace

QString urlWithoutCredentials(const QString& url)
{
    const qsizetype scheme = url.indexOf(u"://"_s);
    if (scheme < 0)
        return url;
    // The authority ends at the first '/', '?' or '#' after the scheme; its last '@' ends the user
    // info. Done by hand: QUrl rejects some URLs that a user still types and expects to work.
    const qsizetype start = scheme + 3;
    qsizetype end = url.size();
    for (const QChar c : {u'/', u'?', u'#'}) {
        const qsizetype i = url.indexOf(c, start);
        if (i >= 0 && i < end)
            end = i;
    }
    const qsizetype at = url.lastIndexOf(u'@', end - 1);
    if (at < start)
        return url;
    return url.left(start) + url.mid(at + 1);
}

QByteArray redactYaml(const QByteArray& yaml, bool* changed)
{
    // A key that names a secret, as a whole word: "pass", "password", "key_password",
    // "passphrase", "secret", "client_secret", "token", "api_key" (not "passive", "bypass_x").
    static const QRegularExpression key(
        u"(?<![A-Za-z0-9])((?:[A-Za-z0-9]+_)*(?:pass|passwd|password|passphrase|secret|token|api_key))"
        u"([\"']?)(\\s*:[ \\t]*)"_s,
        QRegularExpression::CaseInsensitiveOption);
    bool any = false;
    QList<QByteArray> lines = yaml.split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        QString line = QString::fromUtf8(lines[i]);
        const QString trimmed = line.trimmed();
        if (trimmed.startsWith(u'#'))
            continue;
        bool lineChanged = false;
        qsizetype from = 0;
        QRegularExpressionMatch m;
        while ((m = key.match(line, from)).hasMatch()) {
            const qsizetype valueStart = m.capturedEnd();
            // The value runs to a ',' or '}' in flow style (inside braces), else to a comment or the end.
            const bool flow
                = line.left(m.capturedStart()).count(u'{') > line.left(m.capturedStart()).count(u'}');
            qsizetype valueEnd = line.size();
            const QChar quote = valueStart < line.size() ? line[valueStart] : QChar();
            if (quote == u'"' || quote == u'\'') {
                qsizetype close = valueStart + 1;
                while (close < line.size()) {
                    if (line[close] == quote && !(quote == u'"' && line[close - 1] == u'\\'))
                        break;
                    ++close;
                }
                valueEnd = qMin(close + 1, line.size());
            } else {
                for (qsizetype j = valueStart; j < line.size(); ++j) {
                    if ((flow && (line[j] == u',' || line[j] == u'}'))
                        || (line[j] == u'#' && j > 0 && line[j - 1].isSpace())) {
                        valueEnd = j;
                        break;
                    }
                }
                while (valueEnd > valueStart && line[valueEnd - 1].isSpace())
                    --valueEnd;
            }
            const QString value = line.mid(valueStart, valueEnd - valueStart);
            const QString plain = value.trimmed();
            if (plain.isEmpty() || plain == u"\"\""_s || plain == u"''"_s || plain == u"~"_s
                || plain == u"null"_s || plain.startsWith(u'{') || plain.startsWith(u'[')) {
                from = valueEnd > m.capturedEnd() ? valueEnd : m.capturedEnd();
                if (plain.isEmpty() && !flow) {
                    // A nested map or a value on the following, more indented lines.
                    const qsizetype indent = indentOf(line);
                    qsizetype j = i + 1;
                    while (j < lines.size()) {
                        const QString next = QString::fromUtf8(lines[j]);
                        const qsizetype nextIndent = indentOf(next);
                        if (next.trimmed().isEmpty() || nextIndent <= indent)
                            break;
                        // Only a scalar continuation is a secret; a nested map is walked line by line.
                        if (next.trimmed().contains(u": "_s) || next.trimmed().endsWith(u':'))
                            break;
                        lines[j] = QByteArray(nextIndent, ' ') + Secrets::kRedacted;
                        any = true;
                        ++j;
                    }
                }
                continue;
            }
            if (plain.startsWith(u'|') || plain.startsWith(u'>')) {
                // A block scalar: its lines are the more indented ones that follow.
                const qsizetype indent = indentOf(line);
                qsizetype j = i + 1;
                while (j < lines.size()) {
                    const QString next = QString::fromUtf8(lines[j]);
                    const qsizetype nextIndent = indentOf(next);
                    if (!next.trimmed().isEmpty() && nextIndent <= indent)
                        break;
                    if (!next.trimmed().isEmpty())
                        lines[j] = QByteArray(nextIndent, ' ') + Secrets::kRedacted;
                    ++j;
                }
                any = true;
                from = valueEnd;
                continue;
            }
            if (plain.startsWith(u'*') || plain.startsWith(u"$(arg"_s)) {
                // An alias (its anchor is redacted where it is defined) or a launch argument.
                from = valueEnd;
                continue;
            }
            qsizetype replaceFrom = valueStart;
            if (plain.startsWith(u'&')) {
                // Keep the anchor: aliases elsewhere in the file still resolve.
                const qsizetype space = line.indexOf(u' ', valueStart);
                if (space < 0 || space >= valueEnd) {
                    from = valueEnd;
                    continue;
                }
                replaceFrom = space + 1;
            }
            const QString replacement = u"\"%1\""_s.arg(QLatin1StringView(Secrets::kRedacted));
            line.replace(replaceFrom, valueEnd - replaceFrom, replacement);
            from = replaceFrom + replacement.size();
            lineChanged = true;
        }
        if (lineChanged) {
            lines[i] = line.toUtf8();
            any = true;
        }
    }
    if (changed)
        *changed = any;
    return any ? lines.join('\n') : yaml;
}

} // namespace Secrets
