// SPDX-License-Identifier: MIT
#pragma once

#include "wire/rosmessage.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QVariant>

/// How much one encode may build: bytes written, values visited and nesting. What is encoded comes
/// from a user's text and a definition a broker announced; past a budget it is an error.
struct RosEncodeLimits
{
    qint64 maxBytes = 64 * 1024 * 1024;
    qint64 maxSteps = 1'000'000;
    int maxDepth = 32;
};

/// Serializes a value tree as ROS 1 does (roscpp, and so mqtt_client), or as CDR for ROS 2: the
/// counterpart of RosMessageDecoder, driven by the same registry.
///
/// A message is a map by field name (missing fields take their zero value, unknown names are an
/// error), an array a list (a fixed-length one of exactly its length), a number a number or a
/// string that reads as one, a bool true/false or 0/1, time and duration "sec.nsec" as the decoder
/// writes them, seconds as a number, or a map {secs, nsecs}. A value that does not fit its field
/// (out of range, a fraction for an integer, the wrong kind) is an error naming the field.
class RosMessageEncoder
{
    Q_DECLARE_TR_FUNCTIONS(RosMessageEncoder)
public:
    static Result<QByteArray> encode(const RosTypeRegistry& registry, const QString& type,
                                     const QVariant& value, const RosEncodeLimits& limits = {});
    /// Serializes as rmw does for ROS 2 (and mqtt_client for ROS 2 with it): CDR (XCDR1,
    /// little-endian) after the encapsulation header 00 01 00 00, the counterpart of
    /// RosMessageDecoder::decodeCdr(). The same value rules; a string may not contain NUL.
    static Result<QByteArray> encodeCdr(const RosTypeRegistry& registry, const QString& type,
                                        const QVariant& value, const RosEncodeLimits& limits = {});
    /// A decoded message as YAML in field order that encode() takes back (after YamlVariant);
    /// nullopt when the decode cut anything (a long array or string) or a definition repeats a
    /// field name, as it would not round-trip.
    static std::optional<QString> toYaml(const RosValue& message);
    /// A value of the type with every field zero, empty or of its fixed length.
    static Result<RosValue> zeroValue(const RosTypeRegistry& registry, const QString& type);
};
