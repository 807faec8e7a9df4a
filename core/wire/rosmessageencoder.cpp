// SPDX-License-Identifier: MIT
#include "rosmessageencoder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <QLocale>
#include <QSet>
#include <QStringList>
#include <QtEndian>
#include <QVariantList>
#include <QVariantMap>

using namespace Qt::StringLiterals;

namespace {

struct EncodeError
{
    QString message;
};

constexpr qint64 kNsPerSec = 1'000'000'000LL;

QString kindOf(const QVariant& v)
{
    switch (v.typeId()) {
    case QMetaType::QVariantMap:
    case QMetaType::QVariantHash:
        return RosMessageEncoder::tr("a map");
    case QMetaType::QVariantList:
    case QMetaType::QStringList:
        return RosMessageEncoder::tr("a list");
    case QMetaType::Bool:
        return RosMessageEncoder::tr("a bool");
    case QMetaType::QString:
        return RosMessageEncoder::tr("the text '%1'").arg(v.toString().left(40));
    default:
        return RosMessageEncoder::tr("a number");
    }
}

bool isNumber(const QVariant& v)
{
    switch (v.typeId()) {
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
    case QMetaType::Double:
    case QMetaType::Float:
        return true;
    default:
        return false;
    }
}

bool isMap(const QVariant& v)
{
    return v.typeId() == QMetaType::QVariantMap || v.typeId() == QMetaType::QVariantHash;
}

bool isByteType(const QString& type)
{
    return type == u"uint8"_s || type == u"int8"_s || type == u"char"_s || type == u"byte"_s;
}

/// An integer as sign and magnitude, so that int64 and uint64 both fit.
struct Integer
{
    bool negative = false;
    quint64 magnitude = 0;
};

class Writer
{
    Q_DECLARE_TR_FUNCTIONS(RosMessageEncoder)
public:
    Writer(const RosTypeRegistry& reg, const RosEncodeLimits& limits)
        : m_reg(reg)
        , m_limits(limits)
    { }

    QByteArray take() { return std::move(m_out); }

    /// CDR from here on, as rmw serializes for ROS 2: the encapsulation header 00 01 00 00
    /// (little-endian CDR), then each value aligned to its size from the end of the header,
    /// strings with their NUL, a message of no fields as one zero byte (rosidl's
    /// structure_needs_at_least_one_field).
    void useCdr()
    {
        m_out.append("\x00\x01\x00\x00", 4);
        m_cdr = true;
        m_origin = m_out.size();
    }

    [[noreturn]] static void fail(const QString& path, const QString& what)
    {
        throw EncodeError {path.isEmpty() ? what : tr("%1: %2").arg(path, what)};
    }

