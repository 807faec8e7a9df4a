// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <string>

/// UTF-8 as it is. QString::fromUtf8 drops a byte-order mark at the start, so a topic or value
/// that begins with one ("\ufeffa") would be shown, compared and written back as another ("a").
/// Invalid sequences still become U+FFFD, as with fromUtf8.
inline QString exactUtf8(const char* data, qsizetype size)
{
    qsizetype boms = 0;
    while (size - boms * 3 >= 3 && data[boms * 3] == '\xef' && data[boms * 3 + 1] == '\xbb'
           && data[boms * 3 + 2] == '\xbf')
        ++boms;
    if (boms == 0)
        return QString::fromUtf8(data, size);
    return QString(boms, QChar(0xfeff)) + QString::fromUtf8(data + boms * 3, size - boms * 3);
}

inline QString exactUtf8(const std::string& s)
{
    return exactUtf8(s.data(), qsizetype(s.size()));
}
