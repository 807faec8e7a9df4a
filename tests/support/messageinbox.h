// SPDX-License-Identifier: MIT
#pragma once

#include <mutex>
#include <QByteArray>
#include <QHash>
#include <QList>
#include <QString>

/// Everything that arrives on one side of a bridge, by topic, newest last; filled from a library's
/// thread, read by the test's.
struct MessageInbox
{
    std::mutex mutex;
    QHash<QString, QList<QByteArray>> messages;

    void add(const QString& topic, const QByteArray& bytes)
    {
        std::lock_guard<std::mutex> lock(mutex);
        messages[topic].append(bytes);
    }
    QList<QByteArray> on(const QString& topic)
    {
        std::lock_guard<std::mutex> lock(mutex);
        return messages.value(topic);
    }
};
