// SPDX-License-Identifier: MIT
#include "wire/ros2bridgewire.h"

#include "wire/primitivetext.h"
#include "wire/rosmessageencoder.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>
#include <QVariantMap>

using namespace Qt::StringLiterals;

namespace Ros2BridgeWire {

namespace {
const QByteArray kHeader = QByteArray::fromHex("00010000");

void putU32(QByteArray& out, quint32 v)
{
    while ((out.size() - 4) % 4)
        out.append('\0'); // CDR aligns from the end of the encapsulation header
    char b[4];
    qToLittleEndian(v, b);
    out.append(b, 4);
}

void putTime(QByteArray& out, qint64 ns)
{
    putU32(out, quint32(qint32(ns / 1'000'000'000)));
    putU32(out, quint32(ns % 1'000'000'000));
}

} // namespace

QByteArray encodeTimeStamped(const StampCodec::Decoded& stamp)
{
    const QByteArray frame = stamp.frameId.toUtf8();
    QByteArray out = kHeader;
    putTime(out, stamp.sampleNs);
    putU32(out, quint32(frame.size() + 1));
    out += frame;
    out.append('\0');
    putTime(out, stamp.timeNs);
    return out;
}

QByteArray encodeFloat64(double value)
{
    QByteArray out = kHeader;
    char b[8];
    qToLittleEndian(value, b);
    out.append(b, 8);
    return out;
}

std::optional<qint64> headerStampNs(const QByteArray& cdr)
{
    if (cdr.size() < 12 || cdr.at(0) != 0 || (cdr.at(1) != 0 && cdr.at(1) != 1))
        return std::nullopt;
    const bool little = cdr.at(1) == 1;
    const auto u32 = [&](int at) {
        return little ? qFromLittleEndian<quint32>(cdr.constData() + at) : qFromBigEndian<quint32>(cdr.constData() + at);
    };
    const qint32 sec = qint32(u32(4));
    const quint32 nsec = u32(8);
    const qint64 ns = qint64(sec) * 1'000'000'000 + nsec;
    if (nsec >= 1'000'000'000 || !StampCodec::inRange(ns))
        return std::nullopt;
    return ns;
}

bool startsWithHeader(const RosTypeRegistry& registry, const QString& type)
{
    const RosMessageType* t = registry.find(type);
    if (!t || t->fields.isEmpty() || t->fields.first().isArray)
        return false;
    const QString first = t->fields.first().type;
    return first == u"std_msgs/msg/Header"_s || first == u"std_msgs/Header"_s || first == u"Header"_s;
}

std::optional<QByteArray> primitiveText(const RosTypeRegistry& registry, const QString& type, const QByteArray& cdr)
{
    static const QStringList kTypes {u"String"_s,  u"Bool"_s,   u"Char"_s,    u"Byte"_s,    u"UInt8"_s,
                                      u"UInt16"_s,  u"UInt32"_s, u"UInt64"_s,  u"Int8"_s,    u"Int16"_s,
                                      u"Int32"_s,   u"Int64"_s,  u"Float32"_s, u"Float64"_s, u"UInt8MultiArray"_s};
    if (!type.startsWith(u"std_msgs/msg/"_s) || !kTypes.contains(type.mid(13)))
        return std::nullopt;
    RosDecodeLimits limits;
    limits.maxStringChars = std::numeric_limits<int>::max();
    limits.maxArrayElements = std::numeric_limits<int>::max();
    const Result<RosValue> v = RosMessageDecoder::decodeCdr(registry, type, cdr, limits);
    const RosValue* data = v ? v->find(u"data"_s) : nullptr;
    if (!data)
        return std::nullopt;
    const QString t = type.mid(13);
    if (t == u"String"_s)
        return data->value.toString().toUtf8();
    if (t == u"Bool"_s)
        return data->value.toBool() ? QByteArray("true") : QByteArray("false");
    if (t == u"Float32"_s || t == u"Float64"_s)
        return PrimitiveText::fixed(data->value.toDouble()); // std::to_string
    if (t == u"UInt8MultiArray"_s)
        return QByteArray::fromHex(data->value.toByteArray()); // the decoder gives byte arrays as hex
    return data->value.toString().toUtf8();
}

Typed primitiveFromText(const QByteArray& text)
{
    const PrimitiveText::Parsed p = PrimitiveText::parse(text);
    QByteArray out = kHeader;
    switch (p.kind) {
    case PrimitiveText::Parsed::Kind::Bool:
        return {u"std_msgs/msg/Bool"_s, out + QByteArray(1, p.boolean ? '\1' : '\0')};
    case PrimitiveText::Parsed::Kind::Int32:
        putU32(out, quint32(p.integer));
        return {u"std_msgs/msg/Int32"_s, out};
    case PrimitiveText::Parsed::Kind::Float32: {
        char b[4];
        qToLittleEndian(p.real, b);
        out.append(b, 4);
        return {u"std_msgs/msg/Float32"_s, out};
    }
    case PrimitiveText::Parsed::Kind::String:
        break;
    }
    putU32(out, quint32(text.size() + 1));
    out += text;
    out.append('\0');
    return {u"std_msgs/msg/String"_s, out};
}

std::optional<QByteArray> fixedPrimitive(const RosTypeRegistry& registry, const QString& type, const QByteArray& text)
{
    QVariant data;
    if (type == u"std_msgs/msg/String"_s) {
        data = QString::fromUtf8(text);
    } else if (type == u"std_msgs/msg/Bool"_s) {
        const QByteArray lower = text.toLower();
        if (lower == "true" || lower == "1")
            data = true;
        else if (lower == "false" || lower == "0")
            data = false;
        else
            return std::nullopt;
    } else if (type == u"std_msgs/msg/UInt8MultiArray"_s) {
        QVariantList bytes;
        for (const char c : text)
            bytes.append(uint(quint8(c)));
        data = bytes;
    } else {
        data = QString::fromUtf8(text.trimmed()); // a number: the encoder checks its range and kind
    }
    Result<QByteArray> cdr = RosMessageEncoder::encodeCdr(registry, type, QVariantMap {{u"data"_s, data}});
    if (!cdr)
        return std::nullopt;
    return std::move(cdr).value();
}

namespace {
QJsonValue jsonOf(const RosValue& v)
{
    switch (v.kind) {
    case RosValue::Message: {
        QJsonObject o;
        for (const RosValue& c : v.children)
            o.insert(c.name, jsonOf(c));
        return o;
    }
    case RosValue::Array: {
        QJsonArray a;
        if (v.children.isEmpty() && v.arrayLength > 0) // bytes, given as hex
            for (const char b : QByteArray::fromHex(v.value.toByteArray()))
                a.append(v.type.startsWith(u"int8"_s) ? int(qint8(b)) : int(quint8(b)));
        for (const RosValue& c : v.children)
            a.append(jsonOf(c));
        return a;
    }
    case RosValue::Scalar:
        break;
    }
    return QJsonValue::fromVariant(v.value);
}
} // namespace

QString tooLargeForJson(qsizetype bytes)
{
    return QCoreApplication::translate("Ros2BridgeWire", "a payload of %1 bytes, more than the %2 MiB a json mapping converts: refused unread")
        .arg(bytes)
        .arg(kMaxJsonBytes / (1024 * 1024));
}

Result<QByteArray> toJson(const RosTypeRegistry& registry, const QString& type, const QByteArray& cdr)
{
    if (cdr.size() > kMaxJsonBytes)
        return LocatedError {tooLargeForJson(cdr.size())};
    RosDecodeLimits limits;
    limits.maxStringChars = std::numeric_limits<int>::max();
    limits.maxArrayElements = std::numeric_limits<int>::max();
    const Result<RosValue> v = RosMessageDecoder::decodeCdr(registry, type, cdr, limits);
    if (!v)
        return v.error();
    return QJsonDocument(jsonOf(*v).toObject()).toJson(QJsonDocument::Compact);
}

Result<QByteArray> fromJson(const RosTypeRegistry& registry, const QString& type, const QByteArray& json)
{
    if (json.size() > kMaxJsonBytes) { // never the tree of it
        return LocatedError {tooLargeForJson(json.size())};
    }
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parse);
    if (!doc.isObject())
        return LocatedError {parse.error != QJsonParseError::NoError ? parse.errorString()
                                                                     : u"not a JSON object"_s};
    return RosMessageEncoder::encodeCdr(registry, type, doc.toVariant());
}

} // namespace Ros2BridgeWire