    void value(const QString& type, const QVariant& v, const QString& path, int depth)
    {
        if (++m_steps > m_limits.maxSteps)
            fail(path, tr("more than %1 values: too much for one message").arg(m_limits.maxSteps));
        if (depth > m_limits.maxDepth)
            fail(path, tr("nested deeper than %1 levels").arg(m_limits.maxDepth));
        if (RosTypeRegistry::isBuiltin(type)) {
            builtin(type, v, path);
            return;
        }
        const RosMessageType* msg = m_reg.find(type);
        if (!msg)
            fail(path, tr("no definition for '%1'").arg(type));
        if (v.isValid() && !isMap(v))
            fail(path, tr("%1 is a message and needs a map of its fields, not %2").arg(type, kindOf(v)));
        const QVariantMap fields = v.toMap();
        if (m_cdr && msg->fields.isEmpty() && fields.isEmpty()) {
            put<quint8>(0, path);
            return;
        }
        for (auto it = fields.cbegin(); it != fields.cend(); ++it) {
            const bool known = std::any_of(msg->fields.cbegin(), msg->fields.cend(),
                                           [&](const RosField& f) { return f.name == it.key(); });
            if (!known)
                fail(path, tr("%1 has no field '%2'").arg(type, it.key()));
        }
        for (const RosField& f : msg->fields) {
            const QString sub = path.isEmpty() ? f.name : path + u'.' + f.name;
            if (f.isArray)
                array(f, fields.value(f.name), sub, depth + 1);
            else
                value(f.type, fields.value(f.name), sub, depth + 1);
        }
    }

private:
    void array(const RosField& f, const QVariant& v, const QString& path, int depth)
    {
        QVariantList items;
        if (v.typeId() == QMetaType::QByteArray && isByteType(f.type)) {
            for (char c : v.toByteArray())
                items.append(f.type == u"uint8"_s || f.type == u"char"_s ? QVariant(uint(uchar(c)))
                                                                         : QVariant(int(qint8(c))));
        } else if (v.typeId() == QMetaType::QVariantList || v.typeId() == QMetaType::QStringList) {
            items = v.toList();
        } else if (v.isValid()) {
            fail(path, tr("an array needs a list, not %1").arg(kindOf(v)));
        }
        if (f.fixedLength >= 0) {
            // A missing array is its zero value; a given one must have exactly its length.
            if (v.isValid() && items.size() != f.fixedLength)
                fail(path, tr("has %1 elements, the type fixes %2").arg(items.size()).arg(f.fixedLength));
            if (f.fixedLength > m_limits.maxSteps)
                fail(path, tr("%1 elements: too many for one message").arg(f.fixedLength));
        } else {
            put<quint32>(quint32(items.size()), path);
        }
        const qint64 n = f.fixedLength >= 0 ? f.fixedLength : items.size();
        for (qint64 i = 0; i < n; ++i)
            value(f.type, i < items.size() ? items[i] : QVariant(), path + u"[%1]"_s.arg(i), depth);
    }

    template<typename T> void put(T v, const QString& path)
    {
        if (m_cdr && sizeof(T) > 1) {
            static const char zeros[8] = {};
            const qsizetype offset = (m_out.size() - m_origin) % qsizetype(sizeof(T));
            if (offset)
                write(zeros, qsizetype(sizeof(T)) - offset, path);
        }
        char bytes[sizeof(T)];
        qToLittleEndian<T>(v, bytes);
        write(bytes, sizeof(T), path);
    }

    void write(const char* data, qsizetype n, const QString& path)
    {
        if (m_out.size() + n > m_limits.maxBytes)
            fail(path, tr("the message would pass %1 bytes").arg(m_limits.maxBytes));
        m_out.append(data, n);
    }

    static Integer integer(const QVariant& v, const QString& path)
    {
        Integer out;
        bool ok = true;
        switch (v.typeId()) {
        case QMetaType::UnknownType:
            return out;
        case QMetaType::Int:
        case QMetaType::LongLong: {
            const qint64 i = v.toLongLong();
            out.negative = i < 0;
            out.magnitude = i < 0 ? quint64(0) - quint64(i) : quint64(i);
            return out;
        }
        case QMetaType::UInt:
        case QMetaType::ULongLong:
            out.magnitude = v.toULongLong();
            return out;
        case QMetaType::Double:
        case QMetaType::Float: {
            const double d = v.toDouble();
            if (!std::isfinite(d) || std::trunc(d) != d)
                fail(path, tr("%1 is not a whole number").arg(d));
            if (d <= -9.3e18 || d >= 1.85e19)
                fail(path, tr("%1 is out of range").arg(d));
            out.negative = d < 0;
            out.magnitude = d < 0 ? quint64(-d) : quint64(d);
            return out;
        }
        case QMetaType::QString: {
            const QString s = v.toString().trimmed();
            const bool minus = s.startsWith(u'-');
            const QString digits = minus ? s.mid(1) : s;
            out.magnitude = digits.toULongLong(&ok, 10);
            if (!ok || digits.startsWith(u'-') || digits.startsWith(u'+'))
                fail(path, tr("'%1' is not a whole number").arg(s.left(40)));
            out.negative = minus && out.magnitude != 0;
            return out;
        }
        default:
            fail(path, tr("needs a whole number, not %1").arg(kindOf(v)));
        }
    }

