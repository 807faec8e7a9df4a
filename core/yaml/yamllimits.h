// SPDX-License-Identifier: MIT
#pragma once

#include "base/textpos.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <yaml-cpp/exceptions.h>

namespace YAML {
class Node;
}

/// Bounds on the YAML text Bridgescope reads, checked before anything builds or walks a tree.
///
/// yaml-cpp shares the node an alias names, so a few hundred bytes of nested aliases ("billion
/// laughs") parse quickly but expand to millions of nodes for every reader that walks, copies or
/// writes the tree. check() runs over the parser's events once, adding the expanded size of an
/// anchor at each alias, and stops at the first limit passed: its time is linear in the text.
class YamlLimits
{
    Q_DECLARE_TR_FUNCTIONS(YamlLimits)
public:
    static constexpr qsizetype maxBytes = 8 * 1024 * 1024; ///< size of the text
    static constexpr int maxDepth = 64; ///< collections inside collections, aliases expanded
    static constexpr qint64 maxNodes = 500000; ///< scalars, lists, maps and aliases as written
    static constexpr qint64 maxAliasNodes = 100000; ///< nodes that aliases repeat, in all
    static constexpr qint64 maxAliasBytes = 8 * 1024 * 1024; ///< scalar bytes that aliases repeat

    /// The first limit a text passes, or its first byte that is not UTF-8.
    struct Violation
    {
        TextPos pos; ///< zero-based line and byte column, as yaml-cpp's marks
        QString code; ///< e.g. "yaml-alias-expansion", "invalid-utf8"
        QString message; ///< which limit and the value that passed it
        QString fix;
    };

    /// Thrown by load(). A YAML::ParserException, so that code reporting YAML errors reports this
    /// one too, with its position.
    class Exceeded : public YAML::ParserException
    {
    public:
        explicit Exceeded(const Violation& v);
        Violation violation;
    };

    /// Nothing when `text` is UTF-8 and within every limit. YAML syntax errors are not reported
    /// here (the loader reports them); only the first document is checked, as YAML::Load reads.
    static std::optional<Violation> check(const QByteArray& text);
    /// "The file is 17 MB, the limit is 8 MB." for a text of `size` bytes past maxBytes (said
    /// without its size when that is not known past maxBytes + 1, what readFile() reads).
    static QString tooLargeMessage(qint64 size);
    /// YAML::Load of the first document of `text` after check(). Throws Exceeded when a limit is
    /// passed and YAML::Exception on a syntax error.
    static YAML::Node load(const QByteArray& text);
    /// Whether `bytes` is valid UTF-8 (no overlong forms, surrogates or code points past U+10FFFF);
    /// `badOffset` receives the offset of the first invalid byte.
    static bool isUtf8(const QByteArray& bytes, qsizetype* badOffset = nullptr);
};
