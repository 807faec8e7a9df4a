// SPDX-License-Identifier: MIT
#include "ros2/ros2names.h"

#include "text/topicnames.h"

#include <algorithm>
#include <QCoreApplication>
#include <QStringList>

namespace Ros2Names {

TopicKind classifyDdsTopic(const QString& ddsTopic, QString* rosName)
{
    auto strip = [&](const QString& suffix) {
        QString rest = ddsTopic.mid(2);
        if (!suffix.isEmpty() && rest.endsWith(suffix))
            rest.chop(suffix.size());
        return rest;
    };
    TopicKind kind = TopicKind::Other;
    QString name = ddsTopic;
    if (ddsTopic.startsWith(QLatin1String("rt/")) && ddsTopic.size() > 3) {
        kind = TopicKind::Topic;
        name = strip({});
    } else if (ddsTopic.startsWith(QLatin1String("rq/")) && ddsTopic.size() > 3) {
        kind = TopicKind::ServiceRequest;
        name = strip(QStringLiteral("Request"));
    } else if (ddsTopic.startsWith(QLatin1String("rr/")) && ddsTopic.size() > 3) {
        kind = TopicKind::ServiceReply;
        name = strip(QStringLiteral("Reply"));
    }
    if (kind != TopicKind::Other && !name.startsWith(QLatin1Char('/')))
        name.prepend(QLatin1Char('/'));
    if (rosName)
        *rosName = name;
    return kind;
}

QString ddsTopic(const QString& rosTopic)
{
    QString name = rosTopic;
    while (name.startsWith(QLatin1Char('/')))
        name.remove(0, 1);
    return QStringLiteral("rt/") + name;
}

QString rosType(const QString& ddsType)
{
    const QStringList parts = ddsType.split(QStringLiteral("::"));
    if (parts.size() != 4 || parts[2] != QLatin1String("dds_") || !parts[3].endsWith(QLatin1Char('_'))
        || parts[0].isEmpty() || parts[1].isEmpty() || parts[3].size() < 2)
        return ddsType;
    return parts[0] + QLatin1Char('/') + parts[1] + QLatin1Char('/') + parts[3].chopped(1);
}

QString ddsType(const QString& rosType)
{
    const QStringList parts = rosType.split(QLatin1Char('/'));
    for (const QString& p : parts)
        if (p.isEmpty() || p.contains(QLatin1Char(':')))
            return {};
    if (parts.size() == 2)
        return parts[0] + QStringLiteral("::msg::dds_::") + parts[1] + QLatin1Char('_');
    if (parts.size() == 3)
        return parts[0] + QStringLiteral("::") + parts[1] + QStringLiteral("::dds_::") + parts[2]
            + QLatin1Char('_');
    return {};
}

namespace {
QString quoted(const QString& s)
{
    return s.size() > 60 ? s.left(60) + QStringLiteral("…") : s;
}

bool isIdentifier(const QString& part)
{
    if (part.isEmpty() || !((part[0] >= u'a' && part[0] <= u'z') || (part[0] >= u'A' && part[0] <= u'Z')))
        return false;
    for (const QChar c : part)
        if (!((c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z') || (c >= u'0' && c <= u'9') || c == u'_'))
            return false;
    return true;
}
} // namespace

bool isValidType(const QString& type, QString* why)
{
    auto fail = [&](const QString& reason) {
        if (why)
            *why = reason;
        return false;
    };
    if (type.size() > kMaxNameChars)
        return fail(QCoreApplication::translate("Ros2Names", "the type name has %1 characters (at most %2)")
                        .arg(type.size())
                        .arg(kMaxNameChars));
    const QStringList parts = type.split(QLatin1Char('/'));
    if (parts.size() < 2 || parts.size() > 3 || (parts.size() == 3 && parts[1] != QLatin1String("msg"))
        || !std::all_of(parts.begin(), parts.end(), isIdentifier))
        return fail(
            QCoreApplication::translate("Ros2Names", "\"%1\" is not a ROS 2 message type (pkg/msg/Type)")
                .arg(quoted(type)));
    return true;
}

bool isValidTopic(const QString& topic, QString* why)
{
    if (ddsTopic(topic).size() - 3 > kMaxNameChars) {
        if (why)
            *why = QCoreApplication::translate("Ros2Names", "the topic name has %1 characters (at most %2)")
                       .arg(topic.size())
                       .arg(kMaxNameChars);
        return false;
    }
    QString reason;
    if (!TopicNames::isValidRosName(topic, true, &reason)) {
        if (why)
            *why = QCoreApplication::translate("Ros2Names", "\"%1\" is not a ROS 2 topic name: %2")
                       .arg(quoted(topic), reason);
        return false;
    }
    return true;
}

} // namespace Ros2Names
