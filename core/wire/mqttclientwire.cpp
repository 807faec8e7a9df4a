// SPDX-License-Identifier: MIT
#include "mqttclientwire.h"

#include "text/exactutf8.h"

#include <QtEndian>

namespace {
constexpr qint64 kNsPerSecond = 1000000000LL;

/// A CDR encapsulation header as ROS 2 writes it: 00 01 (little-endian CDR) or 00 00 (big-endian
/// CDR), then two bytes of options, which readers ignore (Cyclone DDS keeps the padding there).
bool isPlainCdrHeader(const char* p)
{
    return p[0] == 0 && (p[1] == 0 || p[1] == 1);
}

/// The three strings of an announcement, in order, each read by `readString` (ROS 1 or CDR).
template<typename ReadString> Result<void> readStrings(RosMsgTypeInfo* info, ReadString& readString)
{
    for (const auto& [out, field] : {std::pair {&info->md5, "md5"}, std::pair {&info->name, "name"},
                                     std::pair {&info->definition, "definition"}}) {
        if (Result<void> read = readString(out, field); !read)
            return read;
    }
    return {};
}
} // namespace

QString MqttClientWire::dataTopicOf(const QString& typeTopic)
{
    const QString prefix = typeTopicPrefix();
    return typeTopic.startsWith(prefix) ? typeTopic.mid(prefix.size()) : QString();
}

MqttClientWire::Dialect MqttClientWire::dialectOf(const QByteArray& announcement)
{
    return !announcement.isEmpty() && announcement.at(0) == 0 ? Dialect::Ros2 : Dialect::Ros1;
}

Result<RosMsgTypeInfo> MqttClientWire::decodeType(const QByteArray& bytes)
{
    qsizetype pos = 0;
    auto readString = [&](QString* out, const char* field) -> Result<void> {
        if (pos + 4 > bytes.size()) {
            return LocatedError {tr("type announcement ends before the length of '%1' (byte %2)")
                                     .arg(QLatin1String(field))
                                     .arg(pos)};
        }
        const quint32 n = qFromLittleEndian<quint32>(bytes.constData() + pos);
        pos += 4;
        if (n > quint32(bytes.size() - pos)) {
            return LocatedError {tr("'%1' claims %2 bytes but only %3 follow")
                                     .arg(QLatin1String(field))
                                     .arg(n)
                                     .arg(bytes.size() - pos)};
        }
        *out = exactUtf8(bytes.constData() + pos, qsizetype(n));
        pos += qsizetype(n);
        return {};
    };
    if (bytes.size() > kMaxTypeBytes)
        return LocatedError {tr("type announcement of %1 bytes, more than the %2 one may have")
                                 .arg(bytes.size())
                                 .arg(kMaxTypeBytes)};
    if (dialectOf(bytes) == Dialect::Ros2)
        return decodeRos2Type(bytes);
    RosMsgTypeInfo info;
    if (const Result<void> read = readStrings(&info, readString); !read)
        return read.error();
    if (pos + 1 != bytes.size())
        return LocatedError {tr("type announcement has %1 bytes after the strings, expected 1 (stamped)")
                                 .arg(bytes.size() - pos)};
    info.stamped = bytes.at(pos) != 0;
    // Also what keeps dialectOf() right: a length of 32 or 1 never starts with a zero byte.
    if (info.md5.size() != 32 && info.md5 != QLatin1String("*"))
        return LocatedError {tr("'%1' is not an MD5 sum").arg(info.md5)};
    if (!info.name.contains(u'/'))
        return LocatedError {tr("'%1' is not a ROS type name").arg(info.name)};
    return info;
}

// mqtt_client (ROS 2) serializes its RosMsgType with rclcpp::Serialization, that is rmw_serialize:
// the header, then each member in order as Fast CDR (rmw_fastrtps) or rmw_cyclonedds_cpp writes
// it; readers take any non-zero bool as true and ignore bytes after the last member.
Result<RosMsgTypeInfo> MqttClientWire::decodeRos2Type(const QByteArray& bytes)
{
    const char* data = bytes.constData();
    const qsizetype size = bytes.size();
    if (size < 4)
        return LocatedError {
            tr("ROS 2 type announcement of %1 bytes ends inside its CDR encapsulation header").arg(size)};
    if (!isPlainCdrHeader(data))
        return LocatedError {tr("ROS 2 type announcement is not plain CDR (encapsulation %1 %2)")
                                 .arg(uchar(data[0]), 2, 16, QLatin1Char('0'))
                                 .arg(uchar(data[1]), 2, 16, QLatin1Char('0'))};
    const bool bigEndian = data[1] == 0;
    qsizetype pos = 4;
    auto readString = [&](QString* out, const char* field) -> Result<void> {
        pos += (4 - (pos - 4) % 4) % 4; // a uint32 sits at a multiple of 4 from the header's end
        if (pos > size - 4) {
            return LocatedError {tr("type announcement ends before the length of '%1' (byte %2)")
                                     .arg(QLatin1String(field))
                                     .arg(std::min(pos, size))};
        }
        const quint32 n
            = bigEndian ? qFromBigEndian<quint32>(data + pos) : qFromLittleEndian<quint32>(data + pos);
        pos += 4;
        if (n > quint32(size - pos)) {
            return LocatedError {tr("'%1' claims %2 bytes but only %3 follow")
                                     .arg(QLatin1String(field))
                                     .arg(n)
                                     .arg(size - pos)};
        }
        // The length counts the terminating NUL, which is no part of the text.
        const qsizetype text = n > 0 && data[pos + qsizetype(n) - 1] == 0 ? qsizetype(n) - 1 : qsizetype(n);
        *out = exactUtf8(data + pos, text);
        pos += qsizetype(n);
        return {};
    };
    RosMsgTypeInfo info;
    info.dialect = Dialect::Ros2;
    if (const Result<void> read = readStrings(&info, readString); !read)
        return read.error();
    if (pos >= size)
        return LocatedError {tr("type announcement ends before 'stamped' (byte %1)").arg(pos)};
    info.stamped = data[pos] != 0;
    ++pos;
    if (size - pos > 3)
        return LocatedError {
            tr("type announcement has %1 bytes after 'stamped', more than CDR's padding of at most 3")
                .arg(size - pos)};
    if (!info.name.contains(u'/'))
        return LocatedError {tr("'%1' is not a ROS type name").arg(info.name)};
    return info;
}

