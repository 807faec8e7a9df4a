// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <atomic>
#include <memory>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QString>

/// Opening a file as data (issue 41): only a regular file, after symbolic links are followed, and
/// never more of it than its size when it was opened. A FIFO, a device (/dev/zero), a socket or a
/// directory is refused with a clear error instead of blocking in open() or being read without end.
///
/// The file is opened with O_NONBLOCK and checked with fstat() on the descriptor that is read, so
/// that neither a FIFO's open() nor a file swapped between the check and the open (TOCTOU) can
/// block or deceive the reader.
class RegularFile
{
    Q_DECLARE_TR_FUNCTIONS(RegularFile)
public:
    /// An open regular file: read at most `size` bytes of it.
    struct Opened
    {
        std::unique_ptr<QFile> file;
        qint64 size = 0; ///< its size when it was opened (fstat): what a reader may read
    };

    /// Opens `path` for reading when it is a regular file of at most `maxBytes` bytes; otherwise
    /// an error without the path ("a FIFO (named pipe), not a file: refused", "3.0 MiB, more than
    /// the 1 MiB such a file may have: refused", or the system's reason).
    static Result<Opened> open(const QString& path, qint64 maxBytes);
    /// The bytes of the regular file `path`, at most `maxBytes` (a bigger file is refused, not cut).
    static Result<QByteArray> read(const QString& path, qint64 maxBytes);
    /// The first `count` bytes of the regular file `path`, whatever its size (for a reader that
    /// says itself that a file is too large, given one byte past its limit).
    static Result<QByteArray> readHead(const QString& path, qint64 count);
    /// readHead() without an error: empty when `path` is no regular file (for telling kinds of
    /// files apart by their first bytes).
    static QByteArray head(const QString& path, qint64 count)
    {
        return readHead(path, count).valueOr(QByteArray());
    }
    /// What `path` is when it is not a regular file ("a FIFO", "a device", ...), empty when it is one
    /// (or when it does not exist: open() says so).
    static QString notAFile(const QString& path);

    /// Set by a signal handler (SIGINT, SIGTERM) or another thread: every long read checks it and
    /// stops ("cancelled"). Async-signal-safe.
    static void requestStop() { s_stop.store(true, std::memory_order_relaxed); }
    static bool stopRequested() { return s_stop.load(std::memory_order_relaxed); }

private:
    static Result<QByteArray> readHead(const QString& path, qint64 count, bool whole);
    static std::atomic<bool> s_stop;
    static_assert(std::atomic<bool>::is_always_lock_free);
};
