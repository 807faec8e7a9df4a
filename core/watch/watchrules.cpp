// SPDX-License-Identifier: MIT
#include "watchrules.h"

#include "base/yamllimits.h"

#include <QRegularExpression>
#include <yaml-cpp/yaml.h>

using namespace Qt::StringLiterals;

namespace {
const char* const kKeys[] = {"latency_p99_ms", "min_rate_hz",   "min_rate_percent",      "max_loss_percent",
                             "stall_seconds",  "stall_periods", "source_stopped_seconds"};
static_assert(std::size(kKeys) == LinkRules::SettingCount);

QString where(const YAML::Mark& mark)
{
    return WatchRules::tr("line %1").arg(mark.line + 1);
}

/// A number that is finite and not negative.
std::optional<double> number(const YAML::Node& node)
{
    double v = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, v) || !std::isfinite(v) || v < 0)
        return std::nullopt;
    return v;
}

/// `key: 5` (the alert level) or `key: {warning: 2, alert: 5}`.
std::optional<Threshold> threshold(const YAML::Node& node, const QString& key, QString* error)
{
    Threshold t;
    if (node.IsScalar()) {
        if (const auto v = number(node)) {
            t.alert = *v;
            return t;
        }
    } else if (node.IsMap()) {
        for (const auto& kv : node) {
            const QString level = QString::fromStdString(kv.first.as<std::string>(""));
            const auto v = number(kv.second);
            if (!v || (level != u"warning"_s && level != u"alert"_s)) {
                *error = WatchRules::tr("%1: %2 takes warning and alert levels, each a number ≥ 0")
                             .arg(where(kv.first.Mark()), key);
                return std::nullopt;
            }
            (level == u"warning"_s ? t.warning : t.alert) = *v;
        }
        if (t.isSet())
            return t;
    }
    *error
        = WatchRules::tr("%1: %2 takes a number ≥ 0 or {warning: N, alert: N}").arg(where(node.Mark()), key);
    return std::nullopt;
}

/// The settings of one map; `match` is skipped (the caller reads it).
bool readSettings(const YAML::Node& map, QList<std::pair<LinkRules::Setting, Threshold>>* out, QString* error)
{
    for (const auto& kv : map) {
        const QString key = QString::fromStdString(kv.first.as<std::string>(""));
        if (key == u"match"_s)
            continue;
        const auto setting = LinkRules::settingOf(key);
        if (!setting) {
            QStringList known;
            for (const char* k : kKeys)
                known << QString::fromLatin1(k);
            *error = WatchRules::tr("%1: unknown setting '%2' (known: %3)")
                         .arg(where(kv.first.Mark()), key, known.join(u", "_s));
            return false;
        }
        const auto t = threshold(kv.second, key, error);
        if (!t)
            return false;
        out->append(std::make_pair(*setting, *t));
    }
    return true;
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

std::optional<WatchRules> WatchRules::fromYaml(const QByteArray& yaml, QString* error)
{
    QString why;
    const auto fail = [&](const QString& text) -> std::optional<WatchRules> {
        if (error)
            *error = text;
        return std::nullopt;
    };
    YAML::Node root;
    try {
        root = YamlLimits::load(yaml);
    } catch (const YAML::Exception& e) {
        return fail(tr("%1: %2").arg(where(e.mark), QString::fromStdString(e.msg)));
    }
    WatchRules rules;
    if (root.IsNull())
        return rules; // an empty file: the defaults
    if (!root.IsMap())
        return fail(tr("rules are a mapping with defaults and links"));
    for (const auto& kv : root) {
        const QString key = QString::fromStdString(kv.first.as<std::string>(""));
        if (key != u"defaults"_s && key != u"links"_s)
            return fail(tr("%1: unknown key '%2' (known: defaults, links)").arg(where(kv.first.Mark()), key));
    }
    if (const YAML::Node d = root["defaults"]) {
        if (!d.IsMap())
            return fail(tr("%1: defaults is a mapping of settings").arg(where(d.Mark())));
        QList<std::pair<LinkRules::Setting, Threshold>> settings;
        if (!readSettings(d, &settings, &why))
            return fail(why);
        for (const auto& [s, t] : std::as_const(settings))
            rules.defaults[s] = t;
    }
    if (const YAML::Node links = root["links"]) {
        if (!links.IsSequence())
            return fail(tr("%1: links is a list of {match: PATTERN, settings...}").arg(where(links.Mark())));
        for (const YAML::Node& entry : links) {
            const YAML::Node match = entry.IsMap() ? entry["match"] : YAML::Node();
            if (!match || !match.IsScalar() || match.Scalar().empty())
                return fail(tr("%1: every entry of links needs a match pattern").arg(where(entry.Mark())));
            Override o;
            o.match = QString::fromStdString(match.Scalar());
            if (!readSettings(entry, &o.settings, &why))
                return fail(why);
            rules.overrides << o;
        }
    }
    return rules;
}

std::optional<WatchRules> WatchRules::load(const QString& path, QString* error)
{
    QString why;
    const std::optional<QByteArray> bytes = YamlLimits::readFile(path, &why);
    std::optional<WatchRules> rules = bytes ? fromYaml(*bytes, &why) : std::nullopt;
    if (!rules && error)
        *error = bytes ? path + u": "_s + why : why;
    return rules;
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

bool WatchRules::matches(const QString& pattern, const LinkKey& key)
{
    // '*' matches any run of characters, '/' included; '?' one character.
    const auto glob = [](const QString& p, const QString& text) {
        if (text.isEmpty())
            return false;
        QString rx;
        for (const QChar c : p)
            rx += c == u'*' ? u".*"_s : c == u'?' ? u"."_s : QRegularExpression::escape(QString(c));
        return QRegularExpression(QRegularExpression::anchoredPattern(rx)).match(text).hasMatch();
    };
    if (pattern.startsWith(u"client:"_s))
        return glob(pattern.mid(7), key.client);
    if (pattern.startsWith(u"config:"_s))
        return glob(pattern.mid(7), key.config);
    return glob(pattern, key.rosTopic) || glob(pattern, key.mqttTopic);
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
