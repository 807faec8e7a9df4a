// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/mappinghealth.h"

#include <QCoreApplication>
#include <QHash>

struct TopicGraph;
struct TopicInfo;
struct Ros2Graph;
struct Ros2Qos;
struct Ros2Topic;
struct TopicFigures;
class FlowRates;

/// Evaluates every mapping of a config against the ROS graph and the figures of its ROS and MQTT
/// topics, as their MessageSources give them. For a ROS 2 graph (`ros2` set; `graph` is then its
/// TopicGraph form) it also checks the QoS mqtt_client would use against the topic's endpoints.
class MappingHealthEvaluator
{
    Q_DECLARE_TR_FUNCTIONS(MappingHealth)
public:
    struct Inputs
    {
        const TopicGraph* graph = nullptr;
        bool rosReachable = false;
        const QHash<QString, TopicFigures>* monitored = nullptr; ///< MessageSource::figures()
        /// The mappings' MQTT topics' figures (the MQTT MessageSource's, with their announced type).
        const QHash<QString, TopicFigures>* mqtt = nullptr;
        bool mqttConnected = false;
        qint64 nowNs = 0;
        qint64 activeWindowNs = 5'000'000'000LL; ///< a topic counts as active for this long after a message
        const Ros2Graph* ros2 = nullptr; ///< the ROS side is this ROS 2 graph
        /// Both ends' message counts over one window: a flowing mapping's rates are taken from
        /// there when known (the figures' own rates come from windows of their own).
        const FlowRates* flows = nullptr;
    };
    static QHash<quint64, MappingHealth> evaluate(const BridgeConfig& config, const Inputs& in);
    /// "pkg/msg/Type" and "pkg/Type" name the same type.
    static bool sameType(const QString& a, const QString& b);
    /// The QoS mqtt_client (v2.5) gives a mapping's ROS 2 endpoint: `advanced.ros.qos.*` where set,
    /// `system_default` as reliable and volatile (what Fast DDS and Cyclone DDS default to); for a
    /// ros2mqtt subscription `auto` (the default) takes the publisher's `matched` QoS. False when a
    /// value is not known (a substitution, a typo).
    static bool bridgeQos(const Mapping& m, const Ros2Qos& matched, Ros2Qos* qos);
    /// ROS 2: why no endpoint on the other side of the bridge's ROS endpoint can match it (its
    /// publishers for ros2mqtt, its subscribers for mqtt2ros), or empty.
    static QString qosProblem(const Mapping& m, const Ros2Topic& topic);

private:
    /// A flowing mapping's rates and words from both ends counted over the same interval.
    static void rateOverOneWindow(const Mapping& m, const Inputs& in, MappingHealth* h);
    /// What outranks the flow's verdict: a type announcement that contradicts the ROS graph, a
    /// QoS that keeps the bridge's ROS 2 endpoint from matching; then the last latency is added.
    static void overrule(const Mapping& m, const TopicInfo* rosInfo, const TopicFigures* mqttInfo,
                         const Inputs& in, MappingHealth* h);
};
