// SPDX-License-Identifier: MIT
#include "stampcodec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {
constexpr qint64 kNsPerSec = 1000000000LL;

struct Reader
{
    const QByteArray& bytes;
    qsizetype pos = 0;
    bool badNsec = false; ///< a time field held nsec >= 1e9: no ROS time, and no round trip
    bool bigEndian = false; ///< CDR only; ROS 1 is always little-endian
    qsizetype origin = 0; ///< CDR aligns from the end of the encapsulation header
    bool u32(quint32& out)
    {
        if (bytes.size() - pos < 4)
            return false;
        out = bigEndian ? qFromBigEndian<quint32>(bytes.constData() + pos)
                        : qFromLittleEndian<quint32>(bytes.constData() + pos);
        pos += 4;
        return true;
    }
    void align4() { pos = origin + ((pos - origin + 3) & ~qsizetype(3)); }
    bool time(qint64& ns)
    {
        quint32 sec = 0;
        quint32 nsec = 0;
        if (!u32(sec) || !u32(nsec))
            return false;
        if (nsec >= quint32(kNsPerSec)) {
            badNsec = true;
            return false;
        }
        ns = qint64(sec) * kNsPerSec + qint64(nsec);
        return true;
    }
};

void putU32(QByteArray& out, quint32 v)
{
    char b[4];
    qToLittleEndian(v, b);
    out.append(b, 4);
}

void putTime(QByteArray& out, qint64 ns)
{
    putU32(out, quint32(ns / kNsPerSec));
    putU32(out, quint32(ns % kNsPerSec));
}

/// Seconds as ns, without the rounding error of multiplying an epoch time by 1e9 in double.
qint64 secondsToNs(double seconds)
{
    const double whole = std::floor(seconds);
    return qint64(whole) * kNsPerSec + qint64(std::llround((seconds - whole) * 1e9));
}

/// A ROS 2 encapsulation header: 00 01 little-endian CDR, 00 00 big-endian (two option bytes).
std::optional<bool> cdrBigEndian(const QByteArray& bytes)
{
    if (bytes.size() < 4 || bytes[0] != 0 || (bytes[1] != 0 && bytes[1] != 1))
        return std::nullopt;
    return bytes[1] == 0;
}

/// A latency in seconds as ns, when it is a finite number no larger than a ROS time.
std::optional<qint64> latencySeconds(double v)
{
    if (!std::isfinite(v) || std::abs(v) >= double(StampCodec::kMaxTimeNs / kNsPerSec))
        return std::nullopt;
    return secondsToNs(v);
}

} // namespace

qint64 StampCodec::hashId(const QByteArray& bytes)
{
    quint64 h = 14695981039346656037ULL; // FNV-1a, 64 bit
    for (char c : bytes) {
        h ^= quint8(c);
        h *= 1099511628211ULL;
    }
    return qint64(h >> 1);
}

QString StampCodec::definition()
{
    return u"# This represents a timestamp with a reference header, incl. a reference timestamp\n"
           "Header header\n"
           "time time\n"
           "================================================================================\n"
           "MSG: std_msgs/Header\n"
           "# Standard metadata for higher-level stamped data types.\n"
           "# This is generally used to communicate timestamped data \n"
           "# in a particular coordinate frame.\n"
           "# \n"
           "# sequence ID: consecutively increasing ID \n"
           "uint32 seq\n"
           "#Two-integer timestamp that is expressed as:\n"
           "# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')\n"
           "# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')\n"
           "# time-handling sugar is provided by the client library\n"
           "time stamp\n"
           "#Frame this data is associated with\n"
           "string frame_id\n"_s;
}

std::optional<StampCodec::Decoded> StampCodec::decodeHeader(const QByteArray& bytes, qsizetype* consumed)
{
    Reader r {bytes};
    Decoded d;
    quint32 frameLength = 0;
    if (!r.u32(d.seq) || !r.time(d.sampleNs) || !r.u32(frameLength)
        || frameLength > quint32(bytes.size() - r.pos))
        return std::nullopt;
    d.frameId = QString::fromUtf8(bytes.constData() + r.pos, qsizetype(frameLength));
    if (consumed)
        *consumed = r.pos + qsizetype(frameLength);
    return d;
}

