// SPDX-License-Identifier: MIT
#include "rosmessage.h"

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
// name belongs to the package of the message that uses it.
QString resolveType(const QString& name, const QString& package)
{
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

} // namespace

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

bool RosTypeRegistry::addDefinition(const QString& type, const QString& definition, QString* error)
{
    QString current = type;
    RosMessageType msg;
    msg.name = type;
    QHash<QString, RosMessageType> parsed;
    const QStringList lines = definition.split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i].trimmed();
        if (isSeparator(line)) {
            parsed.insert(msg.name, msg);
            // Next non-empty line names the dependency: "MSG: pkg/Type".
            while (i + 1 < lines.size() && lines[i + 1].trimmed().isEmpty())
                ++i;
            if (i + 1 >= lines.size() || !lines[i + 1].trimmed().startsWith(u"MSG:"_s)) {
                if (error)
                    *error = tr("line %1: expected 'MSG: package/Type' after the separator").arg(i + 2);
                return false;
            }
            ++i;
            current = lines[i].trimmed().mid(4).trimmed();
            msg = RosMessageType();
            msg.name = current;
            continue;
        }
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        static const QRegularExpression whitespace(u"\\s"_s);
        const int space = line.indexOf(whitespace);
        if (space < 0) {
            if (error)
                *error = tr("line %1: '%2' is not 'type name'").arg(i + 1).arg(line);
            return false;
        }
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
            const QString len = typeToken.mid(bracket + 1, typeToken.size() - bracket - 2);
            bool ok = true;
            field.fixedLength = len.isEmpty() ? -1 : len.toInt(&ok);
            if (!ok || !typeToken.endsWith(u']')) {
                if (error)
                    *error = tr("line %1: bad array type '%2'").arg(i + 1).arg(typeToken);
                return false;
            }
            typeToken = typeToken.left(bracket);
        }
        field.type = resolveType(typeToken, packageOf(current));
        if (field.name.isEmpty()) {
            if (error)
                *error = tr("line %1: field without a name").arg(i + 1);
            return false;
        }
        msg.fields.append(field);
    }
    parsed.insert(msg.name, msg);
    for (auto it = parsed.cbegin(); it != parsed.cend(); ++it)
        m_types.insert(it.key(), it.value());
    m_fixedSizes.clear();
    return true;
}

const RosMessageType* RosTypeRegistry::find(const QString& type) const
{
    const auto it = m_types.constFind(type);
    return it == m_types.cend() ? nullptr : &*it;
}