    static qint64 checkedSigned(const Integer& i, qint64 lo, qint64 hi, const QString& type,
                                const QString& path)
    {
        const bool fits = i.negative ? i.magnitude <= quint64(0) - quint64(lo) : i.magnitude <= quint64(hi);
        if (!fits)
            fail(path,
                 tr("%1%2 does not fit %3 (%4 to %5)")
                     .arg(i.negative ? u"-"_s : QString())
                     .arg(i.magnitude)
                     .arg(type)
                     .arg(lo)
                     .arg(hi));
        return i.negative ? qint64(quint64(0) - i.magnitude) : qint64(i.magnitude);
    }

    static quint64 checkedUnsigned(const Integer& i, quint64 hi, const QString& type, const QString& path)
    {
        if (i.negative || i.magnitude > hi)
            fail(path,
                 tr("%1%2 does not fit %3 (0 to %4)")
                     .arg(i.negative ? u"-"_s : QString())
                     .arg(i.magnitude)
                     .arg(type)
                     .arg(hi));
        return i.magnitude;
    }

    static double real(const QVariant& v, const QString& path)
    {
        if (!v.isValid())
            return 0;
        if (isNumber(v))
            return v.toDouble();
        if (v.typeId() == QMetaType::QString) {
            const QString s = v.toString().trimmed();
            const QString lower = s.toLower();
            if (lower == u"nan"_s || lower == u".nan"_s)
                return std::numeric_limits<double>::quiet_NaN();
            if (lower == u"inf"_s || lower == u".inf"_s || lower == u"+inf"_s || lower == u"+.inf"_s)
                return std::numeric_limits<double>::infinity();
            if (lower == u"-inf"_s || lower == u"-.inf"_s)
                return -std::numeric_limits<double>::infinity();
            bool ok = false;
            const double d = s.toDouble(&ok);
            if (ok)
                return d;
            fail(path, tr("'%1' is not a number").arg(s.left(40)));
        }
        fail(path, tr("needs a number, not %1").arg(kindOf(v)));
    }

    static bool boolean(const QVariant& v, const QString& path)
    {
        if (!v.isValid())
            return false;
        if (v.typeId() == QMetaType::Bool)
            return v.toBool();
        if (v.typeId() == QMetaType::QString) {
            const QString s = v.toString().trimmed().toLower();
            if (s == u"true"_s || s == u"1"_s)
                return true;
            if (s == u"false"_s || s == u"0"_s)
                return false;
            fail(path, tr("'%1' is not true or false").arg(s.left(40)));
        }
        if (isNumber(v)) {
            const double d = v.toDouble();
            if (d == 0 || d == 1)
                return d == 1;
            fail(path, tr("%1 is not a bool (0 or 1)").arg(d));
        }
        fail(path, tr("needs true or false, not %1").arg(kindOf(v)));
    }

