// SPDX-License-Identifier: MIT
#pragma once

#include "latency/pipeline.h"
#include "wire/stampevent.h"

#include <deque>
#include <QHash>
#include <QStringList>
#include <unordered_map>
#include <unordered_set>
#include <vector>

/// Finds a pipeline in whatever stamps arrive: the topics seen, ordered by their mean time within
/// the samples that carry every one of them, with hosts guessed from the names.
///
/// When the names give two hosts or more, each host's clock orders only its own stamps: a host
/// that is left and returned to takes the stamps of the hosts visited meanwhile into the gap they
/// fit in, with their clock offset estimated as the clock offset row does (both ways take as
/// long). So a cloud clock 35 ms ahead, or 250 ms behind, still gives the order the sample took.
///
/// A ROS topic and the MQTT topic mqtt_client carries it on ("/a/b" and "a/b") are one topic; the
/// ROS name is kept. Memory is bounded: only the most recent samples are kept.
class PipelineDiscovery
{
public:
    static constexpr std::size_t kKeptSamples = 2000;
    /// Stamps kept over all samples: a broker with 100,000 stamp topics must not fill memory.
    static constexpr std::size_t kKeptStamps = 1'000'000;

    void add(const StampEvent& event);
    void clear();

    QStringList topics() const { return m_topics; }
    quint64 stampCount(const QString& topic) const;
    /// Samples among the kept ones that carry every topic seen.
    int completeSamples() const;
    /// The proposed pipeline (order by mean offset; by partial samples when none is complete).
    Pipeline propose(int window = Pipeline::kDefaultWindow) const;

private:
    static QString key(const QString& topic);
    /// The heard topics (finite `mean`) in order when names give two hosts or more, with each
    /// one's host in `hosts`; empty otherwise. `sinceSample`: mean time after the sample's id.
    std::vector<int> orderAcrossClocks(const std::vector<double>& mean,
                                       const std::vector<double>& sinceSample,
                                       std::vector<QString>* hosts) const;

    QStringList m_topics;
    QHash<QString, int> m_index; ///< normalized topic -> index in m_topics
    std::vector<quint64> m_counts;
    void dropOldestSample();

    struct PairHash
    {
        std::size_t operator()(const std::pair<qint64, int>& p) const noexcept
        {
            return std::hash<qint64>()(p.first) ^ (std::hash<int>()(p.second) * 0x9e3779b97f4a7c15ULL);
        }
    };
    std::unordered_map<qint64, std::vector<std::pair<int, qint64>>> m_samples;
    /// (sample, topic) of every kept stamp: a scan of the sample per stamp was quadratic in topics.
    std::unordered_set<std::pair<qint64, int>, PairHash> m_kept;
    std::deque<qint64> m_order;
};
