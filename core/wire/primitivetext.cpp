// SPDX-License-Identifier: MIT
#include "primitivetext.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <locale.h>

namespace PrimitiveText {

namespace {

/// mqtt_client runs in the C locale; this program may not (QCoreApplication sets the user's).
locale_t cLocale()
{
    static const locale_t c = newlocale(LC_ALL_MASK, "C", locale_t(nullptr));
    return c;
}

enum class Kind { None, String, Bool, Unsigned, Signed, Float32, Float64, Bytes };

struct Shape
{
    Kind kind = Kind::None;
    int width = 0; ///< bytes of a number
};

/// The primitive a std_msgs type name ("Int32", after the package) is.
Shape shapeOf(QStringView name)
{
    static const struct
    {
        QStringView name;
        Shape shape;
    } kShapes[] {
        {u"String", {Kind::String, 0}},         {u"Bool", {Kind::Bool, 1}},
        {u"Char", {Kind::Unsigned, 1}},         {u"Byte", {Kind::Unsigned, 1}},
        {u"UInt8", {Kind::Unsigned, 1}},        {u"UInt16", {Kind::Unsigned, 2}},
        {u"UInt32", {Kind::Unsigned, 4}},       {u"UInt64", {Kind::Unsigned, 8}},
        {u"Int8", {Kind::Signed, 1}},           {u"Int16", {Kind::Signed, 2}},
        {u"Int32", {Kind::Signed, 4}},          {u"Int64", {Kind::Signed, 8}},
        {u"Float32", {Kind::Float32, 4}},       {u"Float64", {Kind::Float64, 8}},
        {u"UInt8MultiArray", {Kind::Bytes, 0}},
    };
    for (const auto& s : kShapes)
        if (s.name == name)
            return s.shape;
    return {};
}

/// Reads a message's fields in its byte order, with CDR's alignment when `base` >= 0 (alignment is
/// counted from the end of the encapsulation header); every read is checked against the end.
class Reader
{
public:
    Reader(QByteArrayView bytes, qsizetype at, bool little, qsizetype base)
        : m_bytes(bytes)
        , m_at(at)
        , m_little(little)
        , m_base(base)
    { }

    std::optional<quint64> number(int width)
    {
        if (m_base >= 0)
            m_at += (width - (m_at - m_base) % width) % width;
        if (m_at < 0 || m_bytes.size() - m_at < width)
            return std::nullopt;
        quint64 v = 0;
        for (int i = 0; i < width; ++i) {
            const quint64 b = quint8(m_bytes[m_at + (m_little ? i : width - 1 - i)]);
            v |= b << (8 * i);
        }
        m_at += width;
        return v;
    }

    std::optional<QByteArrayView> bytes(quint64 count)
    {
        if (m_at < 0 || quint64(m_bytes.size() - m_at) < count)
            return std::nullopt;
        const QByteArrayView out = m_bytes.sliced(m_at, qsizetype(count));
        m_at += qsizetype(count);
        return out;
    }

    /// A string: ROS 1 its length and characters, CDR its length with the NUL and the NUL.
    std::optional<QByteArrayView> string()
    {
        const auto n = number(4);
        if (!n)
            return std::nullopt;
        const auto chars = bytes(*n);
        if (!chars || m_base < 0)
            return chars;
        if (chars->isEmpty() || chars->back() != '\0')
            return std::nullopt;
        return chars->chopped(1);
    }

