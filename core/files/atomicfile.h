// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// Writes files so that a reader sees either the old or the new content, never half of one.
class AtomicFile
{
    Q_DECLARE_TR_FUNCTIONS(AtomicFile)
public:
    /// How many previous versions a save keeps: `path`.bak (the newest), then .bak.1 ... .bak.9.
    static constexpr int maxBackups = 10;

    /// Writes `data` to a temporary file beside `path`, syncs it to disk and renames it over `path`.
    /// A symbolic link is written through to the file it names. Anything at `path` that is not a
    /// regular file (a FIFO, a device, a directory) and a read-only file are refused, never
    /// replaced. With `keepBackup`, the previous file becomes `path`.bak and older backups move to
    /// .bak.1, .bak.2, ... (see maxBackups). Permissions of an existing file are kept. Every write,
    /// sync and close is checked (a full disk is an error). On failure nothing at `path` has
    /// changed and the error says why.
    static Status write(const QString& path, const QByteArray& data, bool keepBackup = true);
    /// The name of backup `n` of `path`: 0 is `path`.bak, n > 0 is `path`.bak.n.
    static QString backupPath(const QString& path, int n);
    /// Why `path` must not be written over (not a regular file, read-only), or empty when it may be
    /// (also when it does not exist). For writers that cannot go through write().
    static QString refusalReason(const QString& path);
};
