// SPDX-License-Identifier: MIT
#include "dds/ros2topicreaders.h"

#include "base/eventbuffer.h"
#include "base/newestqueue.h"
#include "base/ratewindow.h"
#include "base/wallclock.h"
#include "dds/ros2rawreader.h"

#include <algorithm>
#include <array>
#include <optional>

namespace {
/// The ages of the last TopicFigures::kAgeSamples samples with a source timestamp, oldest overwritten.
struct AgeRing
{
    std::array<qint64, TopicFigures::kAgeSamples> ns {};
    std::size_t count = 0;
    std::size_t next = 0;
    mutable std::optional<double> median; ///< as of the last medianMs(), until a sample comes

    void add(qint64 ageNs)
    {
        ns[next] = ageNs;
        next = (next + 1) % ns.size();
        count = std::min(count + 1, ns.size());
        median.reset();
    }
    /// Sorted only when a sample came since the last call: a snapshot every 100 ms of many quiet topics.
    double medianMs() const
    {
        if (count == 0)
            return qQNaN();
        if (!median)
            median = sortedMedianMs();
        return *median;
    }
    double sortedMedianMs() const
    {
        std::array<qint64, TopicFigures::kAgeSamples> sorted = ns;
        std::sort(sorted.begin(), sorted.begin() + qsizetype(count));
        const std::size_t mid = count / 2;
        const double ns50
            = count % 2 ? double(sorted[mid]) : (double(sorted[mid - 1]) + double(sorted[mid])) / 2;
        return ns50 / 1e6;
    }
};
} // namespace

/// A read topic: monitored, watched, or both.
struct Ros2TopicReaders::Entry
{
    std::unique_ptr<Ros2RawReader> reader;
    Ros2MonitorStats stats;
    RateWindow rates;
    AgeRing ages;
    bool monitored = false; ///< asked for by monitor()
    std::unique_ptr<NewestQueue<Ros2Sample>> watched; ///< set while watchMessages() asks
};

Ros2TopicReaders::Ros2TopicReaders() = default;

Ros2TopicReaders::~Ros2TopicReaders() = default;

void Ros2TopicReaders::add(const QString& topic, const QString& type, bool monitored)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    Entry& e = m_topics[topic];
    e.stats.type = type;
    e.monitored = monitored;
}

void Ros2TopicReaders::setReader(const QString& topic, std::unique_ptr<Ros2RawReader> reader)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_topics[topic].reader = std::move(reader);
}

void Ros2TopicReaders::remove(const QString& topic)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_topics.erase(topic);
}

bool Ros2TopicReaders::markMonitored(const QString& topic)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    if (it == m_topics.end())
        return false;
    it->second.monitored = true;
    return true;
}

bool Ros2TopicReaders::watch(const QString& topic, std::size_t maxMessages, qint64 maxBytes)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    if (it == m_topics.end())
        return false;
    if (it->second.watched)
        it->second.watched->setLimits(maxMessages, maxBytes);
    else
        it->second.watched = std::make_unique<NewestQueue<Ros2Sample>>(maxMessages, maxBytes);
    return true;
}

void Ros2TopicReaders::release(const QString& topic, bool monitorUse)
{
    std::unique_ptr<Ros2RawReader> reader;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const auto it = m_topics.find(topic);
        if (it == m_topics.end())
            return;
        if (monitorUse)
            it->second.monitored = false;
        else
            it->second.watched.reset();
        if (it->second.monitored || it->second.watched)
            return;
        reader = std::move(it->second.reader);
        m_topics.erase(it);
    }
    if (reader)
        reader->close(); // waits for a callback in flight; onSample then finds no entry
}

void Ros2TopicReaders::clear()
{
    std::map<QString, Entry> gone;
    std::lock_guard<std::mutex> lock(m_mutex);
    gone.swap(m_topics);
    m_arrivals.reset();
}

void Ros2TopicReaders::onSample(const QString& topic, const unsigned char* data, std::size_t size,
                                qint64 sourceNs)
{
    const qint64 now = wallClockNs();
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    if (it == m_topics.end())
        return;
    Ros2MonitorStats& s = it->second.stats;
    ++s.messages;
    s.bytes += size;
    s.lastSize = int(size);
    s.lastNs = now;
    s.lastMessage = QByteArray(reinterpret_cast<const char*>(data), qsizetype(size));
    it->second.rates.add(now, s.lastSize);
    if (sourceNs > 0) // a writer's clock far off gives a large or negative age: shown as it is
        it->second.ages.add(now - sourceNs);
    if (it->second.watched)
        it->second.watched->push({now, s.lastMessage}, s.lastSize); // shares the bytes
    if (m_arrivals && it->second.monitored) // as keepArrivals() says: not those only watched
        m_arrivals->push(SourceHead::ofRos(SourceGraph::Ros2, topic, s.type, now, s.lastMessage));
}

bool Ros2TopicReaders::isSubscribed(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_topics.count(topic) > 0;
}

bool Ros2TopicReaders::isMonitored(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    return it != m_topics.end() && it->second.monitored;
}

QHash<QString, Ros2MonitorStats> Ros2TopicReaders::snapshot(qint64 nowNs) const
{
    QHash<QString, Ros2MonitorStats> out;
    std::lock_guard<std::mutex> lock(m_mutex);
    for (const auto& [topic, e] : m_topics) {
        if (!e.monitored)
            continue; // only watched
        Ros2MonitorStats s = e.stats;
        std::tie(s.rateHz, s.bytesPerSecond) = e.rates.rates(nowNs);
        s.matchedPublishers = e.reader ? e.reader->matched.load() : 0;
        s.lost = e.reader ? e.reader->lost.load() : 0;
        s.ageMs = e.ages.medianMs();
        out.insert(topic, s);
    }
    return out;
}

std::vector<Ros2Sample> Ros2TopicReaders::takeMessages(const QString& topic)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    return it != m_topics.end() && it->second.watched ? it->second.watched->take()
                                                      : std::vector<Ros2Sample>();
}

quint64 Ros2TopicReaders::droppedMessages(const QString& topic) const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto it = m_topics.find(topic);
    return it != m_topics.end() && it->second.watched ? it->second.watched->dropped() : 0;
}

void Ros2TopicReaders::keepArrivals(std::size_t maxArrivals)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (maxArrivals == 0)
        m_arrivals.reset();
    else
        m_arrivals = std::make_unique<EventBuffer<SourceHead>>(maxArrivals);
}

std::vector<SourceHead> Ros2TopicReaders::takeArrivals()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_arrivals ? m_arrivals->take() : std::vector<SourceHead>();
}

quint64 Ros2TopicReaders::droppedArrivals() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_arrivals ? m_arrivals->dropped() : 0;
}
