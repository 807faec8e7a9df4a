// SPDX-License-Identifier: MIT
#include "rosmessage.h"

#include "text/exactutf8.h"

#include <algorithm>
#include <cstring>
#include <QRegularExpression>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace {

const QStringList& builtins()
{
    static const QStringList list
        = {u"bool"_s,    u"int8"_s,   u"uint8"_s,  u"byte"_s,    u"char"_s,   u"int16"_s,
           u"uint16"_s,  u"int32"_s,  u"uint32"_s, u"int64"_s,   u"uint64"_s, u"float32"_s,
           u"float64"_s, u"string"_s, u"time"_s,   u"duration"_s};
    return list;
}

QString packageOf(const QString& type)
{
    const int slash = type.indexOf(u'/');
    return slash < 0 ? QString() : type.left(slash);
}

// Resolves a field's type name as ROS does: builtins stay, "Header" is std_msgs/Header, a bare
// name belongs to the package of the message that uses it. ROS 2: every message type is
// pkg/msg/Type, and Header is no shorthand.
QString resolveType(const QString& name, const QString& package, RosTypeRegistry::Dialect dialect)
{
    if (dialect == RosTypeRegistry::Dialect::Ros2) {
        if (RosTypeRegistry::isBuiltin(name) || name == u"wstring"_s)
            return name;
        if (name.contains(u'/'))
            return RosTypeRegistry::ros2TypeName(name);
        return package.isEmpty() ? name : package + u"/msg/"_s + name;
    }
    if (RosTypeRegistry::isBuiltin(name))
        return name;
    if (name == u"Header"_s)
        return u"std_msgs/Header"_s;
    if (name.contains(u'/'))
        return name;
    return package.isEmpty() ? name : package + u'/' + name;
}

bool isSeparator(const QString& line)
{
    return line.size() >= 3 && line.count(u'=') == line.size();
}

/// Type nesting followed when sizing a type; deeper definitions are sized conservatively (not
/// fixed, no minimum) and left to the decoder's own depth limit, so a hostile chain of 100,000
/// dependencies cannot exhaust the stack.
constexpr int kMaxTypeDepth = 64;
constexpr int kMaxFieldName = 256;

qint64 saturatedAdd(qint64 a, qint64 b)
{
    // Both are at most kHugeSize (2^62), but their sum may pass 2^63 (found by fuzz_rosmessage).
    return a > RosTypeRegistry::kHugeSize - b ? RosTypeRegistry::kHugeSize : a + b;
}

qint64 saturatedMul(qint64 a, qint64 b)
{
    if (a == 0 || b == 0)
        return 0;
    return a > RosTypeRegistry::kHugeSize / b ? RosTypeRegistry::kHugeSize : a * b;
}

thread_local qint64 t_lastSteps = 0;

} // namespace

QString RosTypeRegistry::ros2TypeName(const QString& name)
{
    const QStringList parts = name.split(u'/');
    if (parts.size() == 2 && !parts[0].isEmpty() && !parts[1].isEmpty())
        return parts[0] + u"/msg/"_s + parts[1];
    return name;
}

bool RosTypeRegistry::isBuiltin(const QString& type)
{
    return builtins().contains(type);
}

int RosTypeRegistry::builtinSize(const QString& type)
{
    if (type == u"bool"_s || type == u"int8"_s || type == u"uint8"_s || type == u"byte"_s
        || type == u"char"_s)
        return 1;
    if (type == u"int16"_s || type == u"uint16"_s)
        return 2;
    if (type == u"int32"_s || type == u"uint32"_s || type == u"float32"_s)
        return 4;
    if (type == u"int64"_s || type == u"uint64"_s || type == u"float64"_s || type == u"time"_s
        || type == u"duration"_s)
        return 8;
    return -1;
}

