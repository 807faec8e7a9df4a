// SPDX-License-Identifier: MIT
#pragma once

#include "base/newestqueue.h"
#include "ros2/ddschildpipe.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <memory>
#include <QHash>
#include <QString>
#include <vector>

/// The parent side of the topics watched in the child for their whole samples: one queue per
/// owner (each Tap of the participant), the child asked for enough for the most demanding owner
/// (Watch) and asked again after each restart (replay()). Part of Ros2Link; its users reach it
/// through Ros2Participant::openTap().
class Ros2WatchLink
{
public:
    explicit Ros2WatchLink(DdsChildPipe& pipe);

    /// One queue of a topic's whole samples per `owner`: the topic is subscribed while a queue of it
    /// is open, and asked again after each restart of the child.
    void openQueue(const QString& topic, std::size_t maxMessages, qint64 maxBytes, const void* owner);
    void closeQueue(const QString& topic, const void* owner);
    bool isWatched(const QString& topic) const { return m_watched.contains(topic); }
    std::vector<Ros2Sample> takeQueued(const QString& topic, const void* owner);
    /// The owner's drops and the child's (since the child started).
    quint64 droppedQueued(const QString& topic, const void* owner) const;

    /// A new child runs: every watched topic is asked of it again.
    void replay();
    /// The child's Samples frame; false when the body does not read.
    bool onSamples(const QByteArray& body);
    /// The child was ended: its samples and drop counts are gone; what was asked stays.
    void childStopped();

private:
    /// One owner's queue of a watched topic.
    struct Reader
    {
        std::size_t maxMessages = 0;
        qint64 maxBytes = 0;
        std::shared_ptr<NewestQueue<Ros2Sample>> queue; ///< from the first samples until stop()
    };
    struct Watched
    {
        QHash<const void*, Reader> readers;
        quint64 childDropped = 0;
        /// What the child keeps between two polls: enough for the most demanding owner.
        Ros2Protocol::WatchRequest limits(const QString& topic) const;
    };
    const Reader* reader(const QString& topic, const void* owner) const;

    DdsChildPipe& m_pipe;
    QHash<QString, Watched> m_watched; ///< what openQueue() asked for, across stop() and start()
};
