// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QString>
#include <QStringList>

/// Which host a stamp topic is on, guessed from its name when no pipeline file says it: a name
/// part "vehicle", "car", "robot", "ego" stands for the vehicle, "cloud", "edge", "server",
/// "backend" for the cloud.
namespace HostGuess {
/// The host a topic's name stands for ("vehicle", "cloud"), or empty when no part names one.
QString ofName(const QString& topic);
/// Hosts of topics in pipeline order: topics without a host in their name take their
/// neighbours' (the previous one's, at the start the next one's).
QHash<QString, QString> ofTopics(const QStringList& topics);
} // namespace HostGuess
