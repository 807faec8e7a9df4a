// SPDX-License-Identifier: MIT
#include "mqttclientwire.h"

#include "base/exactutf8.h"

#include <QtEndian>

QString MqttClientWire::dataTopicOf(const QString& typeTopic)
{
    const QString prefix = typeTopicPrefix();
    return typeTopic.startsWith(prefix) ? typeTopic.mid(prefix.size()) : QString();
}

std::optional<RosMsgTypeInfo> MqttClientWire::decodeType(const QByteArray& bytes, QString* error)
{
    qsizetype pos = 0;
    auto fail = [&](const QString& what) {
        if (error)
            *error = what;
        return std::nullopt;
    };
    auto readString = [&](QString* out, const char* field) -> bool {
        if (pos + 4 > bytes.size()) {
            if (error)
                *error = tr("type announcement ends before the length of '%1' (byte %2)")
                             .arg(QLatin1String(field))
                             .arg(pos);
            return false;
        }
        const quint32 n = qFromLittleEndian<quint32>(bytes.constData() + pos);
        pos += 4;
        if (n > quint32(bytes.size() - pos)) {
            if (error)
                *error = tr("'%1' claims %2 bytes but only %3 follow")
                             .arg(QLatin1String(field))
                             .arg(n)
                             .arg(bytes.size() - pos);
            return false;
        }
        *out = exactUtf8(bytes.constData() + pos, qsizetype(n));
        pos += qsizetype(n);
        return true;
    };
    if (bytes.size() > kMaxTypeBytes)
        return fail(tr("type announcement of %1 bytes, more than the %2 one may have")
                        .arg(bytes.size())
                        .arg(kMaxTypeBytes));
    RosMsgTypeInfo info;
    if (!readString(&info.md5, "md5") || !readString(&info.name, "name")
        || !readString(&info.definition, "definition"))
        return std::nullopt;
    if (pos + 1 != bytes.size())
        return fail(tr("type announcement has %1 bytes after the strings, expected 1 (stamped)")
                        .arg(bytes.size() - pos));
    info.stamped = bytes.at(pos) != 0;
    if (info.md5.size() != 32 && info.md5 != QLatin1String("*"))
        return fail(tr("'%1' is not an MD5 sum").arg(info.md5));
    if (!info.name.contains(u'/'))
        return fail(tr("'%1' is not a ROS type name").arg(info.name));
    return info;
}

QByteArray MqttClientWire::encodeType(const RosMsgTypeInfo& info)
{
    QByteArray out;
    for (const QString& s : {info.md5, info.name, info.definition}) {
        const QByteArray utf8 = s.toUtf8();
        char len[4];
        qToLittleEndian<quint32>(quint32(utf8.size()), len);
        out.append(len, 4);
        out.append(utf8);
    }
    out.append(info.stamped ? '\x01' : '\x00');
    return out;
}

std::optional<MqttClientWire::Stamped> MqttClientWire::splitStamped(const QByteArray& payload)
{
    if (payload.size() < 8)
        return std::nullopt;
    Stamped s;
    const quint32 sec = qFromLittleEndian<quint32>(payload.constData());
    const quint32 nsec = qFromLittleEndian<quint32>(payload.constData() + 4);
    if (nsec >= 1000000000u)
        return std::nullopt;
    s.stampNs = qint64(sec) * 1000000000LL + nsec;
    s.message = payload.mid(8);
    return s;
}

QByteArray MqttClientWire::stamped(qint64 stampNs, const QByteArray& message)
{
    QByteArray out(8, Qt::Uninitialized);
    qToLittleEndian<quint32>(quint32(stampNs / 1000000000LL), out.data());
    qToLittleEndian<quint32>(quint32(stampNs % 1000000000LL), out.data() + 4);
    return out + message;
}
