// SPDX-License-Identifier: MIT
#pragma once

#include "latency/stampsource.h"
#include "wire/stampevent.h"

#include <map>
#include <memory>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QString>
#include <vector>

class Ros2Participant;
class Tap;

/// Stamps from a ROS 2 graph, as RosStampSource takes them from ROS 1: the suite's
/// `benchmarking_suite/msg/TimeStamped` topics and mqtt_client's `~/latencies/<topic>`
/// (`std_msgs/msg/Float64`, seconds), read as whole samples through the participant
/// (a Tap of the participant per topic) and decoded by hand (StampCodec).
///
/// A stamp needs the whole sample (its frame_id comes before `time`), so a topic is watched, not
/// only monitored, in a queue of this source's own (a field plot of the same topic takes nothing
/// from it); the participant asks the DDS child again after a restart. Everything runs on the
/// thread of the participant (the GUI thread): take() decodes what the participant collected.
class Ros2StampSource : public QObject, public StampSource
{
    Q_OBJECT
public:
    /// Samples kept per topic between two takes (a drain tick); more are dropped and counted.
    static constexpr std::size_t kQueued = 20000;
    static constexpr qint64 kQueuedBytes = 8 * 1024 * 1024;

    explicit Ros2StampSource(Ros2Participant* participant, QObject* parent = nullptr);
    ~Ros2StampSource() override;

    /// Watches exactly these topics (and no more the rest). `stampTopics` maps a ROS 2 topic to the
    /// name its stamps carry (StampEvent::topic: the topic itself, or `ros2:/topic` where a ROS 1
    /// topic has the same name); latencies carry their topic's name.
    void setTopics(const QHash<QString, QString>& stampTopics, const QSet<QString>& latencyTopics);
    QHash<QString, QString> stampTopics() const { return m_stamps; }
    QSet<QString> latencyTopics() const { return m_latencies; }

    /// Decodes what arrived since the last call: stamps into `stamps`, latencies into `latencies`.
    void takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies) override;
    quint64 received() const { return m_received; }
    quint64 malformed() const { return m_malformed; } ///< samples that did not decode
    /// Malformed samples per topic (its ROS 2 name), and the last one's reason ("TOPIC: why").
    const QHash<QString, quint64>& malformedByTopic() const { return m_malformedByTopic; }
    QString lastError() const { return m_lastError; }
    quint64 dropped() const; ///< lost because too many came between two takes

    quint64 malformedStamps() const override { return m_malformed; }
    QHash<QString, quint64> malformedStampsByTopic() const override { return m_malformedByTopic; }
    QString lastStampError() const override { return m_lastError; }

private:
    void fail(const QString& topic, const QString& why);
    void unwatch(const QString& topic);

    QPointer<Ros2Participant> m_participant;
    std::map<QString, std::unique_ptr<Tap>> m_taps; ///< a tap per stamp and latency topic
    QHash<QString, QString> m_stamps;
    QSet<QString> m_latencies;
    quint64 m_received = 0;
    quint64 m_malformed = 0;
    quint64 m_droppedBefore = 0; ///< by topics no longer watched
    QHash<QString, quint64> m_malformedByTopic;
    QString m_lastError;
};
