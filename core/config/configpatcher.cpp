// SPDX-License-Identifier: MIT
#include "configpatcher.h"

#include "yaml/yamllimits.h"
#include "yaml/yamltree.h"
#include "config/configreader.h"
#include "config/configwriter.h"

#include <algorithm>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {

struct GiveUp
{
    QString why;
};

[[noreturn]] void giveUp(const QString& why)
{
    throw GiveUp {why};
}

// The original text with line arithmetic; positions are bytes, as yaml-cpp's marks are.
class Text
{
public:
    explicit Text(QByteArray text)
        : m_text(std::move(text))
    {
        m_starts.push_back(0);
        for (int i = 0; i < m_text.size(); ++i) {
            if (m_text[i] == '\n')
                m_starts.push_back(i + 1);
        }
        if (m_starts.size() > 1 && m_starts.back() == m_text.size())
            m_starts.pop_back();
    }
    int lineCount() const { return int(m_starts.size()); }
    int lineStart(int line) const { return m_starts.at(size_t(line)); }
    int lineEnd(int line) const { return line + 1 < lineCount() ? lineStart(line + 1) : int(m_text.size()); }
    int offset(const YAML::Mark& m) const
    {
        if (m.line < 0 || m.line >= lineCount())
            giveUp(u"position outside the text"_s);
        return lineStart(m.line) + m.column;
    }
    char at(int off) const { return off < m_text.size() ? m_text[off] : '\n'; }
    int indent(int line) const
    {
        int i = lineStart(line);
        const int end = lineEnd(line);
        while (i < end && m_text[i] == ' ')
            ++i;
        return i - lineStart(line);
    }
    bool isBlankOrComment(int line) const
    {
        const int i = lineStart(line) + indent(line);
        const char c = at(i);
        return i >= lineEnd(line) || c == '\n' || c == '\r' || c == '#';
    }
    // The last content line of the block that starts at `line`: following lines belong to it
    // while they are indented deeper than `parentIndent` (blank and comment lines in between
    // too, but not those after its last content line).
    int blockEnd(int line, int parentIndent) const
    {
        int last = line;
        for (int l = line + 1; l < lineCount(); ++l) {
            if (isBlankOrComment(l))
                continue;
            if (indent(l) <= parentIndent)
                break;
            last = l;
        }
        return last;
    }
    // End of a scalar token that starts at `off` (quoted or plain); the rest of its line must
    // be empty or a comment, and the next content line must not continue it.
    int scalarEnd(int off, int ownerIndent, int line) const
    {
        const char c = at(off);
        int end = off;
        const int lineEndOff = lineEnd(line);
        if (c == '"' || c == '\'') {
            int i = off + 1;
            for (; i < lineEndOff; ++i) {
                const char d = m_text[i];
                if (c == '"' && d == '\\') {
                    ++i;
                    continue;
                }
                if (d == c) {
                    if (c == '\'' && at(i + 1) == '\'') {
                        ++i;
                        continue;
                    }
                    break;
                }
            }
            if (i >= lineEndOff || m_text[i] != c)
                giveUp(u"multi-line quoted scalar"_s);
            end = i + 1;
        } else if (c == '|' || c == '>' || c == '[' || c == '{' || c == '&' || c == '!') {
            giveUp(u"block scalar, flow collection, anchor or tag"_s);
        } else {
            int i = off;
            while (i < lineEndOff && m_text[i] != '\n' && m_text[i] != '\r'
                   && !(m_text[i] == '#' && i > off && m_text[i - 1] == ' '))
                ++i;
            end = i;
            while (end > off && (m_text[end - 1] == ' ' || m_text[end - 1] == '\t'))
                --end;
        }
        for (int i = end; i < lineEndOff; ++i) {
            const char d = m_text[i];
            if (d == '#')
                break;
            if (d != ' ' && d != '\t' && d != '\r' && d != '\n')
                giveUp(u"more than one value on a line"_s);
        }
        for (int l = line + 1; l < lineCount(); ++l) {
            if (isBlankOrComment(l))
                continue;
            if (indent(l) > ownerIndent)
                giveUp(u"multi-line scalar"_s);
            break;
        }
        return end;
    }
    // End of a key token starting at `off` (just before its ':').
    int keyEnd(int off) const
    {
        const char c = at(off);
        if (c == '"' || c == '\'') {
            int i = off + 1;
            while (at(i) != c && at(i) != '\n')
                i += (c == '"' && at(i) == '\\') ? 2 : 1;
            if (at(i) != c)
                giveUp(u"multi-line key"_s);
            return i + 1;
        }
        int i = off;
        while (at(i) != '\n'
               && !(at(i) == ':' && (at(i + 1) == ' ' || at(i + 1) == '\n' || at(i + 1) == '\r')))
            ++i;
        if (at(i) != ':')
            giveUp(u"key without ':'"_s);
        return i;
    }
    // Offset just after the ':' that follows a key.
    int afterColon(int keyOff) const
    {
        int i = keyEnd(keyOff);
        while (at(i) == ' ')
            ++i;
        if (at(i) != ':')
            giveUp(u"key without ':'"_s);
        return i + 1;
    }
    const QByteArray& data() const { return m_text; }

private:
    QByteArray m_text;
    std::vector<int> m_starts;
};

