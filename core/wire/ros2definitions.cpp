// SPDX-License-Identifier: MIT
#include "wire/ros2definitions.h"

#include "files/regularfile.h"

#include <QDirIterator>
#include <QFile>
#include <QFileInfo>

namespace Ros2Definitions {

QString typeOfPath(const QString& path)
{
    const QStringList parts = QDir::fromNativeSeparators(path).split(QLatin1Char('/'));
    if (parts.size() < 3 || parts.at(parts.size() - 2) != QLatin1String("msg")
        || !parts.last().endsWith(QLatin1String(".msg")) || parts.last().size() <= 4)
        return {};
    const QString package = parts.at(parts.size() - 3);
    if (package.isEmpty())
        return {};
    return package + QLatin1String("/msg/") + parts.last().chopped(4);
}

int addFolder(RosTypeRegistry& registry, const QString& folder, QStringList* errors)
{
    int added = 0;
    int files = 0;
    // no symbolic links followed: a link loop cannot keep us here
    QDirIterator it(folder, {QStringLiteral("*.msg")}, QDir::Files | QDir::Readable,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        const QString type = typeOfPath(path);
        if (type.isEmpty())
            continue;
        if (++files > kMaxFiles) {
            if (errors)
                errors->append(QCoreApplication::translate(
                                   "Ros2Definitions", "%1: more than %2 definitions; the rest were not read")
                                   .arg(folder)
                                   .arg(kMaxFiles));
            break;
        }
        const Result<QByteArray> text = RegularFile::read(path, kMaxFileBytes);
        if (!text) {
            if (errors)
                errors->append(
                    QCoreApplication::translate("Ros2Definitions", "%1: not readable or over %2 KiB")
                        .arg(path)
                        .arg(kMaxFileBytes / 1024));
            continue;
        }
        if (const Result<void> read = registry.addDefinition(type, QString::fromUtf8(*text)); read)
            ++added;
        else if (errors)
            errors->append(QStringLiteral("%1: %2").arg(path, read.error().toString()));
    }
    return added;
}

RosTypeRegistry registry(const QStringList& folders, QStringList* errors)
{
    RosTypeRegistry r(RosTypeRegistry::Dialect::Ros2);
    addFolder(r, QStringLiteral(":/ros2"), errors);
    for (const QString& folder : folders)
        addFolder(r, folder, errors);
    return r;
}

} // namespace Ros2Definitions
