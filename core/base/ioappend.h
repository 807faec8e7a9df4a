// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <QByteArray>
#include <QIODevice>

namespace IoAppend {
/// Appends what `device` has buffered to `to`, until `to` holds `limit` bytes; the bytes taken.
///
/// Not `to += device.read(limit - to.size())`: QIODevice::read(n) makes an array of n bytes
/// before it knows how many there are, which for a bound of 256 MiB is an mmap and its page
/// faults on every read (perf: most of an idle watch's graph poller at 10,000 topics).
inline qint64 available(QIODevice& device, QByteArray& to, qsizetype limit)
{
    const qint64 want = std::min<qint64>(device.bytesAvailable(), qint64(limit) - to.size());
    if (want <= 0)
        return 0;
    const qsizetype at = to.size();
    to.resize(at + qsizetype(want));
    const qint64 got = device.read(to.data() + at, want);
    to.resize(at + qsizetype(std::max<qint64>(0, got)));
    return std::max<qint64>(0, got);
}
} // namespace IoAppend
