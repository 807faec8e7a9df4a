// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "latency/pipelinelabels.h"

#include <optional>
#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <QStringList>

namespace YAML {
class Node;
}

/// The stamp topics of a measured pipeline, in the order a sample passes them.
///
/// The benchmarking suite's metrics-logger YAML (`topics_in_order`, `metrics_window`) is a valid
/// pipeline file; `hosts: {<topic>: <host>}` is Bridgescope's extension. Stage i spans stamp i to
/// stamp i+1; a stage whose stamps are on different hosts is a crossing (its raw value holds the
/// clock offset between the hosts).
class Pipeline
{
    Q_DECLARE_TR_FUNCTIONS(Pipeline)
public:
    static constexpr int kDefaultWindow = 600;

    Pipeline() = default;
    explicit Pipeline(QStringList topics, int window = kDefaultWindow);

    /// Parses pipeline YAML; errors name the line. Repeated topics count once (as in the suite).
    static Result<Pipeline> read(const QByteArray& yaml);
    static Result<Pipeline> readFile(const QString& path);
    QByteArray toYaml() const;
    Status save(const QString& path) const;

    const QStringList& topics() const { return m_topics; }
    int topicCount() const { return int(m_topics.size()); }
    int stageCount() const { return m_topics.size() < 2 ? 0 : int(m_topics.size()) - 1; }
    bool isEmpty() const { return m_topics.isEmpty(); }
    /// Index of a topic, matching with or without a leading '/' (MQTT topics carry none); -1 if absent.
    int indexOf(QStringView topic) const;
    int indexOf(const QString& topic) const;
    int indexOf(const char16_t* topic) const { return indexOf(QStringView(topic)); }
    void setTopics(QStringList topics);

    int window() const { return m_window; }
    void setWindow(int samples) { m_window = samples; }
    /// Whether every stamp comes from one clock (`one_clock: true`: one machine, or clocks known to
    /// agree). Then a crossing's raw value is its one-way latency and no clock offset is estimated.
    bool oneClock() const { return m_oneClock; }
    void setOneClock(bool one) { m_oneClock = one; }

    QString host(int topicIndex) const;
    void setHost(const QString& topic, const QString& host);
    const QHash<QString, QString>& hosts() const { return m_hosts; }
    bool hasHosts() const;
    bool isCrossing(int stage) const;
    QList<int> crossings() const;
    /// With exactly one crossing away from the first stamp's host and one back to it: (out, return).
    std::optional<std::pair<int, int>> outAndReturnCrossings() const;

    /// How the topics and stages are named for people (PipelineLabels).
    const PipelineLabels& labels() const { return m_labels; }
    /// A short label for stage i: "mqtt_interface_vehicle → mqtt_interface_cloud" between
    /// components, "mqtt_interface_vehicle/pointcloud (in → out)" within one.
    QString stageLabel(int stage) const;
    /// The first name part after the common prefix ("mqtt_interface_vehicle").
    QString component(int topicIndex) const;

    bool operator==(const Pipeline& o) const
    {
        return m_topics == o.m_topics && m_window == o.m_window && m_hosts == o.m_hosts
            && m_oneClock == o.m_oneClock;
    }

private:
    /// metrics_window, one_clock and hosts of a pipeline file.
    Status readSettings(const YAML::Node& root);
    static QString normalized(QStringView topic);

    QStringList m_topics;
    PipelineLabels m_labels; ///< of m_topics, made again with them
    QHash<QString, int> m_index; ///< normalized topic and "/" + normalized topic -> index
    QHash<QString, QString> m_hosts;
    int m_window = kDefaultWindow;
    bool m_oneClock = false;
};