Result<void> RosTypeRegistry::addDefinition(const QString& type, const QString& definition)
{
    const bool ros2 = m_dialect == Dialect::Ros2;
    QString current = ros2 ? ros2TypeName(type) : type;
    RosMessageType msg;
    msg.name = current;
    QHash<QString, RosMessageType> parsed;
    const QStringList lines = definition.split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i].trimmed();
        if (isSeparator(line)) {
            parsed.insert(msg.name, msg);
            // Next non-empty line names the dependency: "MSG: pkg/Type".
            while (i + 1 < lines.size() && lines[i + 1].trimmed().isEmpty())
                ++i;
            if (i + 1 >= lines.size() || !lines[i + 1].trimmed().startsWith(u"MSG:"_s))
                return LocatedError {
                    tr("line %1: expected 'MSG: package/Type' after the separator").arg(i + 2)};
            ++i;
            current = lines[i].trimmed().mid(4).trimmed();
            if (ros2)
                current = ros2TypeName(current);
            msg = RosMessageType();
            msg.name = current;
            continue;
        }
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        static const QRegularExpression whitespace(u"\\s"_s);
        const int space = line.indexOf(whitespace);
        if (space < 0)
            return LocatedError {tr("line %1: '%2' is not 'type name'").arg(i + 1).arg(line)};
        QString typeToken = line.left(space);
        QString rest = line.mid(space + 1).trimmed();
        const int eq = rest.indexOf(u'=');
        const int hash = rest.indexOf(u'#');
        if (eq >= 0 && (hash < 0 || eq < hash))
            continue; // a constant: not serialized
        if (hash >= 0)
            rest = rest.left(hash).trimmed();
        RosField field;
        field.name = rest.section(whitespace, 0, 0);
        const int bracket = typeToken.indexOf(u'[');
        if (bracket >= 0) {
            field.isArray = true;
            QString len = typeToken.mid(bracket + 1, typeToken.size() - bracket - 2);
            // ROS 2's bounded sequence (T[<=5]) is a sequence on the wire: its bound is not kept.
            const bool bounded = ros2 && len.startsWith(u"<="_s);
            if (bounded)
                len = len.mid(2);
            // Digits only (no sign, no space), at most a uint32 as on the wire.
            bool ok = std::all_of(len.cbegin(), len.cend(), [](QChar c) { return c >= u'0' && c <= u'9'; });
            const qulonglong fixed = len.isEmpty() || !ok ? 0 : len.toULongLong(&ok);
            ok = ok && fixed <= 0xffffffffULL;
            field.fixedLength = len.isEmpty() || bounded ? -1 : qint64(fixed);
            if (!ok || !typeToken.endsWith(u']') || (bounded && len.isEmpty()))
                return LocatedError {tr("line %1: bad array type '%2'").arg(i + 1).arg(typeToken)};
            typeToken = typeToken.left(bracket);
        }
        // ROS 2's bounded string (string<=10): a string on the wire.
        if (ros2 && (typeToken.startsWith(u"string<="_s) || typeToken.startsWith(u"wstring<="_s)))
            typeToken = typeToken.left(typeToken.indexOf(u'<'));
        field.type = resolveType(typeToken, packageOf(current), m_dialect);
        if (field.name.isEmpty())
            return LocatedError {tr("line %1: field without a name").arg(i + 1)};
        // ROS names are identifiers; a hostile one of thousands of characters would also pass
        // YAML's 1024-character limit for a key when the message is edited (found by fuzzing).
        if (field.name.size() > kMaxFieldName)
            return LocatedError {tr("line %1: a field name of %2 characters (at most %3)")
                                     .arg(i + 1)
                                     .arg(field.name.size())
                                     .arg(kMaxFieldName)};
        msg.fields.append(field);
    }
    parsed.insert(msg.name, msg);
    for (auto it = parsed.cbegin(); it != parsed.cend(); ++it)
        m_types.insert(it.key(), it.value());
    m_fixedSizes.clear();
    m_minSizes.clear();
    return {};
}

const RosMessageType* RosTypeRegistry::find(const QString& type) const
{
    const auto it = m_types.constFind(type);
    return it == m_types.cend() ? nullptr : &*it;
}

qint64 RosTypeRegistry::fixedSize(const QString& type) const
{
    return fixedSize(type, 0);
}

