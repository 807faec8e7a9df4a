// SPDX-License-Identifier: MIT
#include "payloadtext.h"

#include <QJsonDocument>
#include <QLocale>
#include <QStringDecoder>

using namespace Qt::StringLiterals;

bool PayloadText::isText(const QByteArray& payload)
{
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString s = utf8(payload.left(4096));
    if (utf8.hasError())
        return false;
    for (QChar c : s) {
        if (c.unicode() < 0x20 && c != u'\n' && c != u'\r' && c != u'\t')
            return false;
    }
    return true;
}

QString PayloadText::hexDump(const QByteArray& bytes)
{
    QString out;
    out.reserve(bytes.size() * 4);
    for (qsizetype row = 0; row < bytes.size(); row += 16) {
        out += QString::number(row, 16).rightJustified(8, u'0') + u"  "_s;
        QString ascii;
        for (qsizetype i = row; i < row + 16; ++i) {
            if (i < bytes.size()) {
                const uchar c = uchar(bytes[i]);
                out += QString::number(c, 16).rightJustified(2, u'0') + u' ';
                ascii += c >= 0x20 && c < 0x7f ? QChar(char16_t(c)) : u'.';
            } else {
                out += u"   "_s;
            }
            if (i == row + 7)
                out += u' ';
        }
        out += u' ' + ascii + u'\n';
    }
    return out;
}

PayloadText::Rendered PayloadText::render(const QByteArray& payload, Mode mode, qsizetype limitBytes)
{
    Rendered r;
    const QString size
        = QLocale::system().formattedDataSize(payload.size(), 1, QLocale::DataSizeTraditionalFormat);
    const bool cut = payload.size() > limitBytes;
    const QByteArray shown = cut ? payload.left(limitBytes) : payload;
    if (mode == Mode::Auto) {
        if (!cut && !payload.isEmpty() && (payload.front() == '{' || payload.front() == '[')
            && !QJsonDocument::fromJson(payload).isNull())
            mode = Mode::Json;
        else
            mode = isText(shown) ? Mode::Text : Mode::Hex;
    }
    r.mode = mode;
    switch (mode) {
    case Mode::Json: {
        if (cut) {
            // Parsing and indenting 50 MB for a view that shows 64 kB is work without a bound.
            r.text = QString::fromUtf8(shown);
            r.note = tr("%1; too large to show as JSON, showing the first %2 as text")
                         .arg(size,
                              QLocale::system().formattedDataSize(limitBytes, 0,
                                                                  QLocale::DataSizeTraditionalFormat));
            return r;
        }
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(payload, &error);
        if (doc.isNull()) {
            r.text = QString::fromUtf8(shown);
            r.note = tr("%1; not JSON: %2 at byte %3").arg(size, error.errorString()).arg(error.offset);
            return r;
        }
        r.text = QString::fromUtf8(doc.toJson(QJsonDocument::Indented));
        if (r.text.size() > 4 * limitBytes) {
            // Deep nesting indents quadratically: 64 kB of brackets become megabytes.
            r.text.truncate(4 * limitBytes);
            r.note = tr("%1; indented view cut at %2 characters").arg(size).arg(4 * limitBytes);
            return r;
        }
        break;
    }
    case Mode::Hex:
        r.text = hexDump(shown);
        break;
    case Mode::Text:
    case Mode::Auto:
        r.text = QString::fromUtf8(shown);
        break;
    }
    r.note = cut
        ? tr("%1; showing the first %2")
              .arg(size,
                   QLocale::system().formattedDataSize(limitBytes, 0, QLocale::DataSizeTraditionalFormat))
        : size;
    return r;
}
