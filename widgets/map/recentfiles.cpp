// SPDX-License-Identifier: MIT
#include "recentfiles.h"

#include <QSettings>

namespace {
const auto kRecentKey = "recentConfigFiles"; // configs were the first kind it held
} // namespace

RecentFiles::RecentFiles(QObject* parent)
    : QObject(parent)
{
}

QStringList RecentFiles::files() const
{
    return QSettings().value(QLatin1String(kRecentKey)).toStringList();
}

void RecentFiles::add(const QString& path)
{
    QStringList list = files();
    list.removeAll(path);
    list.prepend(path);
    while (list.size() > kMax)
        list.removeLast();
    QSettings().setValue(QLatin1String(kRecentKey), list);
    emit changed(list);
}
