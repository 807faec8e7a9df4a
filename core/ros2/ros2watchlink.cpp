// SPDX-License-Identifier: MIT
#include "ros2/ros2watchlink.h"

#include <algorithm>

using Ros2Protocol::Kind;

Ros2WatchLink::Ros2WatchLink(DdsChildPipe& pipe)
    : m_pipe(pipe)
{ }

void Ros2WatchLink::replay()
{
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it)
        m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(it.key())));
}

void Ros2WatchLink::childStopped()
{
    for (auto it = m_watched.begin(); it != m_watched.end(); ++it) {
        for (Reader& r : it->readers)
            r.queue.reset();
        it->childDropped = 0;
    }
}

bool Ros2WatchLink::onSamples(const QByteArray& body)
{
    auto batch = Ros2Protocol::decodeSamples(body);
    if (!batch)
        return false;
    const auto it = m_watched.find(batch->topic);
    if (it == m_watched.end())
        return true; // unwatched since the child sent it
    it->childDropped = batch->dropped;
    for (Reader& r : it->readers) {
        if (!r.queue)
            r.queue = std::make_shared<NewestQueue<Ros2Sample>>(r.maxMessages, r.maxBytes);
        for (const Ros2Sample& s : batch->samples)
            r.queue->push(Ros2Sample(s), s.bytes.size()); // shared bytes (QByteArray), no copy
    }
    return true;
}

Ros2Protocol::WatchRequest Ros2WatchLink::Watched::limits(const QString& topic) const
{
    Ros2Protocol::WatchRequest w {topic, 0, 0};
    for (const Reader& r : readers) {
        w.maxMessages = std::max<quint64>(w.maxMessages, r.maxMessages);
        w.maxBytes = std::max(w.maxBytes, r.maxBytes);
    }
    return w;
}

void Ros2WatchLink::openQueue(const QString& topic, std::size_t maxMessages, qint64 maxBytes,
                              const void* owner)
{
    Watched& w = m_watched[topic];
    Reader& r = w.readers[owner];
    r.maxMessages = maxMessages;
    r.maxBytes = maxBytes;
    if (r.queue)
        r.queue->setLimits(maxMessages, maxBytes);
    else if (m_pipe.hasChild())
        r.queue = std::make_shared<NewestQueue<Ros2Sample>>(maxMessages, maxBytes);
    m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(w.limits(topic)));
}

void Ros2WatchLink::closeQueue(const QString& topic, const void* owner)
{
    const auto it = m_watched.find(topic);
    if (it == m_watched.end() || it->readers.remove(owner) == 0)
        return;
    if (it->readers.isEmpty()) {
        m_watched.erase(it);
        m_pipe.send(Kind::Unwatch, Ros2Protocol::encodeStrings({topic}));
    } else {
        m_pipe.send(Kind::Watch, Ros2Protocol::encodeWatch(it->limits(topic)));
    }
}

const Ros2WatchLink::Reader* Ros2WatchLink::reader(const QString& topic, const void* owner) const
{
    const auto it = m_watched.constFind(topic);
    if (it == m_watched.cend())
        return nullptr;
    const auto r = it->readers.constFind(owner);
    return r != it->readers.cend() && r->queue ? &*r : nullptr;
}

std::vector<Ros2Sample> Ros2WatchLink::takeQueued(const QString& topic, const void* owner)
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->take() : std::vector<Ros2Sample>();
}

quint64 Ros2WatchLink::droppedQueued(const QString& topic, const void* owner) const
{
    const Reader* r = reader(topic, owner);
    return r ? r->queue->dropped() + m_watched.value(topic).childDropped : 0;
}
