// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// Writes files so that a reader sees either the old or the new content, never half of one.
class AtomicFile
{
    Q_DECLARE_TR_FUNCTIONS(AtomicFile)
public:
    /// Writes `data` to a temporary file beside `path`, syncs it to disk and renames it over `path`.
    /// With `keepBackup`, the previous file stays as `path` + ".bak". Permissions of an existing file
    /// are kept. On failure nothing at `path` has changed and `error` says why.
    static bool write(const QString& path, const QByteArray& data, QString* error, bool keepBackup = true);
};
