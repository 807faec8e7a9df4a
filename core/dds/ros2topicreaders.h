// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ros2types.h"
#include "wire/sourcemessage.h"

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <QHash>
#include <QString>
#include <vector>

template<typename T> class EventBuffer;
template<typename T> class NewestQueue;
struct Ros2RawReader;

/// The topics the DDS child reads for monitor() and watchMessages() (Ros2Engine), shared with
/// Cyclone's listener thread: per topic its reader, its figures and, while watched, a bounded
/// queue of its samples; and the arrivals of monitored topics while keepArrivals() asks. Every
/// call takes the lock; a reader is closed outside it (closing waits for a callback in flight).
class Ros2TopicReaders
{
public:
    Ros2TopicReaders();
    ~Ros2TopicReaders();
    Ros2TopicReaders(const Ros2TopicReaders&) = delete;
    Ros2TopicReaders& operator=(const Ros2TopicReaders&) = delete;

    /// A topic's entry before its reader opens: its type and whether monitor() asked for it.
    void add(const QString& topic, const QString& type, bool monitored);
    /// The reader of an added topic (kept until release() or clear()).
    void setReader(const QString& topic, std::unique_ptr<Ros2RawReader> reader);
    /// Drops an entry whose reader could not be opened.
    void remove(const QString& topic);
    /// Marks a read topic monitored; false when it is not read.
    bool markMonitored(const QString& topic);
    /// Gives a read topic a queue bounded so (or new bounds); false when it is not read.
    bool watch(const QString& topic, std::size_t maxMessages, qint64 maxBytes);
    /// Ends a use of a topic (monitor() or watchMessages()), and its reader with the last one.
    void release(const QString& topic, bool monitorUse);
    /// Every entry and the arrivals gone (after the participant is).
    void clear();

    /// A sample of `topic` as Cyclone passed it (on its listener thread): counted, queued when
    /// watched, and an arrival when monitored. `sourceNs`: its DDS source timestamp (the writer's
    /// clock, ns since the epoch; 0 or less: none), which gives its age.
    void onSample(const QString& topic, const unsigned char* data, std::size_t size, qint64 sourceNs = 0);

    bool isSubscribed(const QString& topic) const;
    bool isMonitored(const QString& topic) const;
    /// Figures of the monitored topics (rates at `nowNs`).
    QHash<QString, Ros2MonitorStats> snapshot(qint64 nowNs) const;
    /// A watched topic's queue, oldest first, and what it dropped so far.
    std::vector<Ros2Sample> takeMessages(const QString& topic);
    quint64 droppedMessages(const QString& topic) const;
    /// Keeps at most `maxArrivals` arrivals of monitored topics (0: none), from now on.
    void keepArrivals(std::size_t maxArrivals);
    std::vector<SourceHead> takeArrivals();
    quint64 droppedArrivals() const;

private:
    struct Entry;
    mutable std::mutex m_mutex;
    std::map<QString, Entry> m_topics;
    std::unique_ptr<EventBuffer<SourceHead>> m_arrivals;
};
