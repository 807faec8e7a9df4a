// SPDX-License-Identifier: MIT
#pragma once

// What the tests read back from an exported file: that it is what its format says, whole, and
// holds what it should. Each returns what is wrong, or an empty string.
#include <QFile>
#include <QString>
#include <QXmlStreamReader>

namespace ExportCheck {

/// An SVG document: well-formed, <svg> its root, at least `minElements` elements, and `text`
/// among its texts (when given).
inline QString svgProblem(const QString& path, int minElements = 10, const QString& text = {})
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return path + QStringLiteral(": cannot be read");
    QXmlStreamReader xml(&file);
    int elements = 0;
    bool isSvg = false;
    bool hasText = text.isEmpty();
    while (!xml.atEnd()) {
        const QXmlStreamReader::TokenType token = xml.readNext();
        if (token == QXmlStreamReader::StartElement && elements++ == 0)
            isSvg = xml.name() == QStringLiteral("svg");
        else if (token == QXmlStreamReader::Characters && !hasText)
            hasText = xml.text().contains(text);
    }
    if (xml.hasError())
        return path + QStringLiteral(": ") + xml.errorString();
    if (!isSvg || elements < minElements)
        return QStringLiteral("%1: %2 elements, %3")
            .arg(path)
            .arg(elements)
            .arg(isSvg ? QStringLiteral("svg") : QStringLiteral("not svg"));
    if (!hasText)
        return QStringLiteral("%1: no text '%2'").arg(path, text);
    return {};
}

/// A PDF document: its header, its end-of-file mark, and more than a kilobyte between.
inline QString pdfProblem(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return path + QStringLiteral(": cannot be read");
    const QByteArray bytes = file.readAll();
    if (!bytes.startsWith("%PDF-") || !bytes.right(32).contains("%%EOF") || bytes.size() < 1024)
        return QStringLiteral("%1: %2 bytes, not a whole PDF").arg(path).arg(bytes.size());
    return {};
}

} // namespace ExportCheck