Result<StampCodec::Decoded> StampCodec::decodeTimeStamped(const QByteArray& bytes)
{
    qsizetype headerBytes = 0;
    std::optional<Decoded> header = decodeHeader(bytes, &headerBytes);
    if (!header) {
        if (bytes.size() >= 12 && qFromLittleEndian<quint32>(bytes.constData() + 8) >= quint32(kNsPerSec))
            return LocatedError {tr("TimeStamped header stamp has %1 nanoseconds, more than a second")
                                     .arg(qFromLittleEndian<quint32>(bytes.constData() + 8))};
        return LocatedError {bytes.size() < 16
                                 ? tr("TimeStamped message too short (%1 bytes)").arg(bytes.size())
                                 : tr("TimeStamped frame_id claims %1 bytes, only %2 left")
                                       .arg(qFromLittleEndian<quint32>(bytes.constData() + 12))
                                       .arg(bytes.size() - 16)};
    }
    Decoded d = *header;
    Reader r {bytes};
    r.pos = headerBytes;
    if (!r.time(d.timeNs))
        return LocatedError {r.badNsec ? tr("TimeStamped time has %1 nanoseconds, more than a second")
                                             .arg(qFromLittleEndian<quint32>(bytes.constData() + r.pos - 4))
                                       : tr("TimeStamped message ends before its time field")};
    if (r.pos != bytes.size())
        return LocatedError {tr("TimeStamped message has %1 bytes too many").arg(bytes.size() - r.pos)};
    return d;
}

QByteArray StampCodec::encodeTimeStamped(const Decoded& stamp)
{
    const QByteArray frame = stamp.frameId.toUtf8();
    QByteArray out;
    out.reserve(24 + frame.size());
    putU32(out, stamp.seq);
    putTime(out, stamp.sampleNs);
    putU32(out, quint32(frame.size()));
    out.append(frame);
    putTime(out, stamp.timeNs);
    return out;
}

Result<StampCodec::Decoded> StampCodec::decodeTimeStampedCdr(const QByteArray& bytes)
{
    const std::optional<bool> big = cdrBigEndian(bytes);
    if (!big)
        return LocatedError {bytes.size() < 4
                                 ? tr("TimeStamped message too short (%1 bytes)").arg(bytes.size())
                                 : tr("not CDR: the encapsulation header is %1")
                                       .arg(QString::fromLatin1(bytes.left(4).toHex(' ')))};
    Reader r {bytes, 4, false, *big, 4};
    Decoded d;
    quint32 frameLength = 0;
    if (!r.time(d.sampleNs))
        return LocatedError {r.badNsec ? tr("TimeStamped header stamp has %1 nanoseconds, more than a second")
                                             .arg(*big ? qFromBigEndian<quint32>(bytes.constData() + 8)
                                                       : qFromLittleEndian<quint32>(bytes.constData() + 8))
                                       : tr("TimeStamped message too short (%1 bytes)").arg(bytes.size())};
    if (!r.u32(frameLength))
        return LocatedError {tr("TimeStamped message too short (%1 bytes)").arg(bytes.size())};
    if (frameLength > quint32(bytes.size() - r.pos))
        return LocatedError {tr("TimeStamped frame_id claims %1 bytes, only %2 left")
                                 .arg(frameLength)
                                 .arg(bytes.size() - r.pos)};
    // The length counts the terminating NUL (0 is not CDR, but harmless: an empty frame_id).
    d.frameId = QString::fromUtf8(bytes.constData() + r.pos, frameLength > 0 ? qsizetype(frameLength) - 1 : 0);
    r.pos += qsizetype(frameLength);
    r.align4();
    if (!r.time(d.timeNs))
        return LocatedError {r.badNsec
                                 ? tr("TimeStamped time has %1 nanoseconds, more than a second")
                                       .arg(*big ? qFromBigEndian<quint32>(bytes.constData() + r.pos - 4)
                                                 : qFromLittleEndian<quint32>(bytes.constData() + r.pos - 4))
                                 : tr("TimeStamped message ends before its time field")};
    if (bytes.size() - r.pos > 3) // RTPS pads a sample to a multiple of 4 bytes, no more
        return LocatedError {tr("TimeStamped message has %1 bytes too many").arg(bytes.size() - r.pos)};
    // builtin_interfaces/msg/Time has an int32 sec: what reads past 2^31 s was negative.
    if (d.sampleNs >= (qint64(1) << 31) * kNsPerSec || d.timeNs >= (qint64(1) << 31) * kNsPerSec)
        return LocatedError {tr("TimeStamped holds a time before 1970")};
    return d;
}

