// SPDX-License-Identifier: MIT
#pragma once

#include "wire/mqttclientwire.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

class RosTypeRegistry;

/// The bytes a user publishes from what they typed: text as it is, JSON checked first, or a ROS
/// message from YAML or JSON serialized as mqtt_client does (with its send stamp when stamped).
class PublishPayload
{
    Q_DECLARE_TR_FUNCTIONS(PublishPayload)
public:
    enum class Format { Text, Json, RosMessage };

    /// The payload, or the error saying what is wrong (nothing should be sent then).
    /// RosMessage needs the announced type and its registry; `nowNs` is the stamp of a stamped one.
    static Result<QByteArray> build(Format format, const QString& text,
                                    const RosTypeRegistry* registry = nullptr,
                                    const RosMsgTypeInfo* type = nullptr, qint64 nowNs = 0);

    struct Prefill
    {
        QString text; ///< YAML of the message's fields
        QString note; ///< where the values come from
    };
    /// A ROS message text to start from: the last payload's values when it decodes whole, else
    /// the type's zero values (and the note says why).
    static Prefill rosMessage(const RosTypeRegistry& registry, const RosMsgTypeInfo& type,
                              const QByteArray& lastPayload);
};
