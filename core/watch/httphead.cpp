// SPDX-License-Identifier: MIT
#include "httphead.h"

#include <QList>

namespace {
/// The end of the head: the first empty line after the request line (CRLF or bare LF line ends);
/// -1 when it has not come. `*start` is where the request line begins (leading empty lines skipped).
qsizetype headEnd(const QByteArray& bytes, qsizetype* start)
{
    qsizetype lineStart = 0;
    bool seenRequestLine = false;
    *start = 0;
    while (lineStart < bytes.size()) {
        const qsizetype lf = bytes.indexOf('\n', lineStart);
        if (lf < 0)
            return -1;
        const bool empty = lf == lineStart || (lf == lineStart + 1 && bytes[lineStart] == '\r');
        if (empty && seenRequestLine)
            return lineStart;
        if (!empty && !seenRequestLine) {
            seenRequestLine = true;
            *start = lineStart;
        }
        lineStart = lf + 1;
    }
    return -1;
}

/// The path of a request target: origin form as it is, an absolute URI without scheme and authority.
QByteArray pathOf(QByteArray target)
{
    if (const qsizetype cut = target.indexOf('#'); cut >= 0)
        target.truncate(cut);
    if (const qsizetype cut = target.indexOf('?'); cut >= 0)
        target.truncate(cut);
    const QByteArray lower = target.left(8).toLower();
    const qsizetype scheme = lower.startsWith("http://") ? 7 : lower.startsWith("https://") ? 8 : -1;
    if (scheme < 0)
        return target;
    const qsizetype slash = target.indexOf('/', scheme);
    return slash < 0 ? QByteArray("/") : target.mid(slash);
}
} // namespace

HttpHead::Status HttpHead::parse(const QByteArray& input, qsizetype maxBytes, Request* request)
{
    const QByteArray bytes = QByteArray::fromRawData(input.constData(), std::min(input.size(), maxBytes));
    qsizetype start = 0;
    const qsizetype end = headEnd(bytes, &start);
    if (end < 0)
        return input.size() > maxBytes ? Status::TooLarge : Status::Incomplete;
    const QList<QByteArray> lines = bytes.mid(start, end - start).split('\n');
    const QList<QByteArray> parts = lines.front().trimmed().split(' ');
    if (parts.size() != 3 || parts[0].isEmpty() || parts[1].isEmpty() || !parts[2].startsWith("HTTP/1."))
        return Status::Malformed;
    *request = {};
    request->method = parts[0];
    request->path = pathOf(parts[1]);
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QByteArray line = lines[i].trimmed();
        if (line.size() > 7 && qstrnicmp(line.constData(), "accept:", 7) == 0)
            request->accept = line.mid(7).trimmed();
    }
    return Status::Complete;
}
