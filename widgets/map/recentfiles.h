// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

/// The files of any kind opened or saved last (File › Open Recent), newest first, kept in the
/// settings between sessions.
class RecentFiles : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMax = 10;

    explicit RecentFiles(QObject* parent = nullptr);

    QStringList files() const;
    /// Puts `path` first (once), keeping the newest kMax.
    void add(const QString& path);

signals:
    void changed(const QStringList& files);
};
