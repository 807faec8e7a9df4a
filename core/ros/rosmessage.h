// SPDX-License-Identifier: MIT
#pragma once

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
    int fixedLength = -1; ///< arrays: element count, or -1 for a variable-length array
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
class RosTypeRegistry
{
    Q_DECLARE_TR_FUNCTIONS(RosTypeRegistry)
public:
    bool addDefinition(const QString& type, const QString& definition, QString* error = nullptr);
    const RosMessageType* find(const QString& type) const;
    bool contains(const QString& type) const { return m_types.contains(type); }
    /// Bytes on the wire when every field has a fixed size, else -1.
    int fixedSize(const QString& type) const;

    static bool isBuiltin(const QString& type);
    /// Wire size of a builtin, or -1 for string.
    static int builtinSize(const QString& type);

private:
    QHash<QString, RosMessageType> m_types;
    mutable QHash<QString, int> m_fixedSizes;
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

/// How much of a large message is turned into values; the rest is skipped, not read.
struct RosDecodeLimits
{
    int maxArrayElements = 16;
    int maxStringChars = 4096;
    int maxDepth = 32;
};

/// Decodes ROS 1 serialized bytes with a type registry.
class RosMessageDecoder
{
    Q_DECLARE_TR_FUNCTIONS(RosMessageDecoder)
public:
    static std::optional<RosValue> decode(const RosTypeRegistry& registry, const QString& type,
                                          const QByteArray& data, QString* error = nullptr,
                                          const RosDecodeLimits& limits = {});
};

/// A ROS time (or duration) as "sec.nsec" with nine digits of nanoseconds.
QString rosTimeText(qint64 sec, qint64 nsec);
