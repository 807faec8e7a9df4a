// SPDX-License-Identifier: MIT
#pragma once

#include "base/textpos.h"
#include "config/optionschema.h"

#include <QHash>
#include <QList>
#include <QMetaType>
#include <QSet>
#include <QString>
#include <QStringList>

/// The file layouts Bridgescope reads and writes.
enum class ConfigLayout {
    Ros1, ///< mqtt_client ROS 1: bridge.ros2mqtt / bridge.mqtt2ros are lists
    Ros2, ///< mqtt_client ROS 2: <node>: ros__parameters: with topic-keyed maps
    MqttBridge, ///< groove-x/mqtt_bridge: bridge is a list of factories
};

QString layoutName(ConfigLayout layout); ///< "ros1", "ros2", "mqtt_bridge"
bool layoutFromName(const QString& name, ConfigLayout* layout);

/// The direction of one bridge mapping.
enum class Direction { Ros2Mqtt, Mqtt2Ros };

inline OptionScope scopeOf(Direction d)
{
    return d == Direction::Ros2Mqtt ? OptionScope::Ros2Mqtt : OptionScope::Mqtt2Ros;
}

/// The option values of one block (broker, client or a mapping), as written in the file.
///
/// Values keep their text: a qos of `$(arg qos)` stays exactly that, and typed reading happens
/// where a type is needed (validation, the bridge).
class OptionValues
{
public:
    bool has(const QString& path) const { return indexOf(path) >= 0; }
    bool isList(const QString& path) const;
    QString text(const QString& path) const;
    QStringList list(const QString& path) const;
    void setText(const QString& path, const QString& text);
    void setList(const QString& path, const QStringList& list);
    void remove(const QString& path);
    /// Takes over `path` from `other` as it is there (text, list, or not set).
    void copyFrom(const OptionValues& other, const QString& path);
    QStringList paths() const;
    bool isEmpty() const { return m_entries.isEmpty(); }
    bool operator==(const OptionValues& other) const;
    bool operator!=(const OptionValues& other) const { return !(*this == other); }

private:
    struct Entry
    {
        QString path;
        QString text;
        QStringList list;
        bool isList = false;
        bool operator==(const Entry& o) const
        {
            return path == o.path && isList == o.isList && text == o.text && list == o.list;
        }
    };
    int indexOf(const QString& path) const;
    QList<Entry> m_entries;
};

/// A key Bridgescope does not understand, kept with its value so that saving loses nothing.
struct ExtraValue
{
    QStringList path; ///< key path relative to the block that holds it
    QString yaml; ///< the value, as YAML text
    bool operator==(const ExtraValue& o) const { return path == o.path && yaml == o.yaml; }
};

/// Same unknown keys with the same values, in any order (writers put them after known options).
bool sameExtras(const QList<ExtraValue>& a, const QList<ExtraValue>& b);

/// Where a block and its keys were in the file it was read from.
struct SourceMap
{
    int index = -1; ///< position in its list in the file (mappings), -1 when not from a file
    TextPos start;
    QHash<QString, TextPos> keys; ///< option path -> position of its value
    QSet<QString> quoted; ///< option paths whose scalar was quoted in the file
    TextPos keyPos(const QString& path) const { return keys.value(path, start); }
};

/// Values, unknown keys and source positions of one block.
struct OptionBlock
{
    OptionValues values;
    QList<ExtraValue> extras;
    SourceMap source;
    bool sameContent(const OptionBlock& o) const
    {
        return values == o.values && sameExtras(extras, o.extras);
    }
};

/// One ros2mqtt or mqtt2ros entry.
struct Mapping
{
    quint64 id = 0; ///< stable identity within a session; 0 = not assigned yet
    Direction direction = Direction::Ros2Mqtt;
    OptionBlock block;

    QString rosTopic() const { return block.values.text(QStringLiteral("ros_topic")); }
    QString mqttTopic() const { return block.values.text(QStringLiteral("mqtt_topic")); }
    QString value(const QString& path) const { return block.values.text(path); }
    /// The value, or mqtt_client's default when not set.
    QString effective(const QString& path) const;
    bool isSet(const QString& path) const { return block.values.has(path); }
    void set(const QString& path, const QString& text) { block.values.setText(path, text); }
    void unset(const QString& path) { block.values.remove(path); }
    OptionScope scope() const { return scopeOf(direction); }
    /// The topic data comes from, and the one it goes to.
    QString sourceTopic() const { return direction == Direction::Ros2Mqtt ? rosTopic() : mqttTopic(); }
    QString destinationTopic() const { return direction == Direction::Ros2Mqtt ? mqttTopic() : rosTopic(); }
    bool sameContent(const Mapping& o) const
    {
        return direction == o.direction && block.sameContent(o.block);
    }

    static Mapping create(Direction direction, const QString& rosTopic, const QString& mqttTopic);
    static quint64 nextId();
};

/// The whole content of an mqtt_client bridge config, whatever layout it came from.
struct BridgeConfig
{
    ConfigLayout layout = ConfigLayout::Ros1;
    QString ros2NodeName = QStringLiteral("mqtt_client"); ///< ROS 2: the key above ros__parameters
    OptionBlock broker;
    OptionBlock client;
    QList<ExtraValue> rootExtras; ///< unknown keys beside broker/client/bridge
    QList<ExtraValue> bridgeExtras; ///< unknown keys inside bridge
    QList<ExtraValue> documentExtras; ///< ROS 2: other top-level keys beside the node
    QList<Mapping> mappings;

    const OptionBlock& block(OptionScope scope) const
    {
        return scope == OptionScope::Broker ? broker : client;
    }
    OptionBlock& block(OptionScope scope) { return scope == OptionScope::Broker ? broker : client; }
    /// Effective broker/client value (mqtt_client's default when not set).
    QString effective(OptionScope scope, const QString& path) const;

    int indexOfMapping(quint64 id) const;
    const Mapping* mappingById(quint64 id) const;
    /// Gives every mapping without an id a fresh one.
    void assignIds();

    /// Same meaning (settings, unknown keys, mappings in order), ignoring layout and positions.
    bool sameContent(const BridgeConfig& o) const;
    /// Settings and unknown keys only.
    bool sameSettings(const BridgeConfig& o) const;
};

Q_DECLARE_METATYPE(Mapping)
