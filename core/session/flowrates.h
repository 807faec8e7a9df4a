// SPDX-License-Identifier: MIT
#pragma once

#include "topics/topicfigures.h"

#include <deque>
#include <optional>
#include <QHash>
#include <QString>

/// The rates of a mapping's two ends over one window: the message counts of both sides, sampled
/// at the same instants, give each end's rate over the same interval. The sources' own rates
/// come from windows of their own (the MQTT tree's last one-second tick, the ROS monitor's five
/// seconds ending at its last message): side by side they showed a destination faster than its
/// source ("10.0 → 10.7 Hz", issue 40).
class FlowRates
{
public:
    static constexpr qint64 kWindowNs = 5'000'000'000LL;
    /// Samples closer together than this replace the newest (a drop asks for health at once).
    static constexpr qint64 kMinStepNs = 500'000'000LL;
    static constexpr std::size_t kMaxSamples = 2 + 2 * std::size_t(kWindowNs / kMinStepNs);

    /// Keeps the message counts of every topic of `ros` and `mqtt` (MessageSource::figures()) at
    /// `nowNs`, and forgets what is older than the window.
    void sample(qint64 nowNs, const QHash<QString, TopicFigures>& ros,
                const QHash<QString, TopicFigures>& mqtt);

    /// Both ends counted over the same interval.
    struct Flow
    {
        qint64 spanNs = 0;
        quint64 rosMessages = 0;
        quint64 mqttMessages = 0;
        double rosHz() const { return spanNs > 0 ? double(rosMessages) * 1e9 / double(spanNs) : 0; }
        double mqttHz() const { return spanNs > 0 ? double(mqttMessages) * 1e9 / double(spanNs) : 0; }
    };
    /// The longest interval, at most the window, at whose two ends both topics were counted;
    /// nothing before the second sample, or when a count went back (a subscription made anew).
    std::optional<Flow> flow(const QString& rosTopic, const QString& mqttTopic) const;
    void clear() { m_samples.clear(); }

private:
    struct Sample
    {
        qint64 ns = 0;
        QHash<QString, quint64> ros;
        QHash<QString, quint64> mqtt;
    };
    std::deque<Sample> m_samples;
};
