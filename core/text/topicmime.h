// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

class QMimeData;

/// What a drag of discovered topics carries, under our own MIME types.
namespace TopicMime {
inline QString rosType()
{
    return QStringLiteral("application/x-bridgescope-ros-topics");
}
inline QString mqttType()
{
    return QStringLiteral("application/x-bridgescope-mqtt-topics");
}

/// One dragged topic: its name and, where known, its ROS type.
struct Topic
{
    QString name;
    QString rosType;
    bool operator==(const Topic& o) const { return name == o.name && rosType == o.rosType; }
};

QMimeData* encode(const QString& mimeType, const QList<Topic>& topics);
/// The topics of `mimeType` in `data`, or none.
QList<Topic> decode(const QMimeData* data, const QString& mimeType);
} // namespace TopicMime
