// SPDX-License-Identifier: MIT
#pragma once

#include "latency/stampsource.h"
#include "mqtt/mqttconnection.h"
#include "wire/mqttclientwire.h"
#include "wire/rosmessage.h"
#include "wire/stampevent.h"

#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <vector>

/// Stamps from MQTT, in a batch as the drain timer takes it from the connection:
/// - `benchmarking_suite/TimeStamped` carried by mqtt_client (its type announcement on
///   `mqtt_client/ros_msg_type/<topic>`, then ROS-serialized payloads, stamped or not), and its
///   ROS 2 form `benchmarking_suite/msg/TimeStamped` as mqtt_client for ROS 2 carries it (CDR);
/// - JSON stamps `{"sample": "<id>", "time": <seconds | "sec.nsec">}` on any topic;
/// - every stamped mqtt_client payload (any type, ROS 1 or ROS 2) as a single-stage latency
///   series: receive time minus the injected send stamp, as mqtt_client computes for
///   `~/latencies/<topic>`.
///
/// Stamp topics keep their MQTT names ("a/b"); pipelines match them to ROS names ("/a/b").
class MqttStampDecoder : public StampSource
{
    Q_DECLARE_TR_FUNCTIONS(MqttStampDecoder)
public:
    /// The series name of a stamped MQTT topic's latency.
    static QString latencySeries(const QString& topic) { return QStringLiteral("mqtt:") + topic; }
    /// Whether an announced type is the suite's stamp: ROS 1 by its md5, ROS 2 by its name.
    static bool isTimeStamped(const RosMsgTypeInfo& info);

    void decode(const std::vector<MqttMessage>& batch, std::vector<StampEvent>& stamps,
                std::vector<LatencyValue>& latencies);
    void clear();
    /// Decodes a batch into what takeStamps() hands over next.
    void collect(const std::vector<MqttMessage>& batch) { decode(batch, m_stamps, m_latencies); }

    void takeStamps(std::vector<StampEvent>& stamps, std::vector<LatencyValue>& latencies) override;
    quint64 malformedStamps() const override { return m_malformed; }
    QHash<QString, quint64> malformedStampsByTopic() const override { return m_malformedByTopic; }
    QString lastStampError() const override { return m_lastError; }

    quint64 malformed() const { return m_malformed; }
    /// Malformed stamps (and stamp type announcements) per MQTT topic.
    const QHash<QString, quint64>& malformedByTopic() const { return m_malformedByTopic; }
    QString lastError() const { return m_lastError; }

private:
    struct TopicType
    {
        bool timeStamped = false; ///< ROS 1 by md5, ROS 2 by name (its announcements have no md5)
        bool stamped = false;
        RosTypeRegistry::Dialect dialect = RosTypeRegistry::Dialect::Ros1;
    };
    void fail(const QString& topic, const QString& why);

    QHash<QString, TopicType> m_types; ///< by data topic, from the announcements
    std::vector<StampEvent> m_stamps; ///< collect()ed, not taken yet
    std::vector<LatencyValue> m_latencies;
    quint64 m_malformed = 0;
    QHash<QString, quint64> m_malformedByTopic;
    QString m_lastError;
};
