// SPDX-License-Identifier: MIT
#include "regularfile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <sys/stat.h>
#include <unistd.h>

using namespace Qt::StringLiterals;

std::atomic<bool> RegularFile::s_stop {false};

namespace {
QString kindOf(mode_t mode)
{
    if (S_ISFIFO(mode))
        return RegularFile::tr("a FIFO (named pipe)");
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return RegularFile::tr("a device");
    if (S_ISSOCK(mode))
        return RegularFile::tr("a socket");
    if (S_ISDIR(mode))
        return RegularFile::tr("a folder");
    return RegularFile::tr("not a regular file");
}

QString sizeText(qint64 bytes)
{
    if (bytes >= 1024 * 1024)
        return RegularFile::tr("%1 MiB").arg(double(bytes) / (1024 * 1024), 0, 'f', 1);
    return RegularFile::tr("%1 bytes").arg(bytes);
}
} // namespace

QString RegularFile::notAFile(const QString& path)
{
    if (path.startsWith(u':'))
        return {}; // a Qt resource
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0 || S_ISREG(st.st_mode))
        return {};
    return kindOf(st.st_mode);
}

Result<RegularFile::Opened> RegularFile::open(const QString& path, qint64 maxBytes)
{
    if (path.startsWith(u':')) { // a Qt resource: compiled into the program, in memory, not hostile
        Opened opened;
        opened.file = std::make_unique<QFile>(path);
        if (!opened.file->open(QIODevice::ReadOnly))
            return LocatedError {opened.file->errorString()};
        opened.size = opened.file->size();
        if (opened.size > maxBytes)
            return LocatedError {tr("%1, more than the %2 such a file may have: refused")
                                     .arg(sizeText(opened.size), sizeText(maxBytes))};
        return opened;
    }
    // O_NONBLOCK: opening a FIFO for reading would wait for a writer; a regular file ignores it.
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0)
        return LocatedError {QString::fromLocal8Bit(std::strerror(errno))};
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int e = errno;
        ::close(fd);
        return LocatedError {QString::fromLocal8Bit(std::strerror(e))};
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        return LocatedError {tr("%1, not a file: refused").arg(kindOf(st.st_mode))};
    }
    if (st.st_size > maxBytes) {
        ::close(fd);
        return LocatedError {tr("%1, more than the %2 such a file may have: refused")
                                 .arg(sizeText(st.st_size), sizeText(maxBytes))};
    }
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0)
        ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    Opened opened;
    opened.file = std::make_unique<QFile>();
    opened.size = st.st_size;
    if (!opened.file->open(fd, QIODevice::ReadOnly, QFileDevice::AutoCloseHandle)) {
        ::close(fd);
        return LocatedError {opened.file->errorString()};
    }
    return opened;
}

Result<QByteArray> RegularFile::read(const QString& path, qint64 maxBytes)
{
    return readHead(path, maxBytes, true);
}

Result<QByteArray> RegularFile::readHead(const QString& path, qint64 count)
{
    return readHead(path, count, false);
}

Result<QByteArray> RegularFile::readHead(const QString& path, qint64 count, bool whole)
{
    Result<Opened> f = open(path, whole ? count : std::numeric_limits<qint64>::max());
    if (!f)
        return f.error();
    QByteArray bytes = f->file->read(std::min(count, f->size)); // never more than its size at the check
    if (f->file->error() != QFileDevice::NoError)
        return LocatedError {f->file->errorString()};
    return bytes;
}
