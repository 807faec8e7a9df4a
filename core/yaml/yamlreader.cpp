// SPDX-License-Identifier: MIT
#include "yamlreader.h"

#include "text/exactutf8.h"
#include "files/regularfile.h"
#include "yaml/yamllimits.h"

#include <cmath>
#include <QFile>

using namespace Qt::StringLiterals;

Result<YAML::Node> YamlReader::parse(const QByteArray& text) const
{
    try {
        return YamlLimits::load(text);
    } catch (const YamlLimits::Exceeded& e) {
        const YamlLimits::Violation& v = e.violation;
        return LocatedError {v.message, v.pos, {}, m_style, v.code, v.fix};
    } catch (const YAML::Exception& e) {
        LocatedError error = errorAt(e.mark, exactUtf8(e.msg));
        error.code = u"yaml-syntax"_s;
        return error;
    }
}

Result<QByteArray> YamlReader::readFile(const QString& path)
{
    // A regular file only (a FIFO or /dev/zero is refused, not waited on or read without end);
    // one byte past the limit, so that YamlLimits says it is too large.
    return RegularFile::readHead(path, YamlLimits::maxBytes + 1).inFile(path);
}

LocatedError YamlReader::error(const QString& message) const
{
    return LocatedError {message, {}, {}, m_style};
}

LocatedError YamlReader::errorAt(const YAML::Mark& mark, const QString& message) const
{
    return LocatedError {message, {mark.line, mark.column}, {}, m_style};
}

Status YamlReader::checkKeys(const YAML::Node& map, const QStringList& known) const
{
    for (const auto& kv : map) {
        const QString key = text(kv.first);
        if (!known.contains(key))
            return errorAt(kv.first, tr("unknown key '%1' (known: %2)").arg(key, known.join(u", "_s)));
    }
    return {};
}

QString YamlReader::text(const YAML::Node& node)
{
    return node && node.IsScalar() ? QString::fromStdString(node.Scalar()) : QString();
}

std::optional<double> YamlReader::number(const YAML::Node& node)
{
    if (!node || !node.IsScalar())
        return std::nullopt;
    bool ok = false;
    const double v = text(node).toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

TextPos YamlReader::posOf(const YAML::Node& node)
{
    const YAML::Mark m = node.Mark();
    if (m.is_null())
        return {};
    return {m.line, m.column};
}

Result<YamlField<int>> YamlReader::integer(const YAML::Node& map, const char* key, int min, int max,
                                           int fallback, const QString& message) const
{
    const YAML::Node n = map[key];
    if (!n)
        return YamlField<int> {fallback, {}};
    bool ok = false;
    const int v = text(n).toInt(&ok);
    if (!ok || v < min || v > max)
        return errorAt(n, message);
    return YamlField<int> {v, posOf(n)};
}
