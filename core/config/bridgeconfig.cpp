// SPDX-License-Identifier: MIT
#include "bridgeconfig.h"

#include <atomic>

using namespace Qt::StringLiterals;

QString layoutName(ConfigLayout layout)
{
    switch (layout) {
    case ConfigLayout::Ros1:
        return u"ros1"_s;
    case ConfigLayout::Ros2:
        return u"ros2"_s;
    case ConfigLayout::MqttBridge:
        return u"mqtt_bridge"_s;
    }
    return QString();
}

bool layoutFromName(const QString& name, ConfigLayout* layout)
{
    for (ConfigLayout l : {ConfigLayout::Ros1, ConfigLayout::Ros2, ConfigLayout::MqttBridge}) {
        if (layoutName(l) == name) {
            *layout = l;
            return true;
        }
    }
    return false;
}

int OptionValues::indexOf(const QString& path) const
{
    for (int i = 0; i < m_entries.size(); ++i) {
        if (m_entries[i].path == path)
            return i;
    }
    return -1;
}

bool OptionValues::isList(const QString& path) const
{
    const int i = indexOf(path);
    return i >= 0 && m_entries[i].isList;
}

QString OptionValues::text(const QString& path) const
{
    const int i = indexOf(path);
    if (i < 0)
        return QString();
    return m_entries[i].isList ? m_entries[i].list.join(u", "_s) : m_entries[i].text;
}

QStringList OptionValues::list(const QString& path) const
{
    const int i = indexOf(path);
    if (i < 0)
        return {};
    return m_entries[i].isList ? m_entries[i].list : QStringList {m_entries[i].text};
}

void OptionValues::setText(const QString& path, const QString& text)
{
    const int i = indexOf(path);
    Entry e {path, text, {}, false};
    if (i < 0)
        m_entries.append(e);
    else
        m_entries[i] = e;
}

void OptionValues::setList(const QString& path, const QStringList& list)
{
    const int i = indexOf(path);
    Entry e {path, QString(), list, true};
    if (i < 0)
        m_entries.append(e);
    else
        m_entries[i] = e;
}

void OptionValues::remove(const QString& path)
{
    const int i = indexOf(path);
    if (i >= 0)
        m_entries.removeAt(i);
}

void OptionValues::copyFrom(const OptionValues& other, const QString& path)
{
    const int i = other.indexOf(path);
    if (i < 0)
        remove(path);
    else if (other.m_entries[i].isList)
        setList(path, other.m_entries[i].list);
    else
        setText(path, other.m_entries[i].text);
}

QStringList OptionValues::paths() const
{
    QStringList out;
    out.reserve(m_entries.size());
    for (const Entry& e : m_entries)
        out << e.path;
    return out;
}

bool OptionValues::operator==(const OptionValues& other) const
{
    if (m_entries.size() != other.m_entries.size())
        return false;
    for (const Entry& e : m_entries) {
        const int j = other.indexOf(e.path);
        if (j < 0 || !(other.m_entries[j] == e))
            return false;
    }
    return true;
}

QString Mapping::effective(const QString& path) const
{
    if (block.values.has(path))
        return block.values.text(path);
    const OptionSpec* spec = OptionSchema::find(scope(), path);
    return spec ? spec->defaultText : QString();
}

Mapping Mapping::create(Direction direction, const QString& rosTopic, const QString& mqttTopic)
{
    Mapping m;
    m.id = nextId();
    m.direction = direction;
    if (direction == Direction::Ros2Mqtt) {
        m.set(u"ros_topic"_s, rosTopic);
        m.set(u"mqtt_topic"_s, mqttTopic);
    } else {
        m.set(u"mqtt_topic"_s, mqttTopic);
        m.set(u"ros_topic"_s, rosTopic);
    }
    return m;
}

quint64 Mapping::nextId()
{
    static std::atomic<quint64> counter {0};
    return ++counter;
}

QString BridgeConfig::effective(OptionScope scope, const QString& path) const
{
    const OptionBlock& b = block(scope);
    if (b.values.has(path))
        return b.values.text(path);
    const OptionSpec* spec = OptionSchema::find(scope, path);
    return spec ? spec->defaultText : QString();
}

int BridgeConfig::indexOfMapping(quint64 id) const
{
    for (int i = 0; i < mappings.size(); ++i) {
        if (mappings[i].id == id)
            return i;
    }
    return -1;
}

const Mapping* BridgeConfig::mappingById(quint64 id) const
{
    const int i = indexOfMapping(id);
    return i < 0 ? nullptr : &mappings[i];
}

void BridgeConfig::assignIds()
{
    for (Mapping& m : mappings) {
        if (m.id == 0)
            m.id = Mapping::nextId();
    }
}

bool sameExtras(const QList<ExtraValue>& a, const QList<ExtraValue>& b)
{
    if (a.size() != b.size())
        return false;
    for (const ExtraValue& e : a) {
        if (!b.contains(e))
            return false;
    }
    return true;
}

bool BridgeConfig::sameSettings(const BridgeConfig& o) const
{
    return broker.sameContent(o.broker) && client.sameContent(o.client)
        && sameExtras(rootExtras, o.rootExtras) && sameExtras(bridgeExtras, o.bridgeExtras)
        && sameExtras(documentExtras, o.documentExtras);
}

bool BridgeConfig::sameContent(const BridgeConfig& o) const
{
    if (!sameSettings(o) || mappings.size() != o.mappings.size())
        return false;
    for (int i = 0; i < mappings.size(); ++i) {
        if (!mappings[i].sameContent(o.mappings[i]))
            return false;
    }
    return true;
}
