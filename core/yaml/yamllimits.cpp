// SPDX-License-Identifier: MIT
#include "yamllimits.h"

#include "yaml/yamlreader.h"

#include <istream>
#include <QLocale>
#include <streambuf>
#include <unordered_map>
#include <vector>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {

// Reads a QByteArray in place (the text can be megabytes; no std::string copies).
class ByteArrayBuffer : public std::streambuf
{
public:
    explicit ByteArrayBuffer(const QByteArray& bytes)
    {
        char* begin = const_cast<char*>(bytes.constData());
        setg(begin, begin, begin + bytes.size());
    }
};

TextPos positionOf(const QByteArray& text, qsizetype offset)
{
    int line = 0;
    qsizetype lineStart = 0;
    for (qsizetype i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return {line, int(offset - lineStart)};
}

struct Stop
{
    YamlLimits::Violation violation;
};

// What an anchor stands for once its aliases are expanded.
struct AnchorSize
{
    qint64 nodes = 0;
    qint64 bytes = 0;
    int height = 0; ///< collections nested in it, itself included
    bool complete = false; ///< false while its collection is still open
    QString name;
};

class Counter : public YAML::EventHandler
{
    Q_DECLARE_TR_FUNCTIONS(YamlLimits)
public:
    void OnDocumentStart(const YAML::Mark&) override { }
    void OnDocumentEnd() override { }
    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override
    {
        // "~", "null", "NULL" and an empty key are the same null key (found by fuzz_config).
        if (nextChild())
            checkKey(mark, std::string("\0null", 5));
        leaf(mark, anchor, 0);
    }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  const std::string& value) override
    {
        if (nextChild())
            checkKey(mark, value);
        leaf(mark, anchor, qint64(value.size()));
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override
    {
        const bool isKey = nextChild();
        countNode(mark);
        ++m_aliases;
        const AnchorSize* a = anchor < m_anchors.size() ? &m_anchors[anchor] : nullptr;
        const QString name = a ? a->name : QString();
        if (!a || !a->complete)
            stop(mark, u"yaml-alias-cycle"_s,
                 tr("The alias *%1 refers to a node that contains it; the document would be infinite.")
                     .arg(name),
                 tr("Remove the alias or point it at a node outside its anchor."));
        m_aliasNodes += a->nodes;
        m_aliasBytes += a->bytes;
        if (m_aliasNodes > YamlLimits::maxAliasNodes)
            stop(mark, u"yaml-alias-expansion"_s,
                 tr("The alias *%1 makes aliases repeat %2 nodes; at most %3 are read.")
                     .arg(name)
                     .arg(m_aliasNodes)
                     .arg(YamlLimits::maxAliasNodes),
                 aliasFix());
        if (m_aliasBytes > YamlLimits::maxAliasBytes)
            stop(mark, u"yaml-alias-expansion"_s,
                 tr("The alias *%1 makes aliases repeat %2 bytes of text; at most %3 are read.")
                     .arg(name)
                     .arg(m_aliasBytes)
                     .arg(YamlLimits::maxAliasBytes),
                 aliasFix());
        if (int(m_open.size()) + a->height > YamlLimits::maxDepth)
            stop(mark, u"yaml-too-deep"_s,
                 tr("The alias *%1 nests collections %2 deep; at most %3 are read.")
                     .arg(name)
                     .arg(int(m_open.size()) + a->height)
                     .arg(YamlLimits::maxDepth),
                 aliasFix());
        if (isKey && a->height > 0)
            complexKey(mark);
        child(a->height);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override
    {
        if (nextChild())
            complexKey(mark);
        open(mark, anchor, false);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override
    {
        if (nextChild())
            complexKey(mark);
        open(mark, anchor, true);
    }
    void OnMapEnd() override { close(); }
    void OnAnchor(const YAML::Mark&, const std::string& name) override
    {
        m_pendingName = QString::fromStdString(name);
    }

private:
    struct Open
    {
        YAML::anchor_t anchor;
        qint64 nodesBefore;
        qint64 bytesBefore;
        int height = 1;
        bool isMap = false;
        bool keyNext = true; ///< in a map: the next child is a key
        std::unordered_map<std::string, int> keys; ///< scalar keys of a map and their line
    };

    /// Called at the start of every node: whether it is a key of the open map.
    bool nextChild()
    {
        if (m_open.empty() || !m_open.back().isMap)
            return false;
        Open& o = m_open.back();
        o.keyNext = !o.keyNext;
        return !o.keyNext;
    }

    // A list or map as a key ("? [a, b]: 1"): ROS's rosparam cannot load it (PyYAML keys must be
    // hashable), no config has one, and written back it does not read (found by fuzz_config).
    [[noreturn]] static void complexKey(const YAML::Mark& mark)
    {
        stop(mark, u"yaml-complex-key"_s, tr("A list or a map is used as a key here; keys must be plain text."),
             tr("Write the key as text, or remove the entry."));
    }

    // YAML forbids a key twice in one mapping. yaml-cpp keeps both and its lookups find the
    // first, while ROS's rosparam (PyYAML), which loads mqtt_client's configs, keeps the last:
    // the bridge would run another config than the one shown.
    void checkKey(const YAML::Mark& mark, const std::string& key)
    {
        const auto [it, inserted] = m_open.back().keys.emplace(key, mark.line);
        if (!inserted)
            stop(mark, u"yaml-duplicate-key"_s,
                 tr("The key \"%1\" appears twice in this mapping (first on line %2); YAML forbids "
                    "it, and readers disagree on which value counts.")
                     .arg(key == std::string("\0null", 5) ? tr("~ (null, also written null, NULL or nothing)")
                                                         : QString::fromStdString(key))
                     .arg(it->second + 1),
                 tr("Remove one of the two, or rename it."));
    }

    [[noreturn]] static void stop(const YAML::Mark& mark, const QString& code, const QString& message,
                                  const QString& fix)
    {
        throw Stop {{{mark.line, mark.column}, code, message, fix}};
    }

    static QString aliasFix()
    {
        return tr("Anchors and aliases are for sharing a few values; write the values out instead.");
    }

    // An alias stands for the node it names, in place of itself.
    qint64 expandedNodes() const { return m_nodes - m_aliases + m_aliasNodes; }
    qint64 expandedBytes() const { return m_bytes + m_aliasBytes; }

    void countNode(const YAML::Mark& mark)
    {
        if (++m_nodes > YamlLimits::maxNodes)
            stop(mark, u"yaml-too-many-nodes"_s,
                 tr("The document has more than %1 nodes (values, keys, lists and maps); at most %1 are "
                    "read.")
                     .arg(YamlLimits::maxNodes),
                 tr("Split the file."));
    }

    AnchorSize& anchorSlot(YAML::anchor_t anchor)
    {
        if (anchor >= m_anchors.size())
            m_anchors.resize(anchor + 1);
        AnchorSize& a = m_anchors[anchor];
        a = AnchorSize();
        a.name = m_pendingName;
        m_pendingName.clear();
        return a;
    }

    void child(int height)
    {
        if (!m_open.empty())
            m_open.back().height = std::max(m_open.back().height, height + 1);
    }

    void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, qint64 bytes)
    {
        countNode(mark);
        m_bytes += bytes;
        if (anchor != YAML::NullAnchor) {
            AnchorSize& a = anchorSlot(anchor);
            a.nodes = 1;
            a.bytes = bytes;
            a.complete = true;
        }
        child(0);
    }

    void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool isMap)
    {
        const qint64 nodesBefore = expandedNodes();
        const qint64 bytesBefore = expandedBytes();
        countNode(mark);
        if (int(m_open.size()) + 1 > YamlLimits::maxDepth)
            stop(mark, u"yaml-too-deep"_s,
                 tr("Lists and maps are nested more than %1 deep here; at most %1 are read.")
                     .arg(YamlLimits::maxDepth),
                 tr("Flatten the structure."));
        if (anchor != YAML::NullAnchor)
            anchorSlot(anchor); // incomplete until its end: an alias inside it is a cycle
        Open o {anchor, nodesBefore, bytesBefore, 1, isMap, true, {}};
        m_open.push_back(std::move(o));
    }

    void close()
    {
        if (m_open.empty())
            return;
        const Open o = std::move(m_open.back());
        m_open.pop_back();
        if (o.anchor != YAML::NullAnchor && o.anchor < m_anchors.size()) {
            AnchorSize& a = m_anchors[o.anchor];
            a.nodes = expandedNodes() - o.nodesBefore;
            a.bytes = expandedBytes() - o.bytesBefore;
            a.height = o.height;
            a.complete = true;
        }
        child(o.height);
    }

    std::vector<AnchorSize> m_anchors; // by yaml-cpp's anchor id (1, 2, ... per document)
    std::vector<Open> m_open;
    QString m_pendingName;
    qint64 m_nodes = 0;
    qint64 m_bytes = 0;
    qint64 m_aliases = 0;
    qint64 m_aliasNodes = 0;
    qint64 m_aliasBytes = 0;
};

YAML::Mark markOf(const TextPos& pos)
{
    YAML::Mark m;
    m.line = pos.line;
    m.column = pos.column;
    return m;
}

} // namespace

