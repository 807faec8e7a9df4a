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

bool sameProblems(const QList<Problem>& a, const QList<Problem>& b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i)
        if (a[i].severity != b[i].severity || a[i].code != b[i].code || a[i].mappingId != b[i].mappingId
            || a[i].message != b[i].message || a[i].fix != b[i].fix)
            return false;
    return true;
}

Problem Problem::about(const Mapping* m, Severity severity, const QString& code, const QString& field,
                       const QString& message, const QString& fix)
{
    Problem p;
    p.severity = severity;
    p.code = code;
    p.message = message;
    p.fix = fix;
    p.field = field;
    if (m) {
        p.mappingId = m->id;
        p.scope = m->scope();
        p.pos = m->block.source.keyPos(field);
    }
    return p;
}