    bool atEnd() const { return m_at == m_bytes.size(); }

private:
    QByteArrayView m_bytes;
    qsizetype m_at = 0;
    bool m_little = true;
    qsizetype m_base = -1;
};

std::optional<QByteArray> numberText(Reader& r, Shape s)
{
    const auto raw = r.number(s.width);
    if (!raw)
        return std::nullopt;
    switch (s.kind) {
    case Kind::Bool:
        return *raw ? QByteArray("true") : QByteArray("false");
    case Kind::Unsigned:
        return QByteArray::number(*raw);
    case Kind::Signed: {
        const int shift = 64 - 8 * s.width;
        return QByteArray::number(qint64(*raw << shift) >> shift);
    }
    case Kind::Float32: {
        float f = 0;
        const quint32 bits = quint32(*raw);
        std::memcpy(&f, &bits, sizeof f);
        return fixed(double(f));
    }
    case Kind::Float64: {
        double d = 0;
        std::memcpy(&d, &*raw, sizeof d);
        return fixed(d);
    }
    default:
        return std::nullopt;
    }
}

/// std_msgs/UInt8MultiArray: its layout (dimensions: label, size, stride; data offset), then data.
std::optional<QByteArray> multiArrayData(Reader& r)
{
    const auto dims = r.number(4);
    if (!dims)
        return std::nullopt;
    for (quint64 i = 0; i < *dims; ++i) // each reads at least 12 bytes: bounded by the message's size
        if (!r.string() || !r.number(4) || !r.number(4))
            return std::nullopt;
    if (!r.number(4))
        return std::nullopt;
    const auto count = r.number(4);
    const auto data = count ? r.bytes(*count) : std::nullopt;
    return data ? std::optional<QByteArray>(data->toByteArray()) : std::nullopt;
}

std::optional<QByteArray> textOf(Reader& r, Shape s)
{
    std::optional<QByteArray> text;
    if (s.kind == Kind::String) {
        if (const auto v = r.string())
            text = v->toByteArray();
    } else if (s.kind == Kind::Bytes) {
        text = multiArrayData(r);
    } else {
        text = numberText(r, s);
    }
    return text;
}

} // namespace

QByteArray fixed(double v)
{
    char text[400]; // "%f" of the largest double: 309 digits, the point and six more
    const locale_t before = uselocale(cLocale());
    const int n = std::snprintf(text, sizeof text, "%f", v);
    uselocale(before);
    return QByteArray(text, n > 0 ? std::min(n, int(sizeof text) - 1) : 0);
}

std::optional<QByteArray> ofRos1(QStringView type, QByteArrayView bytes)
{
    if (!type.startsWith(u"std_msgs/"))
        return std::nullopt;
    const QStringView name = type.mid(9);
    const Shape s = shapeOf(name);
    // mqtt_client for ROS 1 knows neither byte arrays nor std_msgs/Byte (and its byte is signed)
    if (s.kind == Kind::None || s.kind == Kind::Bytes || name == u"Byte")
        return std::nullopt;
    Reader r(bytes, 0, true, -1);
    std::optional<QByteArray> text = textOf(r, s);
    return text && r.atEnd() ? text : std::nullopt;
}

std::optional<QByteArray> ofCdr(QStringView type, QByteArrayView cdr)
{
    if (!type.startsWith(u"std_msgs/msg/") || cdr.size() < 4 || cdr[0] != 0 || (cdr[1] != 0 && cdr[1] != 1))
        return std::nullopt;
    const Shape s = shapeOf(type.mid(13));
    if (s.kind == Kind::None)
        return std::nullopt;
    Reader r(cdr, 4, cdr[1] == 1, 4);
    std::optional<QByteArray> text = textOf(r, s);
    // CDR pads a message to 4 bytes (or its largest alignment): what follows the value is padding.
    return text;
}

Parsed parse(QByteArrayView payload)
{
    Parsed p;
    if (qstrnicmp(payload.data(), payload.size(), "true") == 0
        || qstrnicmp(payload.data(), payload.size(), "false") == 0) {
        p.kind = Parsed::Kind::Bool;
        p.boolean = payload.size() == 4;
        return p;
    }
    // std::stoi and std::stof over a C string: a NUL ends it, and the text must be used whole.
    // Neither reads a text whose first character after white space cannot start a number (most
    // payloads a watch sees: it reads them all, without copying them).
    qsizetype first = 0;
    while (first < payload.size() && std::strchr(" \t\n\v\f\r", payload[first]) && payload[first] != '\0')
        ++first;
    if (first == payload.size() || !std::strchr("+-.0123456789iInN", payload[first]) || payload[first] == '\0'
        || std::memchr(payload.data(), '\0', size_t(payload.size())))
        return p;
    char small[kMaxRoundTripBytes + 1];
    std::string large;
    const char* begin = small;
    if (payload.size() <= kMaxRoundTripBytes) {
        std::memcpy(small, payload.data(), size_t(payload.size()));
        small[payload.size()] = '\0';
    } else {
        large.assign(payload.data(), size_t(payload.size()));
        begin = large.c_str();
    }
    const char* const whole = begin + payload.size();
    char* end = nullptr;
    errno = 0;
    const long i = std::strtol(begin, &end, 10);
    if (end == whole && errno == 0 && i >= std::numeric_limits<qint32>::min()
        && i <= std::numeric_limits<qint32>::max()) {
        p.kind = Parsed::Kind::Int32;
        p.integer = qint32(i);
        return p;
    }
    errno = 0;
    const float f = strtof_l(begin, &end, cLocale());
    if (end == whole && errno == 0) {
        p.kind = Parsed::Kind::Float32;
        p.real = f;
    }
    return p;
}

std::optional<QByteArray> roundTripChanged(QByteArrayView payload)
{
    if (payload.size() > kMaxRoundTripBytes)
        return std::nullopt;
    const Parsed p = parse(payload);
    QByteArray text;
    switch (p.kind) {
    case Parsed::Kind::Bool:
        text = p.boolean ? QByteArray("true") : QByteArray("false");
        break;
    case Parsed::Kind::Int32:
        text = QByteArray::number(p.integer);
        break;
    case Parsed::Kind::Float32:
        text = fixed(double(p.real));
        break;
    case Parsed::Kind::String:
        return std::nullopt;
    }
    return text == payload ? std::nullopt : std::optional<QByteArray>(std::move(text));
}

QByteArray roundTrip(QByteArrayView payload)
{
    return roundTripChanged(payload).value_or(payload.toByteArray());
}

} // namespace PrimitiveText
