// SPDX-License-Identifier: MIT
#include "publishpayload.h"

#include "yaml/yamlvariant.h"
#include "wire/rosmessage.h"
#include "wire/rosmessageencoder.h"

#include <QJsonDocument>
#include <QJsonParseError>

Result<QByteArray> PublishPayload::build(Format format, const QString& text, const RosTypeRegistry* registry,
                                         const RosMsgTypeInfo* type, qint64 nowNs)
{
    const QByteArray utf8 = text.toUtf8();
    if (format == Format::Text)
        return utf8;
    if (format == Format::Json) {
        QJsonParseError parse {};
        QJsonDocument::fromJson(utf8, &parse);
        if (parse.error != QJsonParseError::NoError)
            return LocatedError {
                tr("not JSON: %1 at character %2").arg(parse.errorString()).arg(parse.offset)};
        return utf8;
    }
    if (!registry || !type)
        return LocatedError {tr("no ROS type is announced for this topic")};
    const Result<QVariant> value = YamlVariant::read(utf8);
    if (!value)
        return LocatedError {tr("not YAML or JSON: %1").arg(value.error().toString())};
    // mqtt_client for ROS 2 sends CDR as its RMW serializes, for ROS 1 roscpp's serialization
    const bool ros2 = type->dialect == RosTypeRegistry::Dialect::Ros2;
    const Result<QByteArray> bytes = ros2 ? RosMessageEncoder::encodeCdr(*registry, type->name, *value)
                                          : RosMessageEncoder::encode(*registry, type->name, *value);
    if (!bytes)
        return LocatedError {tr("not a %1: %2").arg(type->name, bytes.error().toString())};
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
        const Result<RosValue> value = MqttClientWire::decodePayload(registry, type, lastPayload, limits);
        if (value) {
            if (const auto yaml = RosMessageEncoder::toYaml(*value)) {
                out.text = *yaml;
                out.note = tr("Values of the last message.");
                return out;
            }
            why = tr("the last message is too large to edit here");
        } else {
            why = value.error().toString();
        }
    } else {
        why = tr("no message yet");
    }
    if (const Result<RosValue> zero = RosMessageEncoder::zeroValue(registry, type.name); zero)
        out.text = RosMessageEncoder::toYaml(*zero).value_or(QString());
    else
        why = zero.error().toString();
    out.note = tr("Zero values (%1).").arg(why);
    return out;
}
