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
QByteArray writeTemp(const QString& dir, const QString& base, const QByteArray& data, mode_t mode,
                     QString* error)
{
    QByteArray tmpl = QFile::encodeName(dir + u"/."_s + base + u".XXXXXX"_s);
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) {
        *error = AtomicFile::tr("cannot create a temporary file in %1: %2").arg(dir, errnoText());
        return QByteArray();
    }
    bool ok = writeAll(fd, data) && ::fchmod(fd, mode) == 0 && ::fsync(fd) == 0;
    if (!ok)
        *error = AtomicFile::tr("cannot write %1: %2").arg(QFile::decodeName(tmpl), errnoText());
    if (::close(fd) != 0 && ok) {
        *error = AtomicFile::tr("cannot write %1: %2").arg(QFile::decodeName(tmpl), errnoText());
        ok = false;
    }
    if (!ok) {
        ::unlink(tmpl.constData());
        return QByteArray();
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

} // namespace

bool AtomicFile::write(const QString& path, const QByteArray& data, QString* error, bool keepBackup)
{
    QString ignored;
    if (!error)
        error = &ignored;
    // Write through a symbolic link to the file it names, keeping the link.
    const QFileInfo link(path);
    const QFileInfo info(link.isSymLink() ? link.symLinkTarget() : path);
    const QString dir = info.absolutePath();
    const QByteArray target = QFile::encodeName(info.absoluteFilePath());

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

    const QByteArray tmp = writeTemp(dir, info.fileName(), data, mode, error);
    if (tmp.isEmpty())
        return false;

    if (keepBackup && exists) {
        // The previous file becomes the backup by a hard link, so it is never copied half-way;
        // where links are not possible, a synced copy is made instead.
        const QByteArray bak = target + ".bak";
        QByteArray bakTmp = tmp + ".bak";
        bool ok = ::link(target.constData(), bakTmp.constData()) == 0;
        if (!ok) {
            QFile old(path);
            if (old.open(QIODevice::ReadOnly)) {
                bakTmp = writeTemp(dir, info.fileName() + u".bak"_s, old.readAll(), mode, error);
                ok = !bakTmp.isEmpty();
            }
        }
        if (!ok || ::rename(bakTmp.constData(), bak.constData()) != 0) {
            if (ok)
                *error = AtomicFile::tr("cannot keep the previous file as %1: %2")
                             .arg(QFile::decodeName(bak), errnoText());
            else if (error->isEmpty())
                *error = AtomicFile::tr("cannot keep the previous file as %1").arg(QFile::decodeName(bak));
            ::unlink(bakTmp.constData());
            ::unlink(tmp.constData());
            return false;
        }
    }

    if (::rename(tmp.constData(), target.constData()) != 0) {
        *error = AtomicFile::tr("cannot replace %1: %2").arg(path, errnoText());
        ::unlink(tmp.constData());
        return false;
    }
    syncDirectory(dir);
    return true;
}
