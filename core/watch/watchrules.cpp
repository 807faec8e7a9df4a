// SPDX-License-Identifier: MIT
#include "watchrules.h"

#include "yaml/yamlreader.h"

#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
const char* const kKeys[] = {"latency_p99_ms", "min_rate_hz",   "min_rate_percent",      "max_loss_percent",
                             "stall_seconds",  "stall_periods", "source_stopped_seconds"};
static_assert(std::size(kKeys) == LinkRules::SettingCount);

/// Rules name the line of an error, not its column.
const YamlReader kReader(LocatedError::Style::Line);

/// A number that is finite and not negative.
std::optional<double> number(const YAML::Node& node)
{
    double v = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, v) || !std::isfinite(v) || v < 0)
        return std::nullopt;
    return v;
}

/// `key: 5` (the alert level) or `key: {warning: 2, alert: 5}`.
Result<Threshold> threshold(const YAML::Node& node, const QString& key)
{
    Threshold t;
    if (node.IsScalar()) {
        if (const auto v = number(node)) {
            t.alert = *v;
            return t;
        }
    } else if (node.IsMap()) {
        for (const auto& kv : node) {
            const QString level = YamlReader::text(kv.first);
            const auto v = number(kv.second);
            if (!v || (level != u"warning"_s && level != u"alert"_s))
                return kReader.errorAt(
                    kv.first,
                    WatchRules::tr("%1 takes warning and alert levels, each a number ≥ 0").arg(key));
            (level == u"warning"_s ? t.warning : t.alert) = *v;
        }
        if (t.isSet())
            return t;
    }
    return kReader.errorAt(node, WatchRules::tr("%1 takes a number ≥ 0 or {warning: N, alert: N}").arg(key));
}

/// The settings of one map; `match` is skipped (the caller reads it).
Status readSettings(const YAML::Node& map, QList<std::pair<LinkRules::Setting, Threshold>>* out)
{
    for (const auto& kv : map) {
        const QString key = YamlReader::text(kv.first);
        if (key == u"match"_s)
            continue;
        const auto setting = LinkRules::settingOf(key);
        if (!setting) {
            QStringList known;
            for (const char* k : kKeys)
                known << QString::fromLatin1(k);
            return kReader.errorAt(
                kv.first, WatchRules::tr("unknown setting '%1' (known: %2)").arg(key, known.join(u", "_s)));
        }
        const Result<Threshold> t = threshold(kv.second, key);
        if (!t)
            return t.error();
        out->append(std::make_pair(*setting, *t));
    }
    return {};
}

QString levels(const Threshold& t)
{
    const auto num = [](double v) { return QString::number(v, 'g', 10); };
    if (std::isnan(t.warning))
        return num(t.alert);
    if (std::isnan(t.alert))
        return u"{warning: %1}"_s.arg(num(t.warning));
    return u"{warning: %1, alert: %2}"_s.arg(num(t.warning), num(t.alert));
}

QString quoted(const QString& text)
{
    QString q = text;
    q.replace(u'\\', u"\\\\"_s).replace(u'"', u"\\\""_s);
    return u'"' + q + u'"';
}
} // namespace

QString LinkRules::key(Setting s)
{
    return QString::fromLatin1(kKeys[std::size_t(s)]);
}

std::optional<LinkRules::Setting> LinkRules::settingOf(const QString& key)
{
    for (int i = 0; i < SettingCount; ++i)
        if (key == QLatin1String(kKeys[i]))
            return Setting(i);
    return std::nullopt;
}

LinkRules LinkRules::defaults()
{
    LinkRules r;
    r[StallPeriods].alert = 5;
    r[SourceStoppedSeconds].warning = 3;
    r[MaxLossPercent] = {1, 5};
    r[MinRatePercent].alert = 50;
    return r;
}

Result<WatchRules> WatchRules::read(const QByteArray& yaml)
{
    const Result<YAML::Node> parsed = kReader.parse(yaml);
    if (!parsed)
        return parsed.error();
    const YAML::Node& root = *parsed;
    WatchRules rules;
    if (root.IsNull())
        return rules; // an empty file: the defaults
    if (!root.IsMap())
        return kReader.error(tr("rules are a mapping with defaults and links"));
    if (const Status s = kReader.checkKeys(root, {u"defaults"_s, u"links"_s}); !s)
        return s.error();
    if (const YAML::Node d = root["defaults"]) {
        if (!d.IsMap())
            return kReader.errorAt(d, tr("defaults is a mapping of settings"));
        QList<std::pair<LinkRules::Setting, Threshold>> settings;
        if (const Status s = readSettings(d, &settings); !s)
            return s.error();
        for (const auto& [s, t] : std::as_const(settings))
            rules.defaults[s] = t;
    }
    if (const YAML::Node links = root["links"]) {
        if (const Status s = readOverrides(links, &rules.overrides); !s)
            return s.error();
    }
    return rules;
}