struct Edit
{
    int start;
    int end;
    QByteArray text;
    int seq;
};

QByteArray indented(const QString& text, int indent)
{
    QByteArray out;
    const QByteArray pad(indent, ' ');
    const QStringList lines = text.split(u'\n');
    for (const QString& line : lines) {
        if (line.isEmpty())
            continue;
        out += pad + line.toUtf8() + '\n';
    }
    return out;
}

// YAML::Node's operator= writes through to the node it is bound to (it would edit the parsed
// document); every rebinding below therefore goes through reset().
struct KeyRef
{
    YAML::Node key;
    YAML::Node value;
    bool found = false;

    KeyRef() = default;
    KeyRef(const KeyRef& o) = default;
    KeyRef& operator=(const KeyRef& o)
    {
        key.reset(o.key);
        value.reset(o.value);
        found = o.found;
        return *this;
    }
};

KeyRef findKey(const YAML::Node& map, const QString& name)
{
    KeyRef ref;
    if (!map.IsMap())
        return ref;
    const std::string n = name.toStdString();
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (it->first.IsScalar() && it->first.Scalar() == n) {
            ref.key.reset(it->first);
            ref.value.reset(it->second);
            ref.found = true;
            return ref;
        }
    }
    return ref;
}

bool isBlockMap(const YAML::Node& n)
{
    return n.IsMap() && n.Style() != YAML::EmitterStyle::Flow && n.size() > 0;
}

bool isBlockSeq(const YAML::Node& n)
{
    return n.IsSequence() && n.Style() != YAML::EmitterStyle::Flow && n.size() > 0;
}

class Patcher
{
public:
    Patcher(const QByteArray& text, ConfigLayout layout)
        : m_text(text)
        , m_layout(layout)
    { }

    void add(int start, int end, QByteArray text)
    {
        m_edits.push_back({start, end, std::move(text), m_seq++});
    }

    QByteArray apply()
    {
        std::vector<Edit> sorted = m_edits;
        // Lines inserted at the same place: the deeper ones close the inner block that ends
        // there, so they go first (an option of the last mapping before a new "client:" section).
        auto depth = [](const Edit& e) {
            if (e.start != e.end)
                return 0;
            int n = 0;
            while (n < e.text.size() && e.text[n] == ' ')
                ++n;
            return n;
        };
        std::sort(sorted.begin(), sorted.end(), [&depth](const Edit& a, const Edit& b) {
            if (a.start != b.start)
                return a.start < b.start;
            if (depth(a) != depth(b))
                return depth(a) > depth(b);
            return a.seq < b.seq;
        });
        for (size_t i = 1; i < sorted.size(); ++i) {
            if (sorted[i].start < sorted[i - 1].end)
                giveUp(u"overlapping edits"_s);
        }
        QByteArray out = m_text.data();
        const bool crlf = out.contains("\r\n");
        for (auto it = sorted.rbegin(); it != sorted.rend(); ++it) {
            QByteArray piece = it->text;
            if (crlf)
                piece.replace("\n", "\r\n");
            out.replace(it->start, it->end - it->start, piece);
        }
        return out;
    }

