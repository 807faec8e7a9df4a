// SPDX-License-Identifier: MIT
#include "mappingfactory.h"

#include <QJsonDocument>
#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace {
QString join(const QString& prefix, const QString& name)
{
    QString p = prefix;
    while (p.endsWith(u'/'))
        p.chop(1);
    return p.isEmpty() ? name : p + u'/' + name;
}
} // namespace

QString MappingFactory::mqttTopicFor(const QString& rosTopic, const QString& prefix)
{
    QString name = rosTopic;
    while (name.startsWith(u'/') || name.startsWith(u'~'))
        name.remove(0, 1);
    QString p = prefix;
    while (p.startsWith(u'/'))
        p.remove(0, 1);
    return join(p, name);
}

QString MappingFactory::rosTopicFor(const QString& mqttTopic, const QString& ns)
{
    static const QRegularExpression invalid(u"[^A-Za-z0-9_]"_s);
    QStringList levels;
    for (const QString& level : mqttTopic.split(u'/', Qt::SkipEmptyParts)) {
        QString l = level;
        l.replace(invalid, u"_"_s);
        if (l.front().isDigit())
            l.prepend(u'_'); // ROS 2 names may not start a level with a digit
        levels << l;
    }
    QString base = ns.isEmpty() ? u"/"_s : ns;
    if (!base.startsWith(u'/'))
        base.prepend(u'/');
    while (base.size() > 1 && base.endsWith(u'/'))
        base.chop(1);
    if (base == u"/"_s)
        return u'/' + levels.join(u'/');
    return base + u'/' + levels.join(u'/');
}

bool MappingFactory::isPrimitiveType(const QString& rosType)
{
    static const QStringList names
        = {u"String"_s, u"Bool"_s,   u"Char"_s,   u"Int8"_s,   u"Int16"_s,   u"Int32"_s,  u"Int64"_s,
           u"UInt8"_s,  u"UInt16"_s, u"UInt32"_s, u"UInt64"_s, u"Float32"_s, u"Float64"_s};
    const QStringList parts = rosType.split(u'/');
    return parts.size() >= 2 && parts.first() == u"std_msgs"_s && names.contains(parts.last());
}

QString MappingFactory::typeForLayout(const QString& rosType, ConfigLayout layout)
{
    const QStringList parts = rosType.split(u'/', Qt::SkipEmptyParts);
    if (parts.size() < 2)
        return rosType;
    if (layout == ConfigLayout::Ros2)
        return parts.first() + u"/msg/"_s + parts.last();
    return parts.first() + u'/' + parts.last();
}

QString MappingFactory::primitiveTypeOf(const QByteArray& payload)
{
    const QByteArray t = payload.trimmed();
    if (t.isEmpty() || t.size() > 256)
        return QString();
    if (t == "true" || t == "false" || t == "True" || t == "False")
        return u"std_msgs/Bool"_s;
    bool ok = false;
    t.toLongLong(&ok);
    if (ok)
        return u"std_msgs/Int64"_s;
    t.toDouble(&ok);
    if (ok)
        return u"std_msgs/Float64"_s;
    for (char c : t) {
        if (uchar(c) < 0x20 && c != '\t')
            return QString();
    }
    if (!QJsonDocument::fromJson(t).isNull())
        return QString(); // JSON, not a primitive
    return u"std_msgs/String"_s;
}

Mapping MappingFactory::ros2mqtt(const QString& rosTopic, const QString& rosType, const QString& mqttTopic,
                                 const MqttFacts& destination, ConfigLayout layout)
{
    Mapping m = Mapping::create(Direction::Ros2Mqtt, rosTopic, mqttTopic);
    // A std_msgs primitive sent to a topic that non-ROS devices already use (plain payloads, no
    // type announcement) goes as text, so that they can read it.
    if (isPrimitiveType(rosType) && destination.seen && destination.announcedType.isEmpty()
        && !primitiveTypeOf(destination.lastPayload).isEmpty()) {
        m.set(u"primitive"_s, u"true"_s);
        if (layout == ConfigLayout::Ros2)
            m.set(u"ros_type"_s, typeForLayout(rosType, layout));
    }
    return m;
}

namespace {
/// The most JSON text looked at to suggest a json mapping: what a json mapping converts (issue 41).
constexpr qsizetype kMaxJsonBytes = 1024 * 1024;
} // namespace

Mapping MappingFactory::mqtt2ros(const QString& mqttTopic, const MqttFacts& source, const QString& rosTopic,
                                 ConfigLayout layout)
{
    Mapping m = Mapping::create(Direction::Mqtt2Ros, rosTopic, mqttTopic);
    if (!source.announcedType.isEmpty() || !source.seen)
        return m; // mqtt_client on the other end tells the type itself
    const QString primitive = primitiveTypeOf(source.lastPayload);
    if (!primitive.isEmpty()) {
        m.set(u"primitive"_s, u"true"_s);
        if (layout == ConfigLayout::Ros2)
            m.set(u"ros_type"_s, typeForLayout(primitive, layout));
    } else if (layout == ConfigLayout::Ros2 && source.lastPayload.size() <= kMaxJsonBytes
               && !QJsonDocument::fromJson(source.lastPayload).isNull()) {
        // (a payload from anyone on the broker: its size first, never the tree of 16 MiB; the ROS 2
        // bridge converts no JSON above that either)
        // JSON from a non-ROS device: mqtt_client needs json and the ROS type (left to the user,
        // and flagged until it is set).
        m.set(u"json"_s, u"true"_s);
    }
    return m;
}
