// SPDX-License-Identifier: MIT
#include "problem.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

QString Problem::severityName(Severity s)
{
    switch (s) {
    case Severity::Info:
        return u"note"_s;
    case Severity::Warning:
        return u"warning"_s;
    case Severity::Error:
        return u"error"_s;
    }
    return QString();
}

QString Problem::format(const QString& fileName) const
{
    // A place only where there is one: a file too large has no line to point at.
    QString text = fileName;
    if (pos.isValid())
        text += u':' + QString::number(pos.line + 1) + u':' + QString::number(pos.column + 1);
    text += u": "_s + severityName(severity) + u": "_s + message;
    if (!fix.isEmpty())
        text += u" ("_s + fix + u')';
    return text;
}

bool hasErrors(const QList<Problem>& problems)
{
    for (const Problem& p : problems) {
        if (p.severity == Severity::Error)
            return true;
    }
    return false;
}