    // Map geometry: the column of its keys and the offset just after its last line.
    int keyColumn(const YAML::Node& map) const { return map.begin()->first.Mark().column; }
    int mapEndOffset(const YAML::Node& map) const
    {
        YAML::Node lastKey;
        for (auto it = map.begin(); it != map.end(); ++it)
            lastKey.reset(it->first);
        const YAML::Mark m = lastKey.Mark();
        return m_text.lineEnd(m_text.blockEnd(m.line, m.column));
    }
    int lineEndAfterKey(const YAML::Node& key) const { return m_text.lineEnd(key.Mark().line); }

    void setScalar(const YAML::Node& key, const QString& yamlScalar)
    {
        const YAML::Mark km = key.Mark();
        int off = m_text.afterColon(m_text.offset(km));
        while (m_text.at(off) == ' ')
            ++off;
        const char c = m_text.at(off);
        if (c == '\n' || c == '\r' || c == '#')
            giveUp(u"value not on the key's line"_s);
        int end;
        if (c == '*') { // an alias: replace it by the literal value
            end = off;
            while (m_text.at(end) != ' ' && m_text.at(end) != '\n' && m_text.at(end) != '\r')
                ++end;
        } else {
            end = m_text.scalarEnd(off, km.column, km.line);
        }
        add(off, end, yamlScalar.toUtf8());
    }

    void replaceToken(const YAML::Node& scalarNode, int ownerIndent, const QString& yamlScalar)
    {
        const YAML::Mark m = scalarNode.Mark();
        const int off = m_text.offset(m);
        add(off, m_text.scalarEnd(off, ownerIndent, m.line), yamlScalar.toUtf8());
    }

    void replaceKey(const YAML::Node& key, const QString& yamlKey)
    {
        const int off = m_text.offset(key.Mark());
        add(off, m_text.keyEnd(off), yamlKey.toUtf8());
    }

    // Removes a key and everything below it; the key must start its line.
    void removeKey(const YAML::Node& key)
    {
        const YAML::Mark m = key.Mark();
        if (m_text.indent(m.line) != m.column)
            giveUp(u"key shares its line with a list dash"_s);
        add(m_text.lineStart(m.line), m_text.lineEnd(m_text.blockEnd(m.line, m.column)), QByteArray());
    }

    // Column of the "- " that starts the sequence item whose content begins at `m`.
    int dashColumn(const YAML::Mark& m) const
    {
        int i = m_text.offset(m) - 1;
        const int start = m_text.lineStart(m.line);
        while (i >= start && m_text.at(i) == ' ')
            --i;
        if (i < start || m_text.at(i) != '-')
            giveUp(u"list item not on its dash's line"_s);
        return i - start;
    }

    void removeItem(const YAML::Node& item)
    {
        const YAML::Mark m = item.Mark();
        const int dash = dashColumn(m);
        if (m_text.indent(m.line) != dash)
            giveUp(u"nested list item"_s);
        add(m_text.lineStart(m.line), m_text.lineEnd(m_text.blockEnd(m.line, dash)), QByteArray());
    }

    // Appends items (text without the dash) to a block sequence, after its last item.
    void appendItems(const YAML::Node& seq, const QStringList& items)
    {
        const YAML::Node last = seq[seq.size() - 1];
        const YAML::Mark m = last.Mark();
        const int dash = dashColumn(m);
        const int at = m_text.lineEnd(m_text.blockEnd(m.line, dash));
        add(at, at, itemsText(items, dash));
    }

