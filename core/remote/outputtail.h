// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

/// The last lines of a child's output, bounded however much it writes: at most `maxLines` lines of
/// at most `maxLineLength` characters each (longer ones cut, marked with "…"), and a partial line
/// of at most that length waiting for its end.
class OutputTail
{
public:
    explicit OutputTail(int maxLines = 40, int maxLineLength = 400)
        : m_maxLines(maxLines)
        , m_maxLineLength(maxLineLength)
    { }

    /// Adds bytes; returns the lines they completed (each already cut to the bound).
    QStringList append(const QByteArray& bytes)
    {
        QStringList complete;
        for (char c : bytes) {
            if (c == '\n') {
                complete << finishLine();
                continue;
            }
            if (m_partial.size() <= m_maxLineLength)
                m_partial.append(c);
        }
        return complete;
    }
    /// Ends a last line without its newline (at the end of the output).
    void flush()
    {
        if (!m_partial.isEmpty())
            finishLine();
    }
    QStringList lines() const { return m_lines; }

private:
    QString finishLine()
    {
        QString line = QString::fromLocal8Bit(m_partial.left(m_maxLineLength));
        if (m_partial.size() > m_maxLineLength)
            line += QStringLiteral("…");
        m_partial.clear();
        m_lines << line;
        while (m_lines.size() > m_maxLines)
            m_lines.removeFirst();
        return line;
    }

    int m_maxLines;
    int m_maxLineLength;
    QByteArray m_partial;
    QStringList m_lines;
};
