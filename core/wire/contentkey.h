// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QByteArrayView>
#include <QHashFunctions>
#include <QtGlobal>

/// What both ends of a bridge can tell of one message's content without a stamp (issue 45): a hash
/// of its bytes and their count. mqtt_client sends a ROS message's serialization as it is (after
/// the injected stamp when stamped), so the message going into a bridge and the payload coming out
/// have one key. At most kHashedBytes are hashed (bounded work per message); two messages that
/// differ only past them, with one size, have one key and are told apart no better than identical
/// ones (ContentMatcher counts them as ambiguous).
struct ContentKey
{
    quint64 hash = 0;
    qsizetype size = 0;

    static constexpr qsizetype kHashedBytes = 4096;
    static ContentKey of(QByteArrayView bytes);
    /// An MQTT payload of mqtt_client's wire: the message after `stampBytes` of injected stamp
    /// (MqttClientWire::stampBytes(), 0 when not stamped); nullopt when the payload is shorter.
    static std::optional<ContentKey> ofPayload(QByteArrayView payload, qsizetype stampBytes);
    /// The key of a text, none without one (PrimitiveText's answers).
    static std::optional<ContentKey> ofText(const std::optional<QByteArray>& text)
    {
        return text ? std::optional<ContentKey>(of(*text)) : std::nullopt;
    }

    bool operator==(const ContentKey& o) const { return hash == o.hash && size == o.size; }
};

inline size_t qHash(const ContentKey& key, size_t seed = 0) noexcept
{
    return qHashMulti(seed, key.hash, key.size);
}