    // Puts items below a key whose value is empty (null or "[]").
    void fillEmptyList(const YAML::Node& key, const YAML::Node& value, const QStringList& items)
    {
        const YAML::Mark km = key.Mark();
        const int colon = m_text.afterColon(m_text.offset(km));
        if (value.IsSequence()) { // "[]": remove it
            int off = colon;
            while (m_text.at(off) == ' ')
                ++off;
            if (m_text.at(off) != '[' || m_text.at(off + 1) != ']')
                giveUp(u"flow list"_s);
            add(colon, off + 2, QByteArray());
        }
        const int at = m_text.lineEnd(km.line);
        add(at, at, itemsText(items, km.column + 2));
    }

    void markEmptyList(const YAML::Node& key)
    {
        const int colon = m_text.afterColon(m_text.offset(key.Mark()));
        add(colon, colon, " []");
    }

    static QByteArray itemsText(const QStringList& items, int dash)
    {
        QByteArray out;
        for (const QString& item : items) {
            const QByteArray body = indented(item, dash + 2);
            out += QByteArray(dash, ' ') + "- " + body.mid(dash + 2);
        }
        return out;
    }

    // Edits one block (settings or a mapping) from `base` to `want`.
    // `owner` is the key above the block (for an empty block), `map` the block's node.
    void diffBlock(OptionScope scope, const KeyRef& owner, const OptionBlock& base, const OptionBlock& want,
                   const QString& skip = QString())
    {
        if (!sameExtras(base.extras, want.extras))
            giveUp(u"unknown keys changed"_s);
        QStringList paths = base.values.paths();
        for (const QString& p : want.values.paths()) {
            if (!paths.contains(p))
                paths << p;
        }
        // Additions are grouped by the deepest map that exists, so that two new options under a
        // new "advanced:" end up in one block.
        struct Group
        {
            QStringList prefix;
            int at = 0;
            int indent = 0;
            OptionBlock block;
        };
        QList<Group> groups;
        for (const QString& path : std::as_const(paths)) {
            if (path == skip)
                continue;
            const bool inBase = base.values.has(path);
            const bool inWant = want.values.has(path);
            if (inBase && inWant && base.values.isList(path) == want.values.isList(path)
                && base.values.text(path) == want.values.text(path)
                && base.values.list(path) == want.values.list(path))
                continue;
            const QStringList comps = path.split(u'.');
            if (inBase) {
                // Find the key in the file.
                YAML::Node node = owner.value;
                KeyRef ref;
                for (const QString& c : comps) {
                    if (!isBlockMap(node))
                        giveUp(u"option not in a block map"_s);
                    ref = findKey(node, c);
                    if (!ref.found)
                        giveUp(u"option not found in the file"_s);
                    node.reset(ref.value);
                }
                if (!inWant) {
                    removeKey(ref.key);
                } else {
                    if (want.values.isList(path) || !ref.value.IsScalar())
                        giveUp(u"list value changed"_s);
                    setScalar(ref.key,
                              ConfigWriter::scalarFor(scope, path, want.values.text(path), m_layout));
                }
                continue;
            }
            // A new option: descend as far as the file has maps.
            KeyRef above = owner;
            QStringList prefix;
            int i = 0;
            for (; i < comps.size() - 1; ++i) {
                if (!isBlockMap(above.value))
                    break;
                const KeyRef ref = findKey(above.value, comps[i]);
                if (!ref.found)
                    break;
                if (!ref.value.IsMap() && !ref.value.IsNull())
                    giveUp(u"a value where a section should be"_s);
                above = ref;
                prefix << comps[i];
            }
            int at;
            int indent;
            if (isBlockMap(above.value)) {
                at = mapEndOffset(above.value);
                indent = keyColumn(above.value);
            } else if (above.value.IsNull() || (above.value.IsMap() && above.value.size() == 0)) {
                if (above.value.IsMap()) // "{}"
                    giveUp(u"empty flow map"_s);
                if (!above.key.IsDefined())
                    giveUp(u"no place for the option"_s);
                at = lineEndAfterKey(above.key);
                indent = above.key.Mark().column + 2;
            } else {
                giveUp(u"flow map"_s);
            }
            Group* group = nullptr;
            for (Group& g : groups) {
                if (g.prefix == prefix && g.at == at)
                    group = &g;
            }
            if (!group) {
                groups.append({prefix, at, indent, {}});
                group = &groups.last();
            }
            group->block.values.copyFrom(want.values, path);
        }
        for (const Group& g : std::as_const(groups)) {
            const QString text = ConfigWriter::blockText(scope, g.block, m_layout, g.prefix);
            add(g.at, g.at, indented(text, g.indent));
        }
    }

