// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <QList>
#include <QString>
#include <QStringList>

/// A small ordered YAML tree that Bridgescope writes configs through.
///
/// yaml-cpp's emitter decides quoting by itself and cannot keep a string such as "123" a string
/// in every consumer; this tree quotes exactly when a scalar would otherwise change type, keeps key
/// order, and splices unknown keys back in as the YAML text they were read from.
class YamlTree
{
public:
    enum class Type { Map, Seq, Scalar, Raw };
    /// How a scalar must be read back: as a string (quoted if it looks like anything else)
    /// or as whatever its text resolves to (numbers, booleans, substitutions).
    enum class ScalarStyle { String, Typed };

    static YamlTree map() { return YamlTree(Type::Map); }
    static YamlTree seq() { return YamlTree(Type::Seq); }
    static YamlTree scalar(const QString& text, ScalarStyle style = ScalarStyle::String);
    static YamlTree raw(const QString& yaml);

    Type type() const { return m_type; }
    bool isEmpty() const { return m_children.isEmpty(); }

    /// The child at key, created as a map when missing.
    YamlTree& child(const QString& key);
    YamlTree* find(const QString& key);
    void insert(const QString& key, YamlTree value); ///< replaces an existing key in place
    void append(YamlTree value);
    /// Puts value at a key path, creating maps on the way; false if a non-map is in the way.
    bool insertAt(const QStringList& path, YamlTree value);

    /// Block-style YAML text, two spaces per level.
    QString toText() const;

private:
    explicit YamlTree(Type t)
        : m_type(t)
    { }
    void write(QString& out, int indent) const;
    void writeValueAfterKey(QString& out, int indent) const;

    Type m_type;
    QString m_text;
    ScalarStyle m_style = ScalarStyle::String;
    QList<std::pair<QString, std::shared_ptr<YamlTree>>> m_children; // key empty for Seq
};

namespace YamlText {
/// Characters no scalar may hold as they are: C0 and C1 controls, DEL, the byte-order mark
/// (readers drop it) and U+2028/9 (line breaks to YAML 1.1 readers). Written as escapes.
bool mustEscape(QChar c);
/// True when text written plain would be read back as something other than this string.
bool needsQuotes(const QString& text);
/// The scalar as YAML: plain when safe, otherwise double-quoted with escapes.
QString quoted(const QString& text);
QString scalar(const QString& text, YamlTree::ScalarStyle style);
/// A key as YAML (topic names as keys may need quotes).
QString key(const QString& text);
/// A YAML 1.1 boolean as the ROS 1 parameter server reads it (true/True/yes/on/...).
bool isTrue(const QString& text);
bool isFalse(const QString& text);
/// True for roslaunch substitutions such as "$(arg qos)".
bool isSubstitution(const QString& text);
} // namespace YamlText