YamlLimits::Exceeded::Exceeded(const Violation& v)
    : YAML::ParserException(markOf(v.pos), v.message.toStdString())
    , violation(v)
{ }

bool YamlLimits::isUtf8(const QByteArray& bytes, qsizetype* badOffset)
{
    const auto* s = reinterpret_cast<const unsigned char*>(bytes.constData());
    const qsizetype n = bytes.size();
    qsizetype i = 0;
    while (i < n) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            ++i;
            continue;
        }
        int len = 0;
        unsigned char lo = 0x80, hi = 0xbf; // allowed range of the second byte
        if (c >= 0xc2 && c <= 0xdf) {
            len = 2;
        } else if (c >= 0xe0 && c <= 0xef) {
            len = 3;
            if (c == 0xe0)
                lo = 0xa0; // overlong
            else if (c == 0xed)
                hi = 0x9f; // UTF-16 surrogates
        } else if (c >= 0xf0 && c <= 0xf4) {
            len = 4;
            if (c == 0xf0)
                lo = 0x90; // overlong
            else if (c == 0xf4)
                hi = 0x8f; // past U+10FFFF
        }
        bool ok = len > 0 && i + len <= n && s[i + 1] >= lo && s[i + 1] <= hi;
        for (int k = 2; ok && k < len; ++k)
            ok = s[i + k] >= 0x80 && s[i + k] <= 0xbf;
        if (!ok) {
            if (badOffset)
                *badOffset = i;
            return false;
        }
        i += len;
    }
    return true;
}