    /// Nanoseconds of a time or duration: "sec.nsec" text, seconds as a number, or {secs, nsecs}.
    static qint64 nanoseconds(const QVariant& v, const QString& path)
    {
        if (!v.isValid())
            return 0;
        if (isMap(v)) {
            const QVariantMap m = v.toMap();
            qint64 sec = 0;
            qint64 nsec = 0;
            for (auto it = m.cbegin(); it != m.cend(); ++it) {
                const Integer i = integer(it.value(), path + u'.' + it.key());
                const qint64 n = checkedSigned(i, -qint64(0xffffffffLL), 0xffffffffLL, u"int64"_s, path);
                if (it.key() == u"secs"_s || it.key() == u"sec"_s)
                    sec = n;
                else if (it.key() == u"nsecs"_s || it.key() == u"nsec"_s || it.key() == u"nanosec"_s)
                    nsec = n;
                else
                    fail(path, tr("a time has secs and nsecs, not '%1'").arg(it.key()));
            }
            return sec * kNsPerSec + nsec;
        }
        if (v.typeId() == QMetaType::QString) {
            const QString s = v.toString().trimmed();
            const bool minus = s.startsWith(u'-');
            const QString body = minus ? s.mid(1) : s;
            const qsizetype dot = body.indexOf(u'.');
            const QString whole = dot < 0 ? body : body.left(dot);
            const QString fraction = dot < 0 ? QString() : body.mid(dot + 1);
            const auto digits = [](const QString& t) {
                return std::all_of(t.cbegin(), t.cend(), [](QChar c) { return c >= u'0' && c <= u'9'; });
            };
            if (whole.isEmpty() || whole.size() > 10 || fraction.size() > 9 || !digits(whole)
                || !digits(fraction))
                fail(path,
                     tr("'%1' is not a time in seconds (sec.nsec, at most nine decimals)").arg(s.left(40)));
            const qint64 ns = whole.toLongLong() * kNsPerSec
                + (fraction.isEmpty() ? 0 : fraction.leftJustified(9, u'0').toLongLong());
            return minus ? -ns : ns;
        }
        if (isNumber(v)) {
            const double d = v.toDouble();
            if (!std::isfinite(d) || std::abs(d) > 5e9)
                fail(path, tr("%1 seconds is out of range").arg(d));
            return qint64(std::llround(d * 1e9));
        }
        fail(path, tr("needs a time (sec.nsec), not %1").arg(kindOf(v)));
    }

    void builtin(const QString& type, const QVariant& v, const QString& path)
    {
        if (type == u"string"_s) {
            if (v.isValid() && v.typeId() != QMetaType::QString)
                fail(path, tr("needs text, not %1").arg(kindOf(v)));
            const QByteArray utf8 = v.toString().toUtf8();
            if (m_cdr) {
                // CDR counts the terminating NUL, and a NUL inside would end the string early
                if (utf8.contains('\0'))
                    fail(path, tr("text with a NUL character cannot be sent as a CDR string"));
                put<quint32>(quint32(std::min<qsizetype>(utf8.size() + 1, 0xffffffff)), path);
                write(utf8.constData(), utf8.size() + 1, path);
                return;
            }
            put<quint32>(quint32(std::min<qsizetype>(utf8.size(), 0xffffffff)), path);
            write(utf8.constData(), utf8.size(), path);
        } else if (type == u"bool"_s) {
            put<quint8>(boolean(v, path) ? 1 : 0, path);
        } else if (type == u"int8"_s || type == u"byte"_s) {
            put<qint8>(qint8(checkedSigned(integer(v, path), -128, 127, type, path)), path);
        } else if (type == u"uint8"_s || type == u"char"_s) {
            put<quint8>(quint8(checkedUnsigned(integer(v, path), 0xff, type, path)), path);
        } else if (type == u"int16"_s) {
            put<qint16>(qint16(checkedSigned(integer(v, path), -32768, 32767, type, path)), path);
        } else if (type == u"uint16"_s) {
            put<quint16>(quint16(checkedUnsigned(integer(v, path), 0xffff, type, path)), path);
        } else if (type == u"int32"_s) {
            put<qint32>(qint32(checkedSigned(integer(v, path), std::numeric_limits<qint32>::min(),
                                             std::numeric_limits<qint32>::max(), type, path)),
                        path);
        } else if (type == u"uint32"_s) {
            put<quint32>(quint32(checkedUnsigned(integer(v, path), 0xffffffffULL, type, path)), path);
        } else if (type == u"int64"_s) {
            put<qint64>(checkedSigned(integer(v, path), std::numeric_limits<qint64>::min(),
                                      std::numeric_limits<qint64>::max(), type, path),
                        path);
        } else if (type == u"uint64"_s) {
            put<quint64>(checkedUnsigned(integer(v, path), std::numeric_limits<quint64>::max(), type, path),
                         path);
        } else if (type == u"float32"_s) {
            const double d = real(v, path);
            if (std::isfinite(d) && std::abs(d) > double(std::numeric_limits<float>::max()))
                fail(path, tr("%1 does not fit float32").arg(d));
            put<float>(float(d), path);
        } else if (type == u"float64"_s) {
            put<double>(real(v, path), path);
        } else if (type == u"time"_s) {
            const qint64 ns = nanoseconds(v, path);
            if (ns < 0 || ns / kNsPerSec > 0xffffffffLL)
                fail(path, tr("a time must lie between 0 and 4294967295 seconds"));
            put<quint32>(quint32(ns / kNsPerSec), path);
            put<quint32>(quint32(ns % kNsPerSec), path);
        } else if (type == u"duration"_s) {
            // As roscpp normalizes: nsec in [0, 1e9), the seconds carry the sign.
            const qint64 ns = nanoseconds(v, path);
            qint64 sec = ns / kNsPerSec;
            qint64 nsec = ns % kNsPerSec;
            if (nsec < 0) {
                --sec;
                nsec += kNsPerSec;
            }
            if (sec < std::numeric_limits<qint32>::min() || sec > std::numeric_limits<qint32>::max())
                fail(path, tr("a duration must lie within ±2147483647 seconds"));
            put<qint32>(qint32(sec), path);
            put<qint32>(qint32(nsec), path);
        } else {
            fail(path, tr("unknown type '%1'").arg(type));
        }
    }