int RosTypeRegistry::fixedSize(const QString& type) const
{
    if (isBuiltin(type))
        return builtinSize(type);
    const auto cached = m_fixedSizes.constFind(type);
    if (cached != m_fixedSizes.cend())
        return *cached;
    m_fixedSizes.insert(type, -1); // guards against recursive definitions
    const RosMessageType* msg = find(type);
    int total = msg ? 0 : -1;
    for (int i = 0; msg && i < msg->fields.size() && total >= 0; ++i) {
        const RosField& f = msg->fields[i];
        if (f.isArray && f.fixedLength < 0) {
            total = -1;
            break;
        }
        const int element = fixedSize(f.type);
        total = element < 0 ? -1 : total + element * (f.isArray ? f.fixedLength : 1);
    }
    m_fixedSizes.insert(type, total);
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

    qsizetype pos() const { return m_pos; }
    qsizetype size() const { return m_size; }

    [[noreturn]] void fail(const QString& what) const
    {
        throw DecodeError {tr("byte %1: %2").arg(m_pos).arg(what)};
    }

    const uchar* need(qsizetype n, const QString& field)
    {
        if (n < 0 || m_pos + n > m_size)
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
        const quint32 n = qFromLittleEndian<quint32>(need(4, field));
        return n;
    }

    QVariant builtin(const QString& type, const QString& field, bool* truncated)
    {
        if (type == u"string"_s) {
            const quint32 n = length(field);
            const uchar* p = need(qsizetype(n), field);
            const qsizetype shown = std::min<qsizetype>(n, m_limits.maxStringChars);
            *truncated = shown < qsizetype(n);
            return QString::fromUtf8(reinterpret_cast<const char*>(p), shown);
        }
        const int size = RosTypeRegistry::builtinSize(type);
        const uchar* p = need(size, field);
        if (type == u"bool"_s)
            return p[0] != 0;
        if (type == u"uint8"_s || type == u"char"_s)
            return uint(p[0]);
        if (type == u"int8"_s || type == u"byte"_s)
            return int(qint8(p[0]));
        if (type == u"uint16"_s)
            return uint(qFromLittleEndian<quint16>(p));
        if (type == u"int16"_s)
            return int(qFromLittleEndian<qint16>(p));
        if (type == u"uint32"_s)
            return uint(qFromLittleEndian<quint32>(p));
        if (type == u"int32"_s)
            return int(qFromLittleEndian<qint32>(p));
        if (type == u"uint64"_s)
            return qulonglong(qFromLittleEndian<quint64>(p));
        if (type == u"int64"_s)
            return qlonglong(qFromLittleEndian<qint64>(p));
        if (type == u"float32"_s)
            return double(qFromLittleEndian<float>(p));
        if (type == u"float64"_s)
            return qFromLittleEndian<double>(p);
        if (type == u"time"_s)
            return rosTimeText(qFromLittleEndian<quint32>(p), qFromLittleEndian<quint32>(p + 4));
        if (type == u"duration"_s)
            return rosTimeText(qFromLittleEndian<qint32>(p), qFromLittleEndian<qint32>(p + 4));
        fail(tr("unknown type '%1'").arg(type));
    }

    // Moves over one value without building it.
    void skip(const QString& type, const QString& field, int depth)
    {
        if (depth > m_limits.maxDepth)
            fail(tr("nested deeper than %1 levels").arg(m_limits.maxDepth));
        const int fixed = m_reg.fixedSize(type);
        if (fixed >= 0) {
            need(fixed, field);
            return;
        }
        if (type == u"string"_s) {
            need(qsizetype(length(field)), field);
            return;
        }
        const RosMessageType* msg = m_reg.find(type);
        if (!msg)
            fail(tr("no definition for '%1'").arg(type));
        for (const RosField& f : msg->fields) {
            if (!f.isArray) {
                skip(f.type, f.name, depth + 1);
                continue;
            }
            const quint32 n = f.fixedLength >= 0 ? quint32(f.fixedLength) : length(f.name);
            const int element = m_reg.fixedSize(f.type);
            if (element >= 0) {
                need(qsizetype(n) * element, f.name);
            } else {
                for (quint32 i = 0; i < n; ++i)
                    skip(f.type, f.name, depth + 1);
            }
        }
    }

    RosValue value(const QString& name, const QString& type, int depth)
    {
        if (depth > m_limits.maxDepth)
            fail(tr("nested deeper than %1 levels").arg(m_limits.maxDepth));
        RosValue v;
        v.name = name;
        v.type = type;
        if (RosTypeRegistry::isBuiltin(type)) {
            v.value = builtin(type, name, &v.truncated);
            return v;
        }
        const RosMessageType* msg = m_reg.find(type);
        if (!msg)
            fail(tr("no definition for '%1'").arg(type));
        v.kind = RosValue::Message;
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
        const quint32 shown = std::min<quint32>(n, quint32(m_limits.maxArrayElements));
        for (quint32 i = 0; i < shown; ++i)
            v.children.append(value(u"[%1]"_s.arg(i), f.type, depth + 1));
        if (shown < n) {
            v.truncated = true;
            const int element = m_reg.fixedSize(f.type);
            if (element >= 0) {
                need(qsizetype(n - shown) * element, f.name);
            } else {
                for (quint32 i = shown; i < n; ++i)
                    skip(f.type, f.name, depth + 1);
            }
        }
        return v;
    }

private:
    const RosTypeRegistry& m_reg;
    const uchar* m_data;
    qsizetype m_size;
    qsizetype m_pos = 0;
    RosDecodeLimits m_limits;
};

} // namespace

std::optional<RosValue> RosMessageDecoder::decode(const RosTypeRegistry& registry, const QString& type,
                                                  const QByteArray& data, QString* error,
                                                  const RosDecodeLimits& limits)
{
    Reader reader(registry, data, limits);
    try {
        RosValue root = reader.value(QString(), type, 0);
        if (reader.pos() != reader.size()) {
            if (error)
                *error = tr("%1 bytes left over after the message").arg(reader.size() - reader.pos());
            return std::nullopt;
        }
        return root;
    } catch (const DecodeError& e) {
        if (error)
            *error = e.message;
        return std::nullopt;
    }
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
