// SPDX-License-Identifier: MIT
#pragma once

#include "pipeline.h"
#include "stampevent.h"

#include <deque>
#include <QHash>
#include <QStringList>
#include <unordered_map>
#include <vector>

/// Finds a pipeline in whatever stamps arrive: the topics seen, ordered by their mean time within
/// the samples that carry every one of them, with hosts guessed from the names.
///
/// A ROS topic and the MQTT topic mqtt_client carries it on ("/a/b" and "a/b") are one topic; the
/// ROS name is kept. Memory is bounded: only the most recent samples are kept.
class PipelineDiscovery
{
public:
    static constexpr std::size_t kKeptSamples = 2000;

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

    QStringList m_topics;
    QHash<QString, int> m_index; ///< normalized topic -> index in m_topics
    std::vector<quint64> m_counts;
    std::unordered_map<qint64, std::vector<std::pair<int, qint64>>> m_samples;
    std::deque<qint64> m_order;
};
