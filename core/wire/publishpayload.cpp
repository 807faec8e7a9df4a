// SPDX-License-Identifier: MIT
#include "publishpayload.h"

#include "base/yamlvariant.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

#include <QJsonDocument>
#include <QJsonParseError>

std::optional<QByteArray> PublishPayload::build(Format format, const QString& text, QString* error,
                                                const RosTypeRegistry* registry, const RosMsgTypeInfo* type,
                                                qint64 nowNs)
{
    const QByteArray utf8 = text.toUtf8();
    if (format == Format::Text)
        return utf8;
    if (format == Format::Json) {
        QJsonParseError parse {};
        QJsonDocument::fromJson(utf8, &parse);
        if (parse.error != QJsonParseError::NoError) {
            if (error)
                *error = tr("not JSON: %1 at character %2").arg(parse.errorString()).arg(parse.offset);
            return std::nullopt;
        }
        return utf8;
    }
    if (!registry || !type) {
        if (error)
            *error = tr("no ROS type is announced for this topic");
        return std::nullopt;
    }
    QString why;
    const std::optional<QVariant> value = YamlVariant::parse(utf8, &why);
    if (!value) {
        if (error)
            *error = tr("not YAML or JSON: %1").arg(why);
        return std::nullopt;
    }
    // mqtt_client for ROS 2 sends CDR as its RMW serializes, for ROS 1 roscpp's serialization
    const bool ros2 = type->dialect == RosTypeRegistry::Dialect::Ros2;
    const std::optional<QByteArray> bytes = ros2
        ? RosMessageEncoder::encodeCdr(*registry, type->name, *value, &why)
        : RosMessageEncoder::encode(*registry, type->name, *value, &why);
    if (!bytes) {
        if (error)
            *error = tr("not a %1: %2").arg(type->name, why);
        return std::nullopt;
    }
    return type->stamped ? MqttClientWire::stamped(nowNs, *bytes, type->dialect) : *bytes;
}

PublishPayload::Prefill PublishPayload::rosMessage(const RosTypeRegistry& registry,
                                                   const RosMsgTypeInfo& type, const QByteArray& lastPayload)
{
    Prefill out;
    QString why;
    if (!lastPayload.isEmpty()) {
        RosDecodeLimits limits;
        limits.maxArrayElements = 4096;
        limits.maxStringChars = 64 * 1024;
        limits.maxBytes = 4 * 1024 * 1024;
        if (const auto value = MqttClientWire::decodePayload(registry, type, lastPayload, &why, limits)) {
            if (const auto yaml = RosMessageEncoder::toYaml(*value)) {
                out.text = *yaml;
                out.note = tr("Values of the last message.");
                return out;
            }
            why = tr("the last message is too large to edit here");
        }
    } else {
        why = tr("no message yet");
    }
    if (const auto zero = RosMessageEncoder::zeroValue(registry, type.name, &why))
        out.text = RosMessageEncoder::toYaml(*zero).value_or(QString());
    out.note = tr("Zero values (%1).").arg(why);
    return out;
}
