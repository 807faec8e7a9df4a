// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

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
    /// Whether two names are the same stamp topic ("/a/b" on ROS is "a/b" on MQTT).
    static bool sameTopic(QStringView a, QStringView b) { return normalized(a) == normalized(b); }

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

    /// A short label for stage i: "mqtt_interface_vehicle → mqtt_interface_cloud" between
    /// components, "mqtt_interface_vehicle/pointcloud (in → out)" within one.
    QString stageLabel(int stage) const;
    /// The stage's two topics without their common prefix.
    QString longStageLabel(int stage) const;
    /// The first name part after the common prefix ("mqtt_interface_vehicle").
    QString component(int topicIndex) const;
    /// The topic without the prefix all topics share.
    QString shortTopic(int topicIndex) const;

    /// Hosts guessed from topic names: a name part "vehicle", "car", "robot" or "cloud", "edge",
    /// "server" sets a host; topics without one take their neighbours' host.
    static QHash<QString, QString> guessHosts(const QStringList& topics);
    /// The host a topic's name stands for ("vehicle", "cloud"), or empty when no part names one.
    static QString hostOfName(const QString& topic);

    bool operator==(const Pipeline& o) const
    {
        return m_topics == o.m_topics && m_window == o.m_window && m_hosts == o.m_hosts
            && m_oneClock == o.m_oneClock;
    }

private:
    /// metrics_window, one_clock and hosts of a pipeline file.
    Status readSettings(const YAML::Node& root);
    static QString normalized(QStringView topic);
    /// The common prefix and every stage label, in one pass over the topics (not per call).
    void relabel();

    QStringList m_topics;
    qsizetype m_prefix = 0; ///< length of the prefix all topics share, up to a '/'
    QStringList m_stageLabels;
    QHash<QString, int> m_index; ///< normalized topic and "/" + normalized topic -> index
    QHash<QString, QString> m_hosts;
    int m_window = kDefaultWindow;
    bool m_oneClock = false;
};
