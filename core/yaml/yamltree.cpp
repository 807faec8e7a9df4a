// SPDX-License-Identifier: MIT
#include "yamltree.h"

#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace YamlText {

namespace {

// Text that a YAML 1.1 reader (rosparam uses PyYAML) or a YAML 1.2 reader (yaml-cpp)
// would resolve to null, a boolean, a number or a date.
bool resolvesToNonString(const QString& t)
{
    static const QRegularExpression special(
        uR"(^(~|null|Null|NULL|true|True|TRUE|false|False|FALSE|yes|Yes|YES|no|No|NO|on|On|ON|off|Off|OFF|y|Y|n|N|=|<<)$)"_s);
    static const QRegularExpression number(
        uR"(^([-+]?(\d[\d_]*)?\.?\d[\d_]*([eE][-+]?\d+)?|[-+]?0x[0-9a-fA-F_]+|0o[0-7]+|[-+]?\.(inf|Inf|INF)|\.(nan|NaN|NAN)|[-+]?\d+(:[0-5]?\d)+(\.\d*)?|\d{4}-\d\d?-\d\d?.*)$)"_s);
    return special.match(t).hasMatch() || number.match(t).hasMatch();
}

// Text that cannot be written plain at all, whatever its type.
bool needsStructuralQuotes(const QString& t)
{
    if (t.isEmpty())
        return true;
    if (t.front().isSpace() || t.back().isSpace())
        return true;
    for (QChar c : t) {
        if (mustEscape(c))
            return true;
    }
    static const QString indicators = u"[]{}#&*!|>'\"%@`,"_s;
    if (indicators.contains(t.front()))
        return true;
    if ((t.front() == u'-' || t.front() == u'?' || t.front() == u':') && (t.size() == 1 || t.at(1) == u' '))
        return true;
    if (t.contains(u": "_s) || t.contains(u" #"_s) || t.endsWith(u':'))
        return true;
    // A key at the start of a line reading "--- ..." or "... ..." would start or end a document
    // (found by fuzz_config).
    if (t.startsWith(u"---"_s) || t.startsWith(u"..."_s))
        return true;
    return false;
}

} // namespace

bool mustEscape(QChar c)
{
    const char16_t u = c.unicode();
    return u < 0x20 || u == 0x7f || (u >= 0x80 && u < 0xa0) || u == 0xfeff || u == 0x2028 || u == 0x2029;
}

bool needsQuotes(const QString& text)
{
    return needsStructuralQuotes(text) || resolvesToNonString(text);
}

QString quoted(const QString& text)
{
    if (!needsQuotes(text))
        return text;
    QString out;
    out.reserve(text.size() + 2);
    out += u'"';
    for (QChar c : text) {
        switch (c.unicode()) {
        case '"':
            out += u"\\\""_s;
            break;
        case '\\':
            out += u"\\\\"_s;
            break;
        case '\n':
            out += u"\\n"_s;
            break;
        case '\t':
            out += u"\\t"_s;
            break;
        case '\r':
            out += u"\\r"_s;
            break;
        case 0:
            out += u"\\0"_s;
            break;
        default:
            if (c.unicode() < 0x100 && mustEscape(c))
                out += u"\\x"_s + QString::number(c.unicode(), 16).rightJustified(2, u'0');
            else if (mustEscape(c))
                out += u"\\u"_s + QString::number(c.unicode(), 16).rightJustified(4, u'0');
            else
                out += c;
        }
    }
    out += u'"';
    return out;
}

QString scalar(const QString& text, YamlTree::ScalarStyle style)
{
    if (style == YamlTree::ScalarStyle::Typed && !needsStructuralQuotes(text))
        return text;
    return quoted(text);
}

QString key(const QString& text)
{
    return quoted(text);
}

bool isTrue(const QString& text)
{
    static const QStringList yes = {u"true"_s, u"True"_s, u"TRUE"_s, u"yes"_s, u"Yes"_s, u"YES"_s,
                                    u"on"_s,   u"On"_s,   u"ON"_s,   u"y"_s,   u"Y"_s};
    return yes.contains(text);
}

bool isFalse(const QString& text)
{
    static const QStringList no = {u"false"_s, u"False"_s, u"FALSE"_s, u"no"_s, u"No"_s, u"NO"_s,
                                   u"off"_s,   u"Off"_s,   u"OFF"_s,   u"n"_s,  u"N"_s};
    return no.contains(text);
}

bool isSubstitution(const QString& text)
{
    static const QRegularExpression re(uR"(\$\((arg|env|optenv|find|anon|eval|dirname)\b[^)]*\))"_s);
    return re.match(text).hasMatch();
}

} // namespace YamlText

YamlTree YamlTree::scalar(const QString& text, ScalarStyle style)
{
    YamlTree t(Type::Scalar);
    t.m_text = text;
    t.m_style = style;
    return t;
}

YamlTree YamlTree::raw(const QString& yaml)
{
    YamlTree t(Type::Raw);
    t.m_text = yaml;
    while (t.m_text.endsWith(u'\n'))
        t.m_text.chop(1);
    return t;
}