QByteArray StampCodec::encodeTimeStampedCdr(const Decoded& stamp)
{
    const QByteArray frame = stamp.frameId.toUtf8();
    QByteArray out("\x00\x01\x00\x00", 4);
    putTime(out, stamp.sampleNs);
    putU32(out, quint32(frame.size() + 1));
    out.append(frame);
    out.append('\0');
    while ((out.size() - 4) % 4 != 0)
        out.append('\0');
    putTime(out, stamp.timeNs);
    return out;
}

QString StampCodec::rangeText()
{
    return tr("outside the times a ROS stamp can hold (0 to 4294967296 s after 1970)");
}

std::optional<qint64> StampCodec::parseTime(QStringView text)
{
    text = text.trimmed();
    if (text.isEmpty())
        return std::nullopt;
    const qsizetype dot = text.indexOf(u'.');
    const bool exponent = text.contains(u'e') || text.contains(u'E');
    if (!exponent && text.startsWith(u'-') && text.size() > 1 && text[1] != u'-' && text[1] != u'+') {
        // Before 1970 (clock offsets, hand-made files): the same exact decimal, negated.
        const std::optional<qint64> magnitude = parseTime(text.mid(1));
        return magnitude ? std::optional<qint64>(-*magnitude) : std::nullopt;
    }
    if (!exponent && !text.startsWith(u'-')) {
        // Exact decimal: integer seconds and up to nine digits of fraction.
        bool ok = false;
        const QStringView secText = dot < 0 ? text : text.left(dot);
        // Digits only: toLongLong() stops at a NUL byte and took "12\0 99" for 12.
        const QStringView digits = secText.startsWith(u'+') ? secText.mid(1) : secText;
        if (!std::all_of(digits.begin(), digits.end(), [](QChar c) { return c >= u'0' && c <= u'9'; }))
            return std::nullopt;
        const qint64 sec = secText.isEmpty() ? 0 : secText.toLongLong(&ok);
        if (!secText.isEmpty() && !ok)
            return std::nullopt;
        if (sec > std::numeric_limits<qint64>::max() / kNsPerSec - 1)
            return std::nullopt;
        qint64 ns = 0;
        if (dot >= 0) {
            const QStringView frac = text.mid(dot + 1);
            if (frac.isEmpty() && secText.isEmpty())
                return std::nullopt;
            qint64 scale = kNsPerSec;
            for (qsizetype i = 0; i < frac.size(); ++i) {
                if (frac[i] < u'0' || frac[i] > u'9')
                    return std::nullopt;
                if (i < 9) {
                    scale /= 10;
                    ns += (frac[i].unicode() - u'0') * scale;
                }
            }
        }
        return sec * kNsPerSec + ns;
    }
    bool ok = false;
    const double seconds = text.toDouble(&ok);
    if (!ok || !std::isfinite(seconds) || std::abs(seconds) > 9.2e9)
        return std::nullopt;
    return secondsToNs(seconds);
}