qint64 RosTypeRegistry::fixedSize(const QString& type, int depth) const
{
    if (isBuiltin(type))
        return builtinSize(type);
    const auto cached = m_fixedSizes.constFind(type);
    if (cached != m_fixedSizes.cend())
        return *cached;
    if (depth > kMaxTypeDepth)
        return -1;
    m_fixedSizes.insert(type, -1); // guards against recursive definitions
    const RosMessageType* msg = find(type);
    qint64 total = msg ? 0 : -1;
    for (qsizetype i = 0; msg && i < msg->fields.size() && total >= 0; ++i) {
        const RosField& f = msg->fields[i];
        if (f.isArray && f.fixedLength < 0) {
            total = -1;
            break;
        }
        if (f.isArray && f.fixedLength == 0)
            continue; // no bytes whatever the element (even "string[0]")
        const qint64 element = fixedSize(f.type, depth + 1);
        total = element < 0 ? -1 : saturatedAdd(total, saturatedMul(element, f.isArray ? f.fixedLength : 1));
    }
    m_fixedSizes.insert(type, total);
    return total;
}

qint64 RosTypeRegistry::minSize(const QString& type) const
{
    return minSize(type, 0);
}

qint64 RosTypeRegistry::minSize(const QString& type, int depth) const
{
    if (type == u"string"_s)
        return 4;
    if (isBuiltin(type))
        return builtinSize(type);
    const auto cached = m_minSizes.constFind(type);
    if (cached != m_minSizes.cend())
        return *cached;
    const RosMessageType* msg = find(type);
    if (!msg || depth > kMaxTypeDepth)
        return 0; // unknown: the decoder reports it; too deep: no claim
    // A type met again while sizing itself contains itself unconditionally: no finite value.
    m_minSizes.insert(type, kHugeSize);
    qint64 total = 0;
    for (const RosField& f : msg->fields) {
        if (f.isArray && f.fixedLength < 0)
            total = saturatedAdd(total, 4); // the length; zero elements may follow
        else if (!f.isArray || f.fixedLength > 0)
            total = saturatedAdd(total,
                                 saturatedMul(minSize(f.type, depth + 1), f.isArray ? f.fixedLength : 1));
    }
    m_minSizes.insert(type, total);
    return total;
}

QString rosTimeText(qint64 sec, qint64 nsec)
{
    const bool negative = sec < 0 || nsec < 0;
    const qint64 total = sec * 1000000000LL + nsec;
    const quint64 magnitude = quint64(negative ? -total : total);
    return (negative ? u"-"_s : QString()) + QString::number(magnitude / 1000000000ULL) + u'.'
        + QString::number(magnitude % 1000000000ULL).rightJustified(9, u'0');
}

namespace {

struct DecodeError
{
    QString message;
};

class Reader
{
    Q_DECLARE_TR_FUNCTIONS(RosMessageDecoder)
public:
    Reader(const RosTypeRegistry& reg, const QByteArray& data, const RosDecodeLimits& limits)
        : m_reg(reg)
        , m_data(reinterpret_cast<const uchar*>(data.constData()))
        , m_size(data.size())
        , m_limits(limits)
    { }

    /// CDR from here on: values aligned to their size from `origin` (where the data after the
    /// encapsulation header begins), in the given byte order.
    void useCdr(qsizetype origin, bool bigEndian)
    {
        m_cdr = true;
        m_origin = origin;
        m_bigEndian = bigEndian;
    }

    // CDR puts a value of n bytes (n = 2, 4, 8) at a multiple of n from the origin.
    void align(int n)
    {
        if (!m_cdr || n <= 1)
            return;
        const qsizetype offset = (m_pos - m_origin) % n;
        if (offset)
            need(n - offset, tr("padding"));
    }

    template<typename T> T number(const uchar* p) const
    {
        return m_bigEndian ? qFromBigEndian<T>(p) : qFromLittleEndian<T>(p);
    }

    qsizetype pos() const { return m_pos; }
    qsizetype size() const { return m_size; }

    [[noreturn]] void fail(const QString& what) const
    {
        throw DecodeError {tr("byte %1: %2").arg(m_pos).arg(what)};
    }

    const uchar* need(qsizetype n, const QString& field)
    {
        if (n < 0 || n > m_size - m_pos)
            fail(tr("the message ends while reading '%1' (needs %2 more bytes, %3 left)")
                     .arg(field)
                     .arg(n)
                     .arg(m_size - m_pos));
        const uchar* p = m_data + m_pos;
        m_pos += n;
        return p;
    }