QByteArray MqttClientWire::encodeType(const RosMsgTypeInfo& info)
{
    const bool ros2 = info.dialect == Dialect::Ros2;
    QByteArray out;
    if (ros2)
        out.append("\x00\x01\x00\x00", 4);
    for (const QString& s : {info.md5, info.name, info.definition}) {
        QByteArray utf8 = s.toUtf8();
        if (ros2) {
            utf8.append('\0');
            out.append((4 - (out.size() - 4) % 4) % 4, '\0');
        }
        char len[4];
        qToLittleEndian<quint32>(quint32(utf8.size()), len);
        out.append(len, 4);
        out.append(utf8);
    }
    out.append(info.stamped ? '\x01' : '\x00');
    return out;
}

Result<MqttClientWire::Stamped> MqttClientWire::splitStamped(const QByteArray& payload, Dialect dialect)
{
    const qsizetype stampSize = stampBytes(dialect);
    if (payload.size() < stampSize)
        return LocatedError {tr("stamped payload of %1 bytes, shorter than its %2-byte stamp")
                                 .arg(payload.size())
                                 .arg(stampSize)};
    const char* p = payload.constData();
    qint64 sec = 0;
    quint32 nsec = 0;
    if (dialect == Dialect::Ros2) {
        if (!isPlainCdrHeader(p))
            return LocatedError {tr("the stamp does not start with a CDR encapsulation header (%1 %2)")
                                     .arg(uchar(p[0]), 2, 16, QLatin1Char('0'))
                                     .arg(uchar(p[1]), 2, 16, QLatin1Char('0'))};
        const bool bigEndian = p[1] == 0;
        sec = bigEndian ? qFromBigEndian<qint32>(p + 4) : qFromLittleEndian<qint32>(p + 4);
        nsec = bigEndian ? qFromBigEndian<quint32>(p + 8) : qFromLittleEndian<quint32>(p + 8);
    } else {
        sec = qFromLittleEndian<quint32>(p);
        nsec = qFromLittleEndian<quint32>(p + 4);
    }
    if (nsec >= quint32(kNsPerSecond))
        return LocatedError {tr("the stamp has %1 nanoseconds, not fewer than 1000000000").arg(nsec)};
    Stamped s;
    s.stampNs = sec * kNsPerSecond + nsec;
    s.message = payload.mid(stampSize);
    return s;
}

QByteArray MqttClientWire::stamped(qint64 stampNs, const QByteArray& message, Dialect dialect)
{
    if (dialect == Dialect::Ros2) {
        // builtin_interfaces/msg/Time: nanosec in [0, 1e9), sec rounded down.
        qint64 sec = stampNs / kNsPerSecond;
        qint64 nsec = stampNs % kNsPerSecond;
        if (nsec < 0) {
            nsec += kNsPerSecond;
            --sec;
        }
        QByteArray out("\x00\x01\x00\x00", 4);
        out.resize(kRos2StampBytes);
        qToLittleEndian<qint32>(qint32(sec), out.data() + 4);
        qToLittleEndian<quint32>(quint32(nsec), out.data() + 8);
        return out + message;
    }
    QByteArray out(8, Qt::Uninitialized);
    qToLittleEndian<quint32>(quint32(stampNs / kNsPerSecond), out.data());
    qToLittleEndian<quint32>(quint32(stampNs % kNsPerSecond), out.data() + 4);
    return out + message;
}

Result<RosValue> MqttClientWire::decodePayload(const RosTypeRegistry& registry, const RosMsgTypeInfo& type,
                                               const QByteArray& payload, const RosDecodeLimits& limits)
{
    QByteArray message = payload;
    if (type.stamped) {
        Result<Stamped> s = splitStamped(payload, type.dialect);
        if (!s)
            return s.error();
        message = std::move(s->message);
    }
    return type.dialect == Dialect::Ros2 ? RosMessageDecoder::decodeCdr(registry, type.name, message, limits)
                                         : RosMessageDecoder::decode(registry, type.name, message, limits);
}
