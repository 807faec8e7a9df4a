// SPDX-License-Identifier: MIT
#include "mqttclientrelease.h"

#include "config/bridgeconfig.h"
#include "yaml/yamltree.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

namespace {
constexpr MqttClientRelease kAll[]
    = {MqttClientRelease::V2_2,   MqttClientRelease::V2_3,   MqttClientRelease::V2_4_0,
       MqttClientRelease::V2_4_1, MqttClientRelease::V2_4_2, MqttClientRelease::V2_5};

/// The texts' translation context.
class Text
{
    Q_DECLARE_TR_FUNCTIONS(MqttClientReleases)
};

/// Raises `range.lowest` to `since` for what `what` names, and says so once.
void needs(MqttClientReleases::Range* range, MqttClientRelease since, const QString& what)
{
    if (since <= MqttClientReleases::kOldest)
        return;
    const QString reason = u"%1 (%2)"_s.arg(what, MqttClientReleases::name(since));
    if (!range->reasons.contains(reason))
        range->reasons << reason;
    range->lowest = std::max(range->lowest, since);
}
} // namespace

namespace MqttClientReleases {

QString name(MqttClientRelease release)
{
    switch (release) {
    case MqttClientRelease::V2_2:
        return u"2.2"_s;
    case MqttClientRelease::V2_3:
        return u"2.3"_s;
    case MqttClientRelease::V2_4_0:
        return u"2.4.0"_s;
    case MqttClientRelease::V2_4_1:
        return u"2.4.1"_s;
    case MqttClientRelease::V2_4_2:
        return u"2.4.2"_s;
    case MqttClientRelease::V2_5:
        return u"2.5"_s;
    }
    return {};
}

QStringList names()
{
    QStringList list;
    for (MqttClientRelease r : kAll)
        list << name(r);
    return list;
}

std::optional<MqttClientRelease> fromName(const QString& text)
{
    QString t = text.trimmed();
    if (t.startsWith(u'v') || t.startsWith(u'V'))
        t = t.mid(1);
    if (t == u"2.2.1"_s)
        return MqttClientRelease::V2_2;
    for (MqttClientRelease r : kAll) {
        const QString n = name(r);
        if (t == n || (n.count(u'.') == 1 && t == n + u".0"_s))
            return r;
    }
    return std::nullopt;
}

Range detect(const BridgeConfig& config)
{
    Range range;
    if (config.layout == ConfigLayout::MqttBridge)
        return range; // not mqtt_client's: no release of it loads it, none is judged
    if (config.layout == ConfigLayout::Ros1) {
        range.highest = kLastRos1;
        range.reasons << Text::tr("the ROS 1 layout (up to %1)").arg(name(kLastRos1));
    }
    for (OptionScope scope : {OptionScope::Broker, OptionScope::Client})
        for (const QString& path : config.block(scope).values.paths())
            if (const OptionSpec* spec = OptionSchema::find(scope, path))
                needs(&range, spec->since, u"%1.%2"_s.arg(OptionSchema::scopeKey(scope), path));
    for (const Mapping& m : config.mappings) {
        for (const QString& path : m.block.values.paths())
            if (const OptionSpec* spec = OptionSchema::find(m.scope(), path))
                needs(&range, spec->since, path);
        if (YamlText::isTrue(m.effective(u"primitive"_s))
            && !primitiveTypeKnown(m.value(u"ros_type"_s), MqttClientRelease::V2_4_1))
            needs(&range, MqttClientRelease::V2_4_2, Text::tr("a primitive %1").arg(m.value(u"ros_type"_s)));
    }
    return range;
}

MqttClientRelease defaultTarget(const BridgeConfig& config)
{
    return detect(config).highest;
}

QString summary(const BridgeConfig& config, std::optional<MqttClientRelease> chosen)
{
    if (config.layout == ConfigLayout::MqttBridge)
        return Text::tr("an mqtt_bridge config: no release of mqtt_client loads it");
    const Range range = detect(config);
    const MqttClientRelease target = chosen.value_or(range.highest);
    const QString loads = !range.loadsSomewhere() ? Text::tr("no release loads all of it")
        : range.lowest == range.highest
        ? Text::tr("it loads in %1 only").arg(name(range.lowest))
        : Text::tr("it loads in %1 to %2").arg(name(range.lowest), name(range.highest));
    return Text::tr("checked against mqtt_client %1%2; %3%4")
        .arg(name(target), chosen ? QString() : Text::tr(" (auto)"), loads,
             range.reasons.isEmpty() ? QString() : u" ("_s + range.reasons.join(u", "_s) + u')');
}

bool primitiveTypeKnown(const QString& rosType, MqttClientRelease release)
{
    const QString type = rosType.section(u'/', -1);
    return type != u"UInt8MultiArray"_s || release >= MqttClientRelease::V2_4_2;
}

} // namespace MqttClientReleases