Status WatchRules::readOverrides(const YAML::Node& links, QList<Override>* out)
{
    if (!links.IsSequence())
        return kReader.errorAt(links, tr("links is a list of {match: PATTERN, settings...}"));
    if (links.size() > std::size_t(kMaxLinkRules))
        return kReader.errorAt(links,
                               tr("%1 entries in links; at most %2 are read (merge patterns with * and ?)")
                                   .arg(links.size())
                                   .arg(kMaxLinkRules));
    for (const YAML::Node& entry : links) {
        const YAML::Node match = entry.IsMap() ? entry["match"] : YAML::Node();
        if (!match || !match.IsScalar() || match.Scalar().empty())
            return kReader.errorAt(entry, tr("every entry of links needs a match pattern"));
        Override o;
        o.match = QString::fromStdString(match.Scalar());
        if (o.match.size() > kMaxPatternChars)
            return kReader.errorAt(
                match,
                tr("a match pattern of %1 characters; at most %2").arg(o.match.size()).arg(kMaxPatternChars));
        if (const Status s = readSettings(entry, &o.settings); !s)
            return s.error();
        *out << o;
    }
    return {};
}

Result<WatchRules> WatchRules::readFile(const QString& path)
{
    return YamlReader::readFileWith(path, &WatchRules::read);
}

QByteArray WatchRules::toYaml() const
{
    QString out
        = u"# bridgescope watch rules: a number is the alert level; {warning: N, alert: N} sets both\n"
          u"defaults:\n"_s;
    for (int i = 0; i < LinkRules::SettingCount; ++i) {
        const Threshold& t = defaults[LinkRules::Setting(i)];
        if (t.isSet())
            out += u"  %1: %2\n"_s.arg(LinkRules::key(LinkRules::Setting(i)), levels(t));
    }
    if (!overrides.isEmpty())
        out += u"links:\n"_s;
    for (const Override& o : overrides) {
        out += u"  - match: %1\n"_s.arg(quoted(o.match));
        for (const auto& [s, t] : o.settings)
            out += u"    %1: %2\n"_s.arg(LinkRules::key(s), levels(t));
    }
    return out.toUtf8();
}

namespace {
/// Whether `text` is `pattern` where '?' is any one character (both the same length).
bool sameWithAnyChar(QStringView pattern, QStringView text)
{
    for (qsizetype i = 0; i < pattern.size(); ++i)
        if (pattern[i] != u'?' && pattern[i] != text[i])
            return false;
    return true;
}

/// '*' matches any run of characters, '/' included; '?' one character; an empty text nothing.
/// The parts before the first and after the last '*' are compared in place first (most patterns
/// are "/prefix/*" or "*suffix": settled without looking at the rest of a long name); between them,
/// greedy, going back only to the last '*'. No allocation; at most |pattern| × |text| steps, which
/// go to `steps`.
bool glob(QStringView pattern, QStringView text, qint64& steps)
{
    if (text.isEmpty())
        return false;
    const qsizetype first = pattern.indexOf(u'*');
    if (first < 0)
        return pattern.size() == text.size() && sameWithAnyChar(pattern, text);
    const qsizetype last = pattern.lastIndexOf(u'*');
    const qsizetype tail = pattern.size() - last - 1;
    if (first + tail > text.size() || !sameWithAnyChar(pattern.left(first), text.left(first))
        || !sameWithAnyChar(pattern.right(tail), text.right(tail)))
        return false;
    pattern = pattern.mid(first, last + 1 - first); // starts and ends with '*'
    text = text.mid(first, text.size() - first - tail);
    qsizetype p = 0, t = 0, star = -1, resume = 0;
    while (t < text.size()) {
        ++steps;
        if (p < pattern.size() && pattern[p] == u'*') {
            star = p++;
            resume = t;
        } else if (p < pattern.size() && (pattern[p] == u'?' || pattern[p] == text[t])) {
            ++p;
            ++t;
        } else if (star >= 0) {
            p = star + 1;
            t = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == u'*')
        ++p;
    return p == pattern.size();
}
} // namespace

bool WatchRules::matches(const QString& pattern, const LinkKey& key, qint64* steps)
{
    qint64 ignored = 0;
    qint64& counted = steps ? *steps : ignored;
    const QStringView p(pattern);
    if (p.startsWith(u"client:"))
        return glob(p.mid(7), key.client, counted);
    if (p.startsWith(u"config:"))
        return glob(p.mid(7), key.config, counted);
    return glob(p, key.rosTopic, counted) || glob(p, key.mqttTopic, counted);
}

LinkRules WatchRules::forLink(const LinkKey& key) const
{
    LinkRules r = defaults;
    for (const Override& o : overrides) {
        if (!matches(o.match, key))
            continue;
        for (const auto& [s, t] : o.settings)
            r[s] = t;
    }
    return r;
}