    quint32 length(const QString& field)
    {
        align(4);
        return number<quint32>(need(4, field));
    }

    QVariant builtin(const QString& type, const QString& field, bool* truncated)
    {
        if (type == u"string"_s) {
            const quint32 n = length(field);
            const uchar* p = need(qsizetype(n), field);
            // CDR counts the terminating NUL; it is no part of the text.
            const qsizetype text = m_cdr && n > 0 && p[n - 1] == 0 ? qsizetype(n) - 1 : qsizetype(n);
            const qsizetype shown = std::min<qsizetype>(text, m_limits.maxStringChars);
            *truncated = shown < text;
            return exactUtf8(reinterpret_cast<const char*>(p), shown);
        }
        const int size = RosTypeRegistry::builtinSize(type);
        if (size < 0)
            fail(tr("unknown type '%1'").arg(type));
        align(type == u"time"_s || type == u"duration"_s ? 4 : size);
        const uchar* p = need(size, field);
        if (type == u"bool"_s)
            return p[0] != 0;
        if (type == u"uint8"_s || type == u"char"_s)
            return uint(p[0]);
        if (type == u"int8"_s || type == u"byte"_s)
            return int(qint8(p[0]));
        if (type == u"uint16"_s)
            return uint(number<quint16>(p));
        if (type == u"int16"_s)
            return int(number<qint16>(p));
        if (type == u"uint32"_s)
            return uint(number<quint32>(p));
        if (type == u"int32"_s)
            return int(number<qint32>(p));
        if (type == u"uint64"_s)
            return qulonglong(number<quint64>(p));
        if (type == u"int64"_s)
            return qlonglong(number<qint64>(p));
        if (type == u"float32"_s)
            return double(number<float>(p));
        if (type == u"float64"_s)
            return number<double>(p);
        if (type == u"time"_s)
            return rosTimeText(number<quint32>(p), number<quint32>(p + 4));
        if (type == u"duration"_s)
            return rosTimeText(number<qint32>(p), number<qint32>(p + 4));
        fail(tr("unknown type '%1'").arg(type));
    }

    qint64 steps() const { return m_steps; }

    // One field or array element visited: the work budget that no definition or length can
    // stretch (elements that take no bytes would otherwise cost nothing to claim).
    void step()
    {
        if (++m_steps > m_limits.maxSteps)
            fail(tr("more than %1 steps (fields and array elements): too much work for one message")
                     .arg(m_limits.maxSteps));
    }

    // An array of n elements, each at least `element` bytes, must fit in what is left: a hostile
    // length fails here at once instead of after n tries.
    void checkCount(quint64 n, const QString& type, const QString& field)
    {
        const qint64 element = m_reg.minSize(type);
        if (element > 0 && saturatedMul(qint64(n), element) > m_size - m_pos)
            fail(tr("'%1' claims %2 elements of at least %3 bytes, but only %4 bytes are left")
                     .arg(field)
                     .arg(n)
                     .arg(element)
                     .arg(m_size - m_pos));
    }

    // Moves over n values of one type without building them.
    void skipElements(quint64 n, const QString& type, const QString& field, int depth)
    {
        if (n == 0)
            return;
        // In CDR only a builtin's size is fixed: a message's padding depends on where it starts.
        const qint64 element = m_cdr && !RosTypeRegistry::isBuiltin(type) ? -1 : m_reg.fixedSize(type);
        if (element >= 0) {
            if (m_cdr)
                align(type == u"time"_s || type == u"duration"_s ? 4 : int(element));
            need(saturatedMul(qint64(n), element), field); // also elements of no bytes: no loop
            return;
        }
        checkCount(n, type, field);
        for (quint64 i = 0; i < n; ++i)
            skip(type, field, depth);
    }