    const RosTypeRegistry& m_reg;
    RosEncodeLimits m_limits;
    QByteArray m_out;
    qint64 m_steps = 0;
    bool m_cdr = false;
    qsizetype m_origin = 0;
};

} // namespace

namespace {
Result<QByteArray> encodeWith(const RosTypeRegistry& registry, const QString& type, const QVariant& value,
                              const RosEncodeLimits& limits, bool cdr)
{
    Writer writer(registry, limits);
    if (cdr)
        writer.useCdr();
    try {
        writer.value(type, value, QString(), 0);
        return writer.take();
    } catch (const EncodeError& e) {
        return LocatedError {e.message};
    }
}
} // namespace

Result<QByteArray> RosMessageEncoder::encode(const RosTypeRegistry& registry, const QString& type,
                                             const QVariant& value, const RosEncodeLimits& limits)
{
    return encodeWith(registry, type, value, limits, false);
}

Result<QByteArray> RosMessageEncoder::encodeCdr(const RosTypeRegistry& registry, const QString& type,
                                                const QVariant& value, const RosEncodeLimits& limits)
{
    const QString name
        = registry.dialect() == RosTypeRegistry::Dialect::Ros2 ? RosTypeRegistry::ros2TypeName(type) : type;
    return encodeWith(registry, name, value, limits, true);
}