QString YamlLimits::tooLargeMessage(qint64 size)
{
    // The file's size in the units people think in; its byte offset at the limit is no place.
    const QLocale locale;
    const auto human = [&locale](qint64 bytes, int decimals) {
        return locale.formattedDataSize(bytes, decimals, QLocale::DataSizeTraditionalFormat);
    };
    const auto decimalsOf = [](qint64 bytes) { return bytes >= 10LL * 1024 * 1024 ? 0 : 1; };
    const QString limit = human(maxBytes, 0);
    const QString shown = human(size, decimalsOf(size));
    if (size <= maxBytes + 1 || shown == human(maxBytes, decimalsOf(size)))
        return tr("The file is larger than %1, the limit.").arg(limit);
    return tr("The file is %1, the limit is %2.").arg(shown, limit);
}

std::optional<YamlLimits::Violation> YamlLimits::check(const QByteArray& text)
{
    if (text.size() > maxBytes)
        return Violation {TextPos {}, u"yaml-too-large"_s, tooLargeMessage(text.size()),
                          tr("Split the file.")};
    qsizetype bad = 0;
    if (!isUtf8(text, &bad))
        return Violation {positionOf(text, bad), u"invalid-utf8"_s,
                          tr("Byte 0x%1 is not valid UTF-8; the file must be UTF-8 text.")
                              .arg(uint(uchar(text[bad])), 2, 16, QChar(u'0')),
                          tr("Save the file as UTF-8, or correct the text at this place.")};
    // YAML allows no control characters but tab and line breaks, not even quoted (found by
    // fuzz_config: yaml-cpp read a NUL inside indentation as content).
    for (qsizetype i = 0; i < text.size(); ++i) {
        const uchar c = uchar(text[i]);
        const bool c1 = c == 0xc2 && i + 1 < text.size() && uchar(text[i + 1]) >= 0x80
            && uchar(text[i + 1]) <= 0x9f && uchar(text[i + 1]) != 0x85;
        if (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))
            return Violation {positionOf(text, i), u"yaml-lone-carriage-return"_s,
                              tr("A carriage return without a line feed: yaml-cpp does not read it as a "
                                 "line break, but as part of the value."),
                              tr("Save the file with LF or CRLF line endings.")};
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f || c1)
            return Violation {positionOf(text, i), u"yaml-control-character"_s,
                              tr("The control character U+%1 is not allowed in YAML; write it as an "
                                 "escape (\\x%2) in a double-quoted string.")
                                  .arg(uint(c1 ? uchar(text[i + 1]) : c), 4, 16, QChar(u'0'))
                                  .arg(uint(c1 ? uchar(text[i + 1]) : c), 2, 16, QChar(u'0')),
                              tr("Remove the character, or correct the text at this place.")};
    }
    ByteArrayBuffer buffer(text);
    std::istream in(&buffer);
    try {
        YAML::Parser parser(in);
        Counter counter;
        parser.HandleNextDocument(counter);
    } catch (const Stop& s) {
        return s.violation;
    } catch (const YAML::Exception&) {
        // A syntax error: YAML::Load reports it with its position.
    }
    return std::nullopt;
}

YAML::Node YamlLimits::load(const QByteArray& text)
{
    if (const auto v = check(text))
        throw Exceeded(*v);
    ByteArrayBuffer buffer(text);
    std::istream in(&buffer);
    return YAML::Load(in);
}