    // Moves over one value without building it.
    void skip(const QString& type, const QString& field, int depth)
    {
        step();
        if (depth > m_limits.maxDepth)
            fail(tr("nested deeper than %1 levels").arg(m_limits.maxDepth));
        const qint64 fixed = m_cdr && !RosTypeRegistry::isBuiltin(type) ? -1 : m_reg.fixedSize(type);
        if (fixed >= 0) {
            if (m_cdr)
                align(type == u"time"_s || type == u"duration"_s ? 4 : int(fixed));
            need(fixed, field);
            return;
        }
        if (type == u"wstring"_s)
            fail(tr("'%1' is a wstring, which is not decoded").arg(field));
        if (type == u"string"_s) {
            need(qsizetype(length(field)), field);
            return;
        }
        const RosMessageType* msg = m_reg.find(type);
        if (!msg)
            fail(tr("no definition for '%1'").arg(type));
        if (m_cdr && msg->fields.isEmpty())
            need(1, field);
        for (const RosField& f : msg->fields) {
            if (!f.isArray) {
                skip(f.type, f.name, depth + 1);
                continue;
            }
            step();
            const quint64 n = f.fixedLength >= 0 ? quint64(f.fixedLength) : length(f.name);
            skipElements(n, f.type, f.name, depth + 1);
        }
    }

    // One value built: bounded apart from the steps, as 16 shown elements per level of nested
    // arrays of empty messages are 16^depth values from no bytes at all.
    void built()
    {
        step();
        if (++m_values > m_limits.maxValues)
            fail(tr("more than %1 values to show: too much work for one message").arg(m_limits.maxValues));
    }

    RosValue value(const QString& name, const QString& type, int depth)
    {
        built();
        if (depth > m_limits.maxDepth)
            fail(tr("nested deeper than %1 levels").arg(m_limits.maxDepth));
        RosValue v;
        v.name = name;
        v.type = type;
        if (RosTypeRegistry::isBuiltin(type)) {
            v.value = builtin(type, name, &v.truncated);
            return v;
        }
        if (type == u"wstring"_s)
            fail(tr("'%1' is a wstring, which is not decoded").arg(name));
        const RosMessageType* msg = m_reg.find(type);
        if (!msg)
            fail(tr("no definition for '%1'").arg(type));
        v.kind = RosValue::Message;
        if (m_cdr && msg->fields.isEmpty())
            need(1,
                 name); // rosidl gives a message of no fields one uint8 (structure_needs_at_least_one_field)
        for (const RosField& f : msg->fields) {
            if (f.isArray)
                v.children.append(array(f, depth + 1));
            else
                v.children.append(value(f.name, f.type, depth + 1));
        }
        return v;
    }

    RosValue array(const RosField& f, int depth)
    {
        built();
        RosValue v;
        v.name = f.name;
        v.type = f.type + (f.fixedLength >= 0 ? u"[%1]"_s.arg(f.fixedLength) : u"[]"_s);
        v.kind = RosValue::Array;
        const quint32 n = f.fixedLength >= 0 ? quint32(f.fixedLength) : length(f.name);
        v.arrayLength = n;
        const bool bytes
            = f.type == u"uint8"_s || f.type == u"int8"_s || f.type == u"char"_s || f.type == u"byte"_s;
        if (bytes) {
            // Binary blobs (point clouds, images, packets): a size and a hex preview.
            const uchar* p = need(qsizetype(n), f.name);
            const qsizetype shown = std::min<qsizetype>(n, m_limits.maxArrayElements);
            v.value = QByteArray(reinterpret_cast<const char*>(p), shown).toHex(' ');
            v.truncated = shown < qsizetype(n);
            return v;
        }
        checkCount(n, f.type, f.name);
        const quint32 shown = std::min<quint32>(n, quint32(std::max(0, m_limits.maxArrayElements)));
        for (quint32 i = 0; i < shown; ++i)
            v.children.append(value(u"[%1]"_s.arg(i), f.type, depth + 1));
        if (shown < n) {
            v.truncated = true;
            skipElements(n - shown, f.type, f.name, depth + 1);
        }
        return v;
    }

private:
    const RosTypeRegistry& m_reg;
    const uchar* m_data;
    qsizetype m_size;
    qsizetype m_pos = 0;
    RosDecodeLimits m_limits;
    bool m_cdr = false;
    bool m_bigEndian = false;
    qsizetype m_origin = 0;
    qint64 m_steps = 0;
    qint64 m_values = 0;
};

} // namespace

