// SPDX-License-Identifier: MIT
#include "flowrates.h"

namespace {
QHash<QString, quint64> countsOf(const QHash<QString, TopicFigures>& figures)
{
    QHash<QString, quint64> counts;
    counts.reserve(figures.size());
    for (auto it = figures.cbegin(); it != figures.cend(); ++it)
        counts.insert(it.key(), it->messages);
    return counts;
}
} // namespace

void FlowRates::sample(qint64 nowNs, const QHash<QString, TopicFigures>& ros,
                       const QHash<QString, TopicFigures>& mqtt)
{
    if (!m_samples.empty() && nowNs < m_samples.back().ns)
        m_samples.clear(); // the clock went back: no interval is known
    if (m_samples.size() >= 2 && nowNs - m_samples[m_samples.size() - 2].ns < kMinStepNs)
        m_samples.pop_back();
    m_samples.push_back({nowNs, countsOf(ros), countsOf(mqtt)});
    // Keep the newest sample at or before the window's start: the interval spans the window.
    while (m_samples.size() > kMaxSamples || (m_samples.size() > 2 && nowNs - m_samples[1].ns >= kWindowNs))
        m_samples.pop_front();
}

std::optional<FlowRates::Flow> FlowRates::flow(const QString& rosTopic, const QString& mqttTopic) const
{
    if (m_samples.size() < 2)
        return std::nullopt;
    const Sample& last = m_samples.back();
    const auto rosNow = last.ros.constFind(rosTopic);
    const auto mqttNow = last.mqtt.constFind(mqttTopic);
    if (rosNow == last.ros.cend() || mqttNow == last.mqtt.cend())
        return std::nullopt;
    for (std::size_t i = 0; i + 1 < m_samples.size(); ++i) {
        const Sample& first = m_samples[i];
        const auto rosThen = first.ros.constFind(rosTopic);
        const auto mqttThen = first.mqtt.constFind(mqttTopic);
        if (rosThen == first.ros.cend() || mqttThen == first.mqtt.cend())
            continue;
        if (*rosThen > *rosNow || *mqttThen > *mqttNow || last.ns <= first.ns)
            return std::nullopt;
        return Flow {last.ns - first.ns, *rosNow - *rosThen, *mqttNow - *mqttThen};
    }
    return std::nullopt;
}