    Text m_text;
    ConfigLayout m_layout;
    std::vector<Edit> m_edits;
    int m_seq = 0;
};

// Mappings of one direction, in file order.
QList<const Mapping*> ofDirection(const BridgeConfig& cfg, Direction d)
{
    QList<const Mapping*> out;
    for (const Mapping& m : cfg.mappings) {
        if (m.direction == d)
            out << &m;
    }
    return out;
}

void patchSettings(Patcher& p, const YAML::Node& params, const BridgeConfig& base, const BridgeConfig& want)
{
    for (OptionScope scope : {OptionScope::Broker, OptionScope::Client}) {
        const OptionBlock& b = base.block(scope);
        const OptionBlock& w = want.block(scope);
        if (b.sameContent(w))
            continue;
        const KeyRef ref = findKey(params, OptionSchema::scopeKey(scope));
        if (ref.found) {
            p.diffBlock(scope, ref, b, w);
            continue;
        }
        if (!b.values.isEmpty() || !b.extras.isEmpty())
            giveUp(u"settings not found in the file"_s);
        const QString body = ConfigWriter::blockText(scope, w, p.m_layout);
        const int at = p.mapEndOffset(params);
        const int indent = p.keyColumn(params);
        p.add(at, at,
              indented(OptionSchema::scopeKey(scope) + u":\n"_s, indent) + indented(body, indent + 2));
    }
}

void patchRos1Mappings(Patcher& p, const YAML::Node& bridge, const BridgeConfig& base,
                       const BridgeConfig& want)
{
    for (Direction d : {Direction::Ros2Mqtt, Direction::Mqtt2Ros}) {
        const QList<const Mapping*> before = ofDirection(base, d);
        const QList<const Mapping*> after = ofDirection(want, d);
        const KeyRef dir = findKey(bridge, OptionSchema::scopeKey(scopeOf(d)));
        int kept = 0;
        for (const Mapping* b : before) {
            const int wi = want.indexOfMapping(b->id);
            const Mapping* w = wi >= 0 ? &want.mappings[wi] : nullptr;
            if (!dir.found || !isBlockSeq(dir.value) || b->block.source.index < 0
                || b->block.source.index >= int(dir.value.size()))
                giveUp(u"mapping not found in the file"_s);
            const YAML::Node item = dir.value[b->block.source.index];
            if (!w || w->direction != d) {
                p.removeItem(item);
                continue;
            }
            ++kept;
            if (!b->sameContent(*w)) {
                if (!isBlockMap(item))
                    giveUp(u"flow mapping"_s);
                KeyRef owner;
                owner.value = item;
                p.diffBlock(scopeOf(d), owner, b->block, w->block);
            }
        }
        QStringList added;
        for (const Mapping* w : after) {
            const Mapping* b = base.mappingById(w->id);
            if (!b || b->direction != d)
                added << ConfigWriter::ros1MappingItem(*w);
        }
        if (added.isEmpty()) {
            if (kept == 0 && !before.isEmpty())
                p.markEmptyList(dir.key);
            continue;
        }
        if (dir.found && isBlockSeq(dir.value)) {
            p.appendItems(dir.value, added);
        } else if (dir.found && (dir.value.IsNull() || (dir.value.IsSequence() && dir.value.size() == 0))) {
            p.fillEmptyList(dir.key, dir.value, added);
        } else if (!dir.found && isBlockMap(bridge)) {
            const int at = p.mapEndOffset(bridge);
            const int indent = p.keyColumn(bridge);
            p.add(at, at,
                  indented(OptionSchema::scopeKey(scopeOf(d)) + u":"_s, indent)
                      + Patcher::itemsText(added, indent + 2));
        } else {
            giveUp(u"no list to add mappings to"_s);
        }
    }
}