namespace {
Result<RosValue> decodeWith(const RosTypeRegistry& registry, const QString& type, const QByteArray& data,
                            const RosDecodeLimits& limits, bool cdr);
} // namespace

Result<RosValue> RosMessageDecoder::decode(const RosTypeRegistry& registry, const QString& type,
                                           const QByteArray& data, const RosDecodeLimits& limits)
{
    return decodeWith(registry, type, data, limits, false);
}

Result<RosValue> RosMessageDecoder::decodeCdr(const RosTypeRegistry& registry, const QString& type,
                                              const QByteArray& data, const RosDecodeLimits& limits)
{
    const QString name
        = registry.dialect() == RosTypeRegistry::Dialect::Ros2 ? RosTypeRegistry::ros2TypeName(type) : type;
    return decodeWith(registry, name, data, limits, true);
}

namespace {
Result<RosValue> decodeWith(const RosTypeRegistry& registry, const QString& type, const QByteArray& data,
                            const RosDecodeLimits& limits, bool cdr)
{
    t_lastSteps = 0;
    if (data.size() > limits.maxBytes)
        return LocatedError {
            RosMessageDecoder::tr("the message has %1 bytes, more than the %2 bytes one message may have")
                .arg(data.size())
                .arg(limits.maxBytes)};
    Reader reader(registry, data, limits);
    try {
        if (cdr) {
            // The encapsulation header: 0x00 0x01 little-endian CDR, 0x00 0x00 big-endian; two
            // bytes of options. XCDR2 and parameter lists are not what ROS 2 sends.
            const uchar* header = reader.need(4, RosMessageDecoder::tr("the CDR encapsulation header"));
            if (header[0] != 0 || header[1] > 1)
                reader.fail(RosMessageDecoder::tr("not plain CDR (encapsulation %1 %2)")
                                .arg(header[0], 2, 16, QLatin1Char('0'))
                                .arg(header[1], 2, 16, QLatin1Char('0')));
            reader.useCdr(4, header[1] == 0);
        }
        RosValue root = reader.value(QString(), type, 0);
        t_lastSteps = reader.steps();
        // CDR writers pad the message to a multiple of 4 bytes.
        const qsizetype slack = cdr ? std::min<qsizetype>(3, reader.size() - reader.pos()) : 0;
        if (reader.pos() + slack != reader.size())
            return LocatedError {RosMessageDecoder::tr("%1 bytes left over after the message")
                                     .arg(reader.size() - reader.pos())};
        return root;
    } catch (const DecodeError& e) {
        t_lastSteps = reader.steps();
        return LocatedError {e.message};
    }
}
} // namespace

qint64 RosMessageDecoder::lastSteps()
{
    return t_lastSteps;
}

QStringList RosValue::toLines(int indent) const
{
    QStringList out;
    const QString pad(indent, u' ');
    const QString label = name.isEmpty() ? QString() : name + u':';
    switch (kind) {
    case Scalar: {
        QString text = value.toString();
        if (type == u"string"_s)
            text = u'"' + text + (truncated ? u"…\""_s : u"\""_s);
        out << pad + label + u' ' + text;
        break;
    }
    case Message:
        if (!label.isEmpty())
            out << pad + label;
        for (const RosValue& c : children)
            out += c.toLines(name.isEmpty() ? indent : indent + 2);
        break;
    case Array:
        if (value.isValid()) {
            out << pad + label + u" [%1 bytes] "_s.arg(arrayLength) + value.toString()
                    + (truncated ? u" …"_s : QString());
        } else {
            out << pad + label + u" [%1]"_s.arg(arrayLength)
                    + (truncated ? u" (first %1 shown)"_s.arg(children.size()) : QString());
            for (const RosValue& c : children)
                out += c.toLines(indent + 2);
        }
        break;
    }
    return out;
}

const RosValue* RosValue::find(const QString& path) const
{
    const RosValue* node = this;
    for (const QString& part : path.split(u'.', Qt::SkipEmptyParts)) {
        const RosValue* next = nullptr;
        for (const RosValue& c : node->children) {
            if (c.name == part) {
                next = &c;
                break;
            }
        }
        if (!next)
            return nullptr;
        node = next;
    }
    return node;
}
