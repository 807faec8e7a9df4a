// SPDX-License-Identifier: MIT
#include "helperprogram.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QStringList>

using namespace Qt::StringLiterals;

QString findHelperProgram(const QString& name, const char* envVar, const QString& buildPath)
{
    QStringList candidates;
    if (qEnvironmentVariableIsSet(envVar))
        candidates << qEnvironmentVariable(envVar);
    if (QCoreApplication::instance()) {
        const QString dir = QCoreApplication::applicationDirPath();
        candidates << dir + u'/' + name << dir + u"/../libexec/bridgescope/"_s + name;
    }
    if (!buildPath.isEmpty())
        candidates << buildPath;
    for (const QString& c : std::as_const(candidates))
        if (QFileInfo(c).isExecutable() && QFileInfo(c).isFile())
            return c;
    return {};
}