Result<StampCodec::Decoded> StampCodec::decodeJson(const QByteArray& payload)
{
    if (payload.size() > kMaxJsonBytes)
        return LocatedError {
            tr("JSON stamp of %1 bytes: a stamp has at most %2").arg(payload.size()).arg(kMaxJsonBytes)};
    QJsonParseError parseError {};
    const QJsonDocument doc = QJsonDocument::fromJson(payload, &parseError);
    if (!doc.isObject())
        return LocatedError {
            parseError.error != QJsonParseError::NoError
                ? tr("not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset)
                : tr("JSON stamp must be an object")};
    const QJsonObject o = doc.object();
    const QJsonValue sample = o.value(u"sample"_s);
    const QJsonValue time = o.value(u"time"_s);
    if (sample.isUndefined() || time.isUndefined())
        return LocatedError {tr("JSON stamp needs \"sample\" and \"time\"")};
    Decoded d;
    if (sample.isString()) {
        const QString id = sample.toString();
        if (id.isEmpty())
            return LocatedError {tr("JSON stamp's \"sample\" is empty: it names no sample")};
        const std::optional<qint64> asTime = parseTime(id);
        d.sampleNs = asTime && inRange(*asTime) ? *asTime : hashId(id.toUtf8());
        d.frameId = id;
    } else if (sample.isDouble()) {
        const std::optional<qint64> asTime = parseTime(QString::number(sample.toDouble(), 'f', 9));
        if (!asTime || !inRange(*asTime))
            return LocatedError {tr("JSON stamp's \"sample\" is not a usable number (%1)").arg(rangeText())};
        d.sampleNs = *asTime;
    } else {
        return LocatedError {tr("JSON stamp's \"sample\" must be a string or a number")};
    }
    std::optional<qint64> t;
    if (time.isString())
        t = parseTime(time.toString());
    else if (time.isDouble() && std::isfinite(time.toDouble()) && std::abs(time.toDouble()) < 9.2e9)
        t = secondsToNs(time.toDouble());
    if (!t)
        return LocatedError {tr("JSON stamp's \"time\" must be seconds or \"sec.nsec\"")};
    if (!inRange(*t))
        return LocatedError {tr("JSON stamp's \"time\" %1 is %2").arg(timeText(*t), rangeText())};
    d.timeNs = *t;
    return d;
}

QByteArray StampCodec::encodeJson(qint64 sampleNs, qint64 timeNs)
{
    return "{\"sample\": \"" + timeText(sampleNs).toLatin1() + "\", \"time\": \""
        + timeText(timeNs).toLatin1() + "\"}";
}

QString StampCodec::timeText(qint64 ns)
{
    // Sign and magnitude, as people write it and as parseTime() reads it back: -1.5 s is
    // "-1.500000000", not the floored "-2.500000000".
    const quint64 magnitude = ns < 0 ? quint64(0) - quint64(ns) : quint64(ns);
    return (ns < 0 ? u"-"_s : QString()) + QString::number(magnitude / kNsPerSec) + u'.'
        + QString::number(magnitude % kNsPerSec).rightJustified(9, u'0');
}

std::optional<qint64> StampCodec::decodeFloat64Seconds(const QByteArray& bytes)
{
    if (bytes.size() != 8)
        return std::nullopt;
    double v = 0;
    std::memcpy(&v, bytes.constData(), 8); // ROS is little-endian on every platform we build for
    return latencySeconds(v);
}

std::optional<qint64> StampCodec::decodeFloat64SecondsCdr(const QByteArray& bytes)
{
    const std::optional<bool> big = cdrBigEndian(bytes);
    if (!big || bytes.size() < 12 || bytes.size() > 12 + 3)
        return std::nullopt;
    const quint64 bits = *big ? qFromBigEndian<quint64>(bytes.constData() + 4)
                              : qFromLittleEndian<quint64>(bytes.constData() + 4);
    double v = 0;
    std::memcpy(&v, &bits, 8);
    return latencySeconds(v);
}
