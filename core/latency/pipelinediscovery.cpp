// SPDX-License-Identifier: MIT
#include "pipelinediscovery.h"

#include "latency/hostguess.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

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

namespace {
/// One host's stamps (mean time, topic) in its clock's order; after a merge, also the stamps of
/// the hosts it holds, shifted into its clock.
struct Block
{
    std::vector<std::pair<double, int>> stamps;
    double span() const { return stamps.back().first - stamps.front().first; }
};

/// Where one block fits into a gap of another: the gap after `at` in `home` is longer than the
/// whole of `away` (both measured on one clock each, so both are true durations).
struct Fit
{
    std::size_t home = 0;
    std::size_t away = 0;
    std::size_t at = 0;
    double margin = 0;
};

std::optional<Fit> bestFit(const std::vector<Block>& blocks)
{
    std::optional<Fit> best;
    for (std::size_t h = 0; h < blocks.size(); ++h)
        for (std::size_t a = 0; a < blocks.size(); ++a) {
            if (a == h)
                continue;
            const auto& stamps = blocks[h].stamps;
            for (std::size_t k = 0; k + 1 < stamps.size(); ++k) {
                const double margin = stamps[k + 1].first - stamps[k].first - blocks[a].span();
                if (margin > 0 && (!best || margin > best->margin))
                    best = Fit {h, a, k, margin};
            }
        }
    return best;
}
} // namespace

std::vector<int> PipelineDiscovery::orderAcrossClocks(const std::vector<double>& mean,
                                                      const std::vector<double>& sinceSample,
                                                      std::vector<QString>* hosts) const
{
    // Hosts by name; a topic whose name names none is on the host of the stamp nearest in time
    // (a host's own stages are short next to the crossings and the clock offsets).
    const std::size_t topics = mean.size();
    std::vector<QString>& host = *hosts;
    host.assign(topics, QString());
    std::vector<int> named;
    QStringList distinct;
    for (std::size_t t = 0; t < topics; ++t) {
        if (!std::isfinite(mean[t]))
            continue;
        host[t] = HostGuess::ofName(m_topics[int(t)]);
        if (host[t].isEmpty())
            continue;
        named.push_back(int(t));
        if (!distinct.contains(host[t]))
            distinct << host[t];
    }
    if (distinct.size() < 2)
        return {}; // one clock: the stamps' times are the order
    std::sort(named.begin(), named.end(),
              [&](int a, int b) { return mean[std::size_t(a)] < mean[std::size_t(b)]; });
    for (std::size_t t = 0; t < topics; ++t) {
        if (!std::isfinite(mean[t]) || !host[t].isEmpty())
            continue;
        const auto after = std::lower_bound(named.cbegin(), named.cend(), mean[t],
                                            [&](int k, double m) { return mean[std::size_t(k)] < m; });
        int nearest = after == named.cend() ? named.back() : *after;
        if (after != named.cbegin()
            && std::abs(mean[std::size_t(*(after - 1))] - mean[t])
                <= std::abs(mean[std::size_t(nearest)] - mean[t]))
            nearest = *(after - 1);
        host[t] = host[std::size_t(nearest)];
    }
    // Within a host its own clock orders the stamps.
    std::vector<Block> blocks(std::size_t(distinct.size()));
    for (std::size_t t = 0; t < topics; ++t)
        if (std::isfinite(mean[t]))
            blocks[std::size_t(distinct.indexOf(host[t]))].stamps.emplace_back(mean[t], int(t));
    for (Block& b : blocks)
        std::sort(b.stamps.begin(), b.stamps.end(), [this](const auto& a, const auto& b) {
            return a.first != b.first ? a.first < b.first : m_topics[a.second] < m_topics[b.second];
        });
    // A host that is left and returned to holds the hosts visited meanwhile in the gap between
    // leaving and returning: the widest gap they fit in. Their clock offset is then estimated as
    // the clock offset row does (both ways take as long), and their stamps join on that clock.
    while (const std::optional<Fit> fit = bestFit(blocks)) {
        Block& home = blocks[fit->home];
        Block away = std::move(blocks[fit->away]);
        const double out = away.stamps.front().first - home.stamps[fit->at].first;
        const double back = home.stamps[fit->at + 1].first - away.stamps.back().first;
        const double offset = (out - back) / 2;
        for (auto& s : away.stamps)
            s.first -= offset;
        home.stamps.insert(home.stamps.begin() + qsizetype(fit->at) + 1, away.stamps.begin(),
                           away.stamps.end());
        blocks.erase(blocks.begin() + qsizetype(fit->away));
    }
    // What is left goes one way, whose offset no stamp tells: the sample starts on the host with
    // the stamp nearest its id (the suite's id is the first stamp's time, on the first host's clock).
    const auto origin = [&](const Block& b) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& [time, t] : b.stamps)
            nearest = std::min(nearest, std::abs(sinceSample[std::size_t(t)]));
        return nearest;
    };
    std::stable_sort(blocks.begin(), blocks.end(),
                     [&](const Block& a, const Block& b) { return origin(a) < origin(b); });
    std::vector<int> order;
    for (const Block& b : blocks)
        for (const auto& [time, t] : b.stamps)
            order.push_back(t);
    return order;
}

Pipeline PipelineDiscovery::propose(int window) const
{
    const std::size_t topics = std::size_t(m_topics.size());
    std::vector<double> sum(topics, 0);
    std::vector<double> sinceSample(topics, 0);
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
            sinceSample[std::size_t(t)] += double(time) - double(k);
            ++n[std::size_t(t)];
        }
    }
    std::vector<double> mean(topics, std::numeric_limits<double>::infinity());
    for (std::size_t t = 0; t < topics; ++t)
        if (n[t] > 0) {
            mean[t] = sum[t] / double(n[t]);
            sinceSample[t] /= double(n[t]);
        }
    std::vector<QString> hostOf;
    std::vector<int> order = orderAcrossClocks(mean, sinceSample, &hostOf);
    if (order.empty()) {
        order.resize(topics);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            if (mean[std::size_t(a)] != mean[std::size_t(b)])
                return mean[std::size_t(a)] < mean[std::size_t(b)];
            return m_topics[a] < m_topics[b];
        });
        hostOf.clear();
    } else {
        std::vector<int> unheard; // not in any sample used: last, by name
        for (std::size_t t = 0; t < topics; ++t)
            if (!std::isfinite(mean[t]))
                unheard.push_back(int(t));
        std::sort(unheard.begin(), unheard.end(), [this](int a, int b) { return m_topics[a] < m_topics[b]; });
        order.insert(order.end(), unheard.begin(), unheard.end());
    }
    QStringList ordered;
    for (int t : order)
        ordered << m_topics[t];
    Pipeline p(ordered, window);
    const QHash<QString, QString> hosts = HostGuess::ofTopics(ordered);
    for (auto it = hosts.cbegin(); it != hosts.cend(); ++it)
        p.setHost(it.key(), it.value());
    for (std::size_t t = 0; t < hostOf.size(); ++t)
        if (!hostOf[t].isEmpty())
            p.setHost(m_topics[int(t)], hostOf[t]);
    return p;
}