void patchRos2Mappings(Patcher& p, const YAML::Node& bridge, const BridgeConfig& base,
                       const BridgeConfig& want)
{
    for (Direction d : {Direction::Ros2Mqtt, Direction::Mqtt2Ros}) {
        const bool out = d == Direction::Ros2Mqtt;
        const QString keyField = out ? u"ros_topic"_s : u"mqtt_topic"_s;
        const QString listKey = out ? u"ros_topics"_s : u"mqtt_topics"_s;
        const QList<const Mapping*> before = ofDirection(base, d);
        const QList<const Mapping*> after = ofDirection(want, d);
        const KeyRef dir = findKey(bridge, OptionSchema::scopeKey(scopeOf(d)));
        const KeyRef list = dir.found ? findKey(dir.value, listKey) : KeyRef();
        int kept = 0;
        for (const Mapping* b : before) {
            const int wi = want.indexOfMapping(b->id);
            const Mapping* w = wi >= 0 ? &want.mappings[wi] : nullptr;
            if (!list.found || !isBlockSeq(list.value) || b->block.source.index < 0
                || b->block.source.index >= int(list.value.size()) || !isBlockMap(dir.value))
                giveUp(u"mapping not found in the file"_s);
            const YAML::Node item = list.value[b->block.source.index];
            const KeyRef settings = findKey(dir.value, b->value(keyField));
            if (!w || w->direction != d) {
                p.removeItem(item);
                if (settings.found)
                    p.removeKey(settings.key);
                continue;
            }
            ++kept;
            if (b->sameContent(*w))
                continue;
            if (!settings.found)
                giveUp(u"topic settings not found"_s);
            if (w->value(keyField) != b->value(keyField)) {
                p.replaceToken(item, p.dashColumn(item.Mark()), YamlText::quoted(w->value(keyField)));
                p.replaceKey(settings.key, YamlText::key(w->value(keyField)));
            }
            p.diffBlock(scopeOf(d), settings, b->block, w->block, keyField);
        }
        QStringList addedTopics;
        QString addedBlocks;
        for (const Mapping* w : after) {
            const Mapping* b = base.mappingById(w->id);
            if (b && b->direction == d)
                continue;
            addedTopics << YamlText::quoted(w->value(keyField));
            const QString body = ConfigWriter::ros2MappingBlock(*w);
            addedBlocks
                += YamlText::key(w->value(keyField)) + u":"_s + (body.isEmpty() ? u" {}\n"_s : u"\n"_s);
            for (const QString& line : body.split(u'\n', Qt::SkipEmptyParts))
                addedBlocks += u"  "_s + line + u'\n';
        }
        if (addedTopics.isEmpty()) {
            if (kept == 0 && !before.isEmpty())
                p.markEmptyList(list.key);
            continue;
        }
        if (!dir.found || !isBlockMap(dir.value) || !list.found)
            giveUp(u"no place to add mappings"_s);
        if (isBlockSeq(list.value))
            p.appendItems(list.value, addedTopics);
        else if (list.value.IsNull() || (list.value.IsSequence() && list.value.size() == 0))
            p.fillEmptyList(list.key, list.value, addedTopics);
        else
            giveUp(u"flow topic list"_s);
        const int at = p.mapEndOffset(dir.value);
        p.add(at, at, indented(addedBlocks, p.keyColumn(dir.value)));
    }
}