namespace {

QString quotedText(const QString& s)
{
    QString out = u"\""_s;
    for (QChar c : s) {
        if (c == u'"' || c == u'\\')
            out += u'\\' + QString(c);
        else if (c == u'\n')
            out += u"\\n"_s;
        else if (c == u'\t')
            out += u"\\t"_s;
        else if (c.unicode() < 0x20 || c.unicode() == 0x7f || c.unicode() == 0xfeff
                 || (c.unicode() >= 0x80 && c.unicode() < 0xa0) || c.unicode() == 0x2028
                 || c.unicode() == 0x2029)
            out += u"\\u%1"_s.arg(uint(c.unicode()), 4, 16, QChar(u'0'));
        else
            out += c;
    }
    return out + u'"';
}

// Field names are whatever a definition says; a name that is not a plain identifier is quoted.
QString keyText(const QString& name)
{
    const bool plain = !name.isEmpty() && std::all_of(name.cbegin(), name.cend(), [](QChar c) {
        return c == u'_' || (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z') || (c >= u'0' && c <= u'9');
    });
    return plain ? name : quotedText(name);
}

QString scalarText(const RosValue& v)
{
    if (v.type == u"string"_s || v.type == u"time"_s || v.type == u"duration"_s)
        return quotedText(v.value.toString());
    if (v.type == u"bool"_s)
        return v.value.toBool() ? u"true"_s : u"false"_s;
    if (v.type == u"float32"_s || v.type == u"float64"_s) {
        const double d = v.value.toDouble();
        if (std::isnan(d))
            return u".nan"_s;
        if (std::isinf(d))
            return d < 0 ? u"-.inf"_s : u".inf"_s;
        return QString::number(d, 'g', QLocale::FloatingPointShortest);
    }
    return v.value.toString();
}

struct YamlWriter
{
    QString out;
    bool cut = false;

    void fields(const RosValue& message, int indent, const QString& firstPad)
    {
        if (message.children.isEmpty()) {
            out += firstPad + u"{}\n"_s;
            return;
        }
        bool first = true;
        QSet<QString> names; // a definition may repeat a name, which no map can hold
        for (const RosValue& c : message.children) {
            cut = cut || names.contains(c.name);
            names.insert(c.name);
            field(c, first ? firstPad : QString(indent, u' '), indent);
            first = false;
        }
    }

    void field(const RosValue& v, const QString& pad, int indent)
    {
        cut = cut || v.truncated;
        // YAML reads a key of at most 1024 characters as written (a quoted control character is
        // six): a longer one is no map's (found by fuzzing), so the YAML is declined as a whole.
        const QString name = keyText(v.name);
        cut = cut || name.toUtf8().size() > 1000; // yaml-cpp counts bytes
        const QString key = pad + name + u':';
        if (v.kind == RosValue::Scalar) {
            out += key + u' ' + scalarText(v) + u'\n';
        } else if (v.kind == RosValue::Message) {
            if (v.children.isEmpty()) {
                out += key + u" {}\n"_s;
            } else {
                out += key + u'\n';
                fields(v, indent + 2, QString(indent + 2, u' '));
            }
        } else if (v.value.isValid()) { // bytes, as the decoder's hex
            QStringList items;
            const bool signedBytes = v.type.startsWith(u"int8"_s) || v.type.startsWith(u"byte"_s);
            for (char c : QByteArray::fromHex(v.value.toByteArray()))
                items << QString::number(signedBytes ? int(qint8(c)) : int(uchar(c)));
            out += key + u" ["_s + items.join(u", "_s) + u"]\n"_s;
        } else if (v.children.isEmpty() || v.children.first().kind == RosValue::Scalar) {
            QStringList items;
            for (const RosValue& e : v.children)
                items << scalarText(e);
            out += key + u" ["_s + items.join(u", "_s) + u"]\n"_s;
        } else {
            out += key + u'\n';
            for (const RosValue& e : v.children) {
                cut = cut || e.truncated;
                fields(e, indent + 4, QString(indent + 2, u' ') + u"- "_s);
            }
        }
    }
};

} // namespace

std::optional<QString> RosMessageEncoder::toYaml(const RosValue& message)
{
    YamlWriter w;
    if (message.kind != RosValue::Message)
        return std::nullopt;
    w.fields(message, 0, QString());
    if (w.cut)
        return std::nullopt;
    return w.out;
}

Result<RosValue> RosMessageEncoder::zeroValue(const RosTypeRegistry& registry, const QString& type)
{
    const Result<QByteArray> bytes = encode(registry, type, QVariant());
    if (!bytes)
        return bytes.error();
    RosDecodeLimits limits;
    limits.maxArrayElements = 4096;
    return RosMessageDecoder::decode(registry, type, *bytes, limits);
}
