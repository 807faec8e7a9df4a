// SPDX-License-Identifier: MIT
#include "atomicfile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <QCoreApplication>
#include <QFileInfo>
#include <sys/stat.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

namespace {

QString errnoText()
{
    return qt_error_string(errno);
}

bool writeAll(int fd, const QByteArray& data)
{
    qsizetype done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.constData() + done, size_t(data.size() - done));
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        done += n;
    }
    return true;
}

// Writes a complete, synced copy of `data` to a fresh temporary file in `dir`.
Result<QByteArray> writeTemp(const QString& dir, const QString& base, const QByteArray& data, mode_t mode)
{
    QByteArray tmpl = QFile::encodeName(dir + u"/."_s + base + u".XXXXXX"_s);
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0)
        return LocatedError {
            AtomicFile::tr("cannot create a temporary file in %1: %2").arg(dir, errnoText())};
    QString why;
    bool ok = writeAll(fd, data) && ::fchmod(fd, mode) == 0 && ::fsync(fd) == 0;
    if (!ok)
        why = AtomicFile::tr("cannot write %1: %2").arg(QFile::decodeName(tmpl), errnoText());
    if (::close(fd) != 0 && ok) {
        why = AtomicFile::tr("cannot write %1: %2").arg(QFile::decodeName(tmpl), errnoText());
        ok = false;
    }
    if (!ok) {
        ::unlink(tmpl.constData());
        return LocatedError {why};
    }
    return tmpl;
}

void syncDirectory(const QString& dir)
{
    const int fd = ::open(QFile::encodeName(dir).constData(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

// The file a path names: symbolic links followed (a bounded number of them), the last one may not
// exist yet.
QString resolvedTarget(const QString& path)
{
    QString p = QFileInfo(path).absoluteFilePath();
    for (int i = 0; i < 40; ++i) {
        const QFileInfo info(p);
        if (!info.isSymLink())
            break;
        p = info.symLinkTarget();
    }
    return p;
}

QString kindName(mode_t mode)
{
    if (S_ISFIFO(mode))
        return AtomicFile::tr("a FIFO (named pipe)");
    if (S_ISCHR(mode))
        return AtomicFile::tr("a character device");
    if (S_ISBLK(mode))
        return AtomicFile::tr("a block device");
    if (S_ISDIR(mode))
        return AtomicFile::tr("a directory");
    if (S_ISSOCK(mode))
        return AtomicFile::tr("a socket");
    if (S_ISLNK(mode))
        return AtomicFile::tr("a symbolic link that leads nowhere (a loop)");
    return AtomicFile::tr("not a regular file");
}

QString refusal(const QString& path, const QByteArray& target)
{
    struct stat st
    {
    };
    if (::lstat(target.constData(), &st) != 0) {
        if (errno == ENOENT)
            return QString();
        return AtomicFile::tr("cannot examine %1: %2").arg(path, errnoText());
    }
    if (!S_ISREG(st.st_mode))
        return AtomicFile::tr("%1 is %2, not a regular file; only regular files are written over")
            .arg(path, kindName(st.st_mode));
    // Renaming over a file ignores its permissions; a file nobody may write stays as it is. The
    // mode bits count for root too, who passes access().
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(target.constData(), W_OK) != 0)
        return AtomicFile::tr("%1 is read-only; make it writable or choose another name").arg(path);
    return QString();
}

} // namespace

QString AtomicFile::backupPath(const QString& path, int n)
{
    if (n == 0)
        return path + u".bak"_s;
    return path + u".bak."_s + QString::number(n);
}

QString AtomicFile::refusalReason(const QString& path)
{
    return refusal(path, QFile::encodeName(resolvedTarget(path)));
}

Status AtomicFile::write(const QString& path, const QByteArray& data, bool keepBackup)
{
    // Write through a symbolic link to the file it names, keeping the link.
    const QFileInfo info(resolvedTarget(path));
    const QString dir = info.absolutePath();
    const QString targetName = info.absoluteFilePath();
    const QByteArray target = QFile::encodeName(targetName);
    if (const QString why = refusal(path, target); !why.isEmpty())
        return LocatedError {why};

    mode_t mode = 0644;
    struct stat st
    {
    };
    const bool exists = ::stat(target.constData(), &st) == 0;
    if (exists) {
        mode = st.st_mode & 07777;
    } else {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        mode = 0666 & ~mask;
    }

    const Result<QByteArray> written = writeTemp(dir, info.fileName(), data, mode);
    if (!written)
        return written.error();
    const QByteArray tmp = *written;

    if (keepBackup && exists) {
        // The previous file becomes the backup by a hard link, so it is never copied half-way;
        // where links are not possible, a synced copy is made instead.
        const QByteArray bak = QFile::encodeName(backupPath(targetName, 0));
        QByteArray bakTmp = tmp + ".bak";
        QString copyError; // why the copy could not be written, when it could not
        bool ok = ::link(target.constData(), bakTmp.constData()) == 0;
        if (!ok) {
            QFile old(targetName);
            if (old.open(QIODevice::ReadOnly)) {
                const Result<QByteArray> copy
                    = writeTemp(dir, info.fileName() + u".bak"_s, old.readAll(), mode);
                ok = copy.ok();
                bakTmp = copy.valueOr(QByteArray());
                copyError = copy.error().message;
            }
        }
        // Older backups move one place down (.bak -> .bak.1 -> .bak.2 ...); the oldest is dropped.
        for (int n = maxBackups - 1; ok && n > 0; --n) {
            const QByteArray from = QFile::encodeName(backupPath(targetName, n - 1));
            const QByteArray to = QFile::encodeName(backupPath(targetName, n));
            if (::rename(from.constData(), to.constData()) != 0 && errno != ENOENT) {
                const LocatedError error {AtomicFile::tr("cannot keep the previous file as %1: %2")
                                              .arg(QFile::decodeName(to), errnoText())};
                ::unlink(bakTmp.constData());
                ::unlink(tmp.constData());
                return error;
            }
        }
        if (!ok || ::rename(bakTmp.constData(), bak.constData()) != 0) {
            const LocatedError error {
                ok ? AtomicFile::tr("cannot keep the previous file as %1: %2")
                         .arg(QFile::decodeName(bak), errnoText())
                    : !copyError.isEmpty()
                    ? copyError
                    : AtomicFile::tr("cannot keep the previous file as %1").arg(QFile::decodeName(bak))};
            ::unlink(bakTmp.constData());
            ::unlink(tmp.constData());
            return error;
        }
    }

    if (::rename(tmp.constData(), target.constData()) != 0) {
        const LocatedError error {AtomicFile::tr("cannot replace %1: %2").arg(path, errnoText())};
        ::unlink(tmp.constData());
        return error;
    }
    syncDirectory(dir);
    return {};
}