YamlTree* YamlTree::find(const QString& key)
{
    for (auto& [k, v] : m_children) {
        if (k == key)
            return v.get();
    }
    return nullptr;
}

YamlTree& YamlTree::child(const QString& key)
{
    if (YamlTree* t = find(key))
        return *t;
    m_children.append({key, std::make_shared<YamlTree>(YamlTree(Type::Map))});
    return *m_children.last().second;
}

void YamlTree::insert(const QString& key, YamlTree value)
{
    for (auto& [k, v] : m_children) {
        if (k == key) {
            v = std::make_shared<YamlTree>(std::move(value));
            return;
        }
    }
    m_children.append({key, std::make_shared<YamlTree>(std::move(value))});
}

void YamlTree::append(YamlTree value)
{
    m_children.append({QString(), std::make_shared<YamlTree>(std::move(value))});
}

bool YamlTree::insertAt(const QStringList& path, YamlTree value)
{
    if (path.isEmpty() || m_type != Type::Map)
        return false;
    YamlTree* node = this;
    for (int i = 0; i + 1 < path.size(); ++i) {
        YamlTree* next = node->find(path[i]);
        if (!next) {
            next = &node->child(path[i]);
        } else if (next->m_type != Type::Map) {
            return false;
        }
        node = next;
    }
    node->insert(path.last(), std::move(value));
    return true;
}

QString YamlTree::toText() const
{
    QString out;
    if (m_type == Type::Map && m_children.isEmpty())
        return u"{}\n"_s;
    write(out, 0);
    return out;
}

namespace {
QString spaces(int n)
{
    return QString(n, u' ');
}

// Whether raw YAML text can follow "key: " on the same line: one line that is no block
// collection. A dumped block sequence is "- 1" and a map in one "- a: 1" (found by fuzz_config:
// "extra: - 1" is not YAML).
bool fitsAfterKey(const QString& text)
{
    if (text.contains(u'\n'))
        return false;
    if (text.startsWith(u'[') || text.startsWith(u'{') || text.startsWith(u'"') || text.startsWith(u'\''))
        return true;
    return !(text == u"-"_s || text.startsWith(u"- "_s) || text.startsWith(u"? "_s) || text.contains(u": "_s)
             || text.endsWith(u':'));
}

void appendIndented(QString& out, const QString& text, int indent)
{
    const QStringList lines = text.split(u'\n');
    for (const QString& line : lines)
        out += (line.isEmpty() ? QString() : spaces(indent) + line) + u'\n';
}
} // namespace

void YamlTree::write(QString& out, int indent) const
{
    switch (m_type) {
    case Type::Map:
        for (const auto& [k, v] : m_children) {
            const QString key = YamlText::key(k);
            // YAML limits implicit keys to 1024 characters; a longer one needs "? " (found by
            // fuzz_config: a key of 1.4 kB was written so that it did not read back).
            if (key.size() > 1000)
                out += spaces(indent) + u"? "_s + key + u'\n' + spaces(indent) + u':';
            else
                out += spaces(indent) + key + u':';
            v->writeValueAfterKey(out, indent);
        }
        break;
    case Type::Seq:
        for (const auto& [k, v] : m_children) {
            Q_UNUSED(k)
            QString item;
            if (v->m_type == Type::Scalar) {
                item = spaces(indent + 2) + YamlText::scalar(v->m_text, v->m_style) + u'\n';
            } else if (v->m_type == Type::Raw) {
                appendIndented(item, v->m_text, indent + 2);
            } else if (v->isEmpty()) {
                item = spaces(indent + 2) + (v->m_type == Type::Map ? u"{}"_s : u"[]"_s) + u'\n';
            } else {
                v->write(item, indent + 2);
            }
            // The first line's indentation becomes the "- " of the item.
            out += spaces(indent) + u"- "_s + item.mid(indent + 2);
        }
        break;
    case Type::Scalar:
        out += spaces(indent) + YamlText::scalar(m_text, m_style) + u'\n';
        break;
    case Type::Raw:
        appendIndented(out, m_text, indent);
        break;
    }
}

void YamlTree::writeValueAfterKey(QString& out, int indent) const
{
    switch (m_type) {
    case Type::Scalar:
        out += u' ' + YamlText::scalar(m_text, m_style) + u'\n';
        break;
    case Type::Raw:
        if (fitsAfterKey(m_text)) {
            out += u' ' + m_text + u'\n';
        } else {
            out += u'\n';
            appendIndented(out, m_text, indent + 2);
        }
        break;
    case Type::Map:
        if (m_children.isEmpty()) {
            out += u" {}\n"_s;
        } else {
            out += u'\n';
            write(out, indent + 2);
        }
        break;
    case Type::Seq:
        if (m_children.isEmpty()) {
            out += u" []\n"_s;
        } else {
            out += u'\n';
            write(out, indent + 2);
        }
        break;
    }
}
