// SPDX-License-Identifier: MIT
#include "pipelinediscovery.h"

#include <algorithm>
#include <numeric>

QString PipelineDiscovery::key(const QString& topic)
{
    qsizetype i = 0;
    while (i < topic.size() && topic[i] == u'/')
        ++i;
    return topic.mid(i);
}

void PipelineDiscovery::add(const StampEvent& event)
{
    const QString k = key(event.topic);
    auto it = m_index.find(k);
    if (it == m_index.end()) {
        it = m_index.insert(k, int(m_topics.size()));
        m_topics << event.topic;
        m_counts.push_back(0);
    } else if (event.topic.startsWith(u'/') && !m_topics[*it].startsWith(u'/')) {
        m_topics[*it] = event.topic; // prefer the ROS name
    }
    const int topic = *it;
    ++m_counts[std::size_t(topic)];
    auto sample = m_samples.find(event.sampleNs);
    if (sample == m_samples.end()) {
        sample = m_samples.emplace(event.sampleNs, std::vector<std::pair<int, qint64>>()).first;
        m_order.push_back(event.sampleNs);
        while (m_order.size() > kKeptSamples)
            dropOldestSample();
    }
    if (!m_kept.emplace(event.sampleNs, topic).second)
        return; // a second stamp of this topic for this sample
    sample->second.emplace_back(topic, event.timeNs);
    while (m_kept.size() > kKeptStamps && m_order.size() > 1 && m_order.front() != event.sampleNs)
        dropOldestSample();
}

void PipelineDiscovery::dropOldestSample()
{
    const auto it = m_samples.find(m_order.front());
    if (it != m_samples.end()) {
        for (const auto& [t, time] : it->second)
            m_kept.erase({it->first, t});
        m_samples.erase(it);
    }
    m_order.pop_front();
}

void PipelineDiscovery::clear()
{
    m_topics.clear();
    m_index.clear();
    m_counts.clear();
    m_samples.clear();
    m_kept.clear();
    m_order.clear();
}

quint64 PipelineDiscovery::stampCount(const QString& topic) const
{
    const int i = m_index.value(key(topic), -1);
    return i < 0 ? 0 : m_counts[std::size_t(i)];
}

int PipelineDiscovery::completeSamples() const
{
    int n = 0;
    for (const auto& [k, stamps] : m_samples)
        if (stamps.size() == std::size_t(m_topics.size()))
            ++n;
    return n;
}

Pipeline PipelineDiscovery::propose(int window) const
{
    const std::size_t topics = std::size_t(m_topics.size());
    std::vector<double> sum(topics, 0);
    std::vector<qint64> n(topics, 0);
    const bool anyComplete = completeSamples() > 0;
    for (const auto& [k, stamps] : m_samples) {
        if (stamps.size() < 2 || (anyComplete && stamps.size() != topics))
            continue;
        qint64 first = stamps.front().second;
        for (const auto& s : stamps)
            first = std::min(first, s.second);
        for (const auto& [t, time] : stamps) {
            sum[std::size_t(t)] += double(time - first);
            ++n[std::size_t(t)];
        }
    }
    std::vector<int> order(topics);
    std::iota(order.begin(), order.end(), 0);
    const auto mean
        = [&](int t) { return n[std::size_t(t)] ? sum[std::size_t(t)] / double(n[std::size_t(t)]) : 1e300; };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        if (mean(a) != mean(b))
            return mean(a) < mean(b);
        return m_topics[a] < m_topics[b];
    });
    QStringList ordered;
    for (int t : order)
        ordered << m_topics[t];
    Pipeline p(ordered, window);
    const QHash<QString, QString> hosts = Pipeline::guessHosts(ordered);
    for (auto it = hosts.cbegin(); it != hosts.cend(); ++it)
        p.setHost(it.key(), it.value());
    return p;
}