// The patched text must read back as exactly the wanted config; returns what differs.
QString readBackDifference(const ConfigReadResult& r, const BridgeConfig& want)
{
    if (!r.parsed)
        return u"not readable: "_s + r.problems.value(0).message;
    if (r.config.layout != want.layout || r.config.ros2NodeName != want.ros2NodeName)
        return u"layout"_s;
    if (!r.config.sameSettings(want))
        return u"settings"_s;
    for (Direction d : {Direction::Ros2Mqtt, Direction::Mqtt2Ros}) {
        QList<const Mapping*> got = ofDirection(r.config, d);
        const QList<const Mapping*> wanted = ofDirection(want, d);
        if (got.size() != wanted.size())
            return u"%1 instead of %2 mappings"_s.arg(got.size()).arg(wanted.size());
        for (const Mapping* w : wanted) {
            const auto it
                = std::find_if(got.begin(), got.end(), [w](const Mapping* g) { return g->sameContent(*w); });
            if (it == got.end())
                return u"mapping %1 -> %2"_s.arg(w->sourceTopic(), w->destinationTopic());
            got.erase(it);
        }
    }
    return QString();
}

} // namespace

std::optional<QByteArray> ConfigPatcher::patch(const QByteArray& text, const BridgeConfig& baseline,
                                               const BridgeConfig& wanted, QString* whyNot,
                                               ConfigReadResult* readBack)
{
    try {
        if (baseline.layout != wanted.layout || wanted.layout == ConfigLayout::MqttBridge)
            giveUp(u"layout changes"_s);
        if (!sameExtras(baseline.rootExtras, wanted.rootExtras)
            || !sameExtras(baseline.bridgeExtras, wanted.bridgeExtras)
            || !sameExtras(baseline.documentExtras, wanted.documentExtras)
            || baseline.ros2NodeName != wanted.ros2NodeName)
            giveUp(u"unknown keys changed"_s);
        if (baseline.sameContent(wanted) && baseline.mappings.size() == wanted.mappings.size()) {
            bool sameIds = true;
            for (int i = 0; i < wanted.mappings.size(); ++i)
                sameIds = sameIds && baseline.mappings[i].id == wanted.mappings[i].id;
            if (sameIds) {
                if (readBack)
                    *readBack = ConfigReader::read(text);
                return text;
            }
        }
        // Work on text that ends with a newline, so that lines appended at the end stand alone.
        QByteArray source = text;
        if (!source.isEmpty() && !source.endsWith('\n'))
            source += '\n';
        YAML::Node root;
        try {
            root = YamlLimits::load(source);
        } catch (const YamlLimits::Exceeded& e) {
            giveUp(e.violation.message);
        } catch (const YAML::Exception&) {
            giveUp(u"the file is not valid YAML"_s);
        }
        const YAML::Node& croot = root;
        YAML::Node params = croot;
        if (wanted.layout == ConfigLayout::Ros2) {
            const KeyRef node = findKey(croot, wanted.ros2NodeName);
            const KeyRef rp = node.found ? findKey(node.value, u"ros__parameters"_s) : KeyRef();
            if (!rp.found)
                giveUp(u"ros__parameters not found"_s);
            params.reset(rp.value);
        }
        if (!isBlockMap(params))
            giveUp(u"parameters are not a block map"_s);

        Patcher p(source, wanted.layout);
        patchSettings(p, params, baseline, wanted);
        const KeyRef bridge = findKey(params, u"bridge"_s);
        if (!bridge.found || !isBlockMap(bridge.value))
            giveUp(u"no 'bridge' map in the file"_s);
        if (wanted.layout == ConfigLayout::Ros1)
            patchRos1Mappings(p, bridge.value, baseline, wanted);
        else
            patchRos2Mappings(p, bridge.value, baseline, wanted);
        QByteArray out = p.apply();
        ConfigReadResult check = ConfigReader::read(out);
        if (const QString diff = readBackDifference(check, wanted); !diff.isEmpty()) {
            if (qEnvironmentVariableIsSet("BRIDGESCOPE_DEBUG_PATCH"))
                qWarning("patched text:\n%s", out.constData());
            giveUp(u"the edited text does not read back as the edited config: "_s + diff);
        }
        if (readBack)
            *readBack = std::move(check);
        return out;
    } catch (const GiveUp& g) {
        if (whyNot)
            *whyNot = g.why;
        return std::nullopt;
    } catch (const YAML::Exception& e) {
        if (whyNot)
            *whyNot = QString::fromStdString(e.msg);
        return std::nullopt;
    }
}
