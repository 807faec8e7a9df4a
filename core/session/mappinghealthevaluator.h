// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "config/mappinghealth.h"

#include <QCoreApplication>
#include <QHash>

struct RosGraph;
struct RosMonitorStats;
class MqttTopicTree;

/// Evaluates every mapping of a config against the ROS graph, the monitored ROS topics and the
/// broker's topic tree.
class MappingHealthEvaluator
{
    Q_DECLARE_TR_FUNCTIONS(MappingHealth)
public:
    struct Inputs
    {
        const RosGraph* graph = nullptr;
        bool rosReachable = false;
        const QHash<QString, RosMonitorStats>* monitored = nullptr;
        const MqttTopicTree* mqtt = nullptr;
        bool mqttConnected = false;
        qint64 nowNs = 0;
        qint64 activeWindowNs = 5'000'000'000LL; ///< a topic counts as active for this long after a message
    };
    static QHash<quint64, MappingHealth> evaluate(const BridgeConfig& config, const Inputs& in);
    /// "pkg/msg/Type" and "pkg/Type" name the same type.
    static bool sameType(const QString& a, const QString& b);
};
