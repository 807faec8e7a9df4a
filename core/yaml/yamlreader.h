// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <yaml-cpp/yaml.h>

/// A value read from YAML with where it was written.
template<typename T> struct YamlField
{
    T value {};
    TextPos pos; ///< invalid when the key was absent (`value` is then the caller's default)
    bool present() const { return pos.isValid(); }
};

/// What every YAML reader of Bridgescope does the same way: the text within YamlLimits, the
/// position of an error, unknown keys, scalars as text and numbers. Each reader keeps its own
/// messages and the meaning of its keys.
class YamlReader
{
    Q_DECLARE_TR_FUNCTIONS(YamlReader)
public:
    explicit YamlReader(LocatedError::Style style = LocatedError::Style::LineColumn)
        : m_style(style)
    { }

    /// The first document of `text` after YamlLimits::check(); a syntax error (code "yaml-syntax")
    /// or a limit passed (the limit's code and fix) is located where yaml-cpp or the limit found it.
    Result<YAML::Node> parse(const QByteArray& text) const;
    /// The bytes of a YAML file, at most one past YamlLimits::maxBytes (enough for check() to say
    /// it is too large; /dev/zero is not read for ever); the error names the file.
    static Result<QByteArray> readFile(const QString& path);
    /// `read` (a reader of YAML bytes returning a Result) applied to the file at `path`; every
    /// error names the file.
    template<typename Read>
    static auto readFileWith(const QString& path, Read read) -> decltype(read(QByteArray()))
    {
        const Result<QByteArray> bytes = readFile(path);
        if (!bytes)
            return bytes.error();
        return read(*bytes).inFile(path);
    }

    /// An error about the whole text (no place).
    LocatedError error(const QString& message) const;
    LocatedError errorAt(const YAML::Mark& mark, const QString& message) const;
    LocatedError errorAt(const YAML::Node& node, const QString& message) const
    {
        return errorAt(node.Mark(), message);
    }
    /// Every key of `map` is one of `known`; else "unknown key 'K' (known: …)" at the first other.
    Status checkKeys(const YAML::Node& map, const QStringList& known) const;

    /// A scalar's text; empty for a missing node, a list or a map.
    static QString text(const YAML::Node& node);
    /// A scalar read as a finite number (QString::toDouble: no hex, no ".inf").
    static std::optional<double> number(const YAML::Node& node);
    /// Where a node was written; invalid for a node not read from text.
    static TextPos posOf(const YAML::Node& node);
    /// `map[key]` as a whole number from `min` to `max`, with its place; absent: `fallback`, no
    /// place. Out of range or not a number: `message` at the value.
    Result<YamlField<int>> integer(const YAML::Node& map, const char* key, int min, int max, int fallback,
                                   const QString& message) const;

private:
    LocatedError::Style m_style;
};
