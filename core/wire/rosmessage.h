// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>
#include <QVariant>

/// One field of a ROS 1 message type.
struct RosField
{
    QString name;
    QString type; ///< element type: "uint32", "time", "std_msgs/Header", ...
    bool isArray = false;
    qint64 fixedLength = -1; ///< arrays: element count (up to 2^32 - 1), or -1 for a variable-length array
};

/// A ROS 1 message type: its fields in wire order (constants are not on the wire).
struct RosMessageType
{
    QString name;
    QList<RosField> fields;
};

/// Message types parsed from full definitions, as ShapeShifter and mqtt_client carry them
/// (the main type's fields, then each dependency after a "MSG: pkg/Type" line).
///
/// Needs no roscpp: a definition text is all it needs.
///
/// A ROS 2 registry reads ROS 2 `.msg` files instead (one type a definition, as they come from the
/// interface packages): types are named `pkg/msg/Type` (`pkg/Type` and a bare `Type` of the same
/// package are normalised to it), `Header` is no shorthand, bounds (`string<=10`, `T[<=5]`) are
/// kept out of the wire type, default values after the name are ignored, and time is
/// `builtin_interfaces/msg/Time`, a message like any other.
class RosTypeRegistry
{
    Q_DECLARE_TR_FUNCTIONS(RosTypeRegistry)
public:
    enum class Dialect { Ros1, Ros2 };
    explicit RosTypeRegistry(Dialect dialect = Dialect::Ros1)
        : m_dialect(dialect)
    { }
    Dialect dialect() const { return m_dialect; }
    /// A ROS 2 type name in its registry form: `pkg/Type` and `pkg/msg/Type` give `pkg/msg/Type`.
    static QString ros2TypeName(const QString& name);

    Result<void> addDefinition(const QString& type, const QString& definition);
    const RosMessageType* find(const QString& type) const;
    bool contains(const QString& type) const { return m_types.contains(type); }
    /// Sizes at or above this are "too large for any message" (saturated, never overflowed).
    static constexpr qint64 kHugeSize = qint64(1) << 62;
    /// Bytes on the wire when every field has a fixed size, else -1 (saturated at kHugeSize).
    qint64 fixedSize(const QString& type) const;
    /// The fewest bytes any value of the type takes on the wire (saturated at kHugeSize, which
    /// also stands for a type that contains itself and so has no finite value).
    qint64 minSize(const QString& type) const;

    static bool isBuiltin(const QString& type);
    /// Wire size of a builtin, or -1 for string.
    static int builtinSize(const QString& type);

private:
    qint64 fixedSize(const QString& type, int depth) const;
    qint64 minSize(const QString& type, int depth) const;

    Dialect m_dialect = Dialect::Ros1;
    QHash<QString, RosMessageType> m_types;
    mutable QHash<QString, qint64> m_fixedSizes;
    mutable QHash<QString, qint64> m_minSizes;
};

/// A decoded message as a tree: messages have fields, arrays have (some of) their elements.
struct RosValue
{
    enum Kind { Scalar, Message, Array };
    QString name;
    QString type;
    Kind kind = Scalar;
    QVariant value; ///< scalars; for byte arrays a hex preview
    QList<RosValue> children;
    quint32 arrayLength = 0; ///< arrays: the full length
    bool truncated = false; ///< arrays: fewer children than elements; strings: cut

    /// "name: value" lines, nested by two spaces (for tests and the CLI).
    QStringList toLines(int indent = 0) const;
    /// The child at a dotted path ("header.stamp"), or nullptr.
    const RosValue* find(const QString& path) const;
};

/// How much of a large message is turned into values (the rest is skipped, not read), and the
/// budget of work per message: bytes, fields and array elements visited. The bytes and the
/// definition come from whoever published them; past a budget the message is a decode error.
struct RosDecodeLimits
{
    int maxArrayElements = 16;
    int maxStringChars = 4096;
    int maxDepth = 32;
    qint64 maxBytes = 64 * 1024 * 1024;
    qint64 maxSteps = 1'000'000; ///< fields and array elements visited, shown or skipped
    qint64 maxValues = 50'000; ///< values built (each costs memory, unlike a skipped one)
};

/// Decodes ROS 1 serialized bytes with a type registry.
class RosMessageDecoder
{
    Q_DECLARE_TR_FUNCTIONS(RosMessageDecoder)
public:
    static Result<RosValue> decode(const RosTypeRegistry& registry, const QString& type,
                                   const QByteArray& data, const RosDecodeLimits& limits = {});
    /// Decodes a ROS 2 message as DDS carries it: CDR (XCDR1) after a 4-byte encapsulation header
    /// (little- or big-endian, as the header says), aligned as CDR aligns, with a ROS 2 registry.
    /// Same limits and the same error rules as decode().
    static Result<RosValue> decodeCdr(const RosTypeRegistry& registry, const QString& type,
                                      const QByteArray& data, const RosDecodeLimits& limits = {});
    /// Steps the last decode() on this thread took (for tests of the work bound).
    static qint64 lastSteps();
};

/// A ROS time (or duration) as "sec.nsec" with nine digits of nanoseconds.
QString rosTimeText(qint64 sec, qint64 nsec);
