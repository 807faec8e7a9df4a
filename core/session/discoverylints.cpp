// SPDX-License-Identifier: MIT
#include "discoverylints.h"

#include "config/configvalidator.h"
#include "ros/rosmasterapi.h"
#include "ros2/ros2graph.h"
#include "topics/topicfigures.h"
#include "yaml/yamltree.h"

using namespace Qt::StringLiterals;

namespace {

class Linter
{
    Q_DECLARE_TR_FUNCTIONS(DiscoveryLints)
public:
    Linter(const BridgeConfig& config, const MappingHealthEvaluator::Inputs& in,
           const DiscoveryLints::Options& o)
        : m_config(config)
        , m_in(in)
        , m_target(o.target.value_or(MqttClientReleases::defaultTarget(config)))
        , m_discoveryServer(o.discoveryServer.trimmed())
    { }

    QList<Problem> problems;

    void run()
    {
        discoveryServer();
        if (!m_in.rosReachable && !m_in.mqttConnected)
            return;
        for (const Mapping& m : m_config.mappings) {
            if (m.direction == Direction::Mqtt2Ros)
                nonRosPublisher(m);
            if (m_in.ros2) {
                if (const Ros2Topic* t = m_in.ros2->topic(m.rosTopic())) {
                    typeChanges(m, *t);
                    qos(m, *t);
                }
            }
        }
    }

private:
    void add(const Mapping* m, const QString& code, const QString& field, const QString& message,
             const QString& fix)
    {
        problems.append(Problem::about(m, Severity::Warning, code, field, message, fix));
    }

    static QString describe(const Mapping& m) { return ConfigValidator::describe(m); }

    bool atLeast(MqttClientRelease r) const { return m_target >= r; }

    /// mqtt_client #12, #78: payloads mqtt_client did not send, on a topic it reads as ROS messages.
    void nonRosPublisher(const Mapping& m)
    {
        if (!m_in.mqttConnected || !m_in.mqtt || YamlText::isTrue(m.value(u"primitive"_s))
            || YamlText::isTrue(m.value(u"json"_s)) || !m.value(u"ros_type"_s).trimmed().isEmpty())
            return;
        const auto it = m_in.mqtt->constFind(m.mqttTopic());
        if (it == m_in.mqtt->cend() || it->messages == 0 || !it->type.isEmpty())
            return;
        QStringList fixes;
        fixes << tr("If its publishers send text or numbers, set primitive: true (a std_msgs type "
                    "is chosen from the payload)");
        if (atLeast(MqttClientRelease::V2_3) && m_config.layout == ConfigLayout::Ros2)
            fixes << tr("or set ros_type to the std_msgs type of the payload (e.g. "
                        "std_msgs/msg/Float64) together with primitive: true");
        if (atLeast(MqttClientRelease::V2_5) && m_config.layout == ConfigLayout::Ros2)
            fixes << tr("if they send JSON, set json: true and ros_type to the message its fields "
                        "fill");
        add(&m, u"non-ros-publisher"_s, u"primitive"_s,
            tr("%1: '%2' carries messages but no mqtt_client announced their type on "
               "'mqtt_client/ros_msg_type/%2', so the bridge waits for one and never publishes them "
               "on ROS (mqtt_client issues #12, #78).")
                .arg(describe(m), m.mqttTopic()),
            fixes.join(u"; "_s) + u'.');
    }

    /// mqtt_client #15, #45: the type the bridge takes depends on who published first.
    void typeChanges(const Mapping& m, const Ros2Topic& t)
    {
        const QString fixed = m.value(u"ros_type"_s).trimmed();
        QStringList published;
        for (const Ros2Endpoint& e : t.publishers)
            if (!e.type.isEmpty() && !published.contains(e.type))
                published << e.type;
        if (fixed.isEmpty()) {
            if (published.size() < 2)
                return;
            const QString fix = atLeast(MqttClientRelease::V2_3)
                ? tr("Set ros_type to the type the bridge must carry; publishers of other types are "
                     "then left out.")
                : tr("Give the topics of different types different names: ros_type, which fixes the "
                     "type, needs mqtt_client 2.3.");
            add(&m, u"ros-type-changes"_s, u"ros_type"_s,
                tr("%1: '%2' is published with %3 types (%4); without ros_type the bridge takes the "
                   "type of the publisher it finds first, and a publisher of another type stops or "
                   "breaks the link (mqtt_client issues #15, #45).")
                    .arg(describe(m), t.name)
                    .arg(published.size())
                    .arg(published.join(u", "_s)),
                fix);
            return;
        }
        if (m.direction != Direction::Ros2Mqtt || published.isEmpty())
            return;
        for (const QString& type : std::as_const(published))
            if (MappingHealthEvaluator::sameType(type, fixed))
                return;
        add(&m, u"ros-type-changes"_s, u"ros_type"_s,
            tr("%1: ros_type is '%2', but '%3' is published as %4 only: the bridge's subscription "
               "matches no publisher.")
                .arg(describe(m), fixed, t.name, published.join(u", "_s)),
            tr("Set ros_type to %1, or remove it to take the publishers' type.").arg(published.first()));
    }

    /// mqtt_client #48: a QoS the topic's other endpoints cannot match.
    void qos(const Mapping& m, const Ros2Topic& t)
    {
        const QString why = MappingHealthEvaluator::qosProblem(m, t);
        if (why.isEmpty())
            return;
        const bool out = m.direction == Direction::Ros2Mqtt;
        QString fix = out ? tr("Set advanced.ros.qos.reliability and .durability to auto (the default "
                               "from mqtt_client 2.3), or to what the publishers offer.")
                          : tr("Offer at least what the subscribers ask for in "
                               "advanced.ros.qos.reliability and .durability.");
        if (!atLeast(MqttClientRelease::V2_3))
            fix = tr("mqtt_client 2.2 has no advanced.ros.qos: make the publishers offer reliable, "
                     "volatile, or target 2.3 or later.");
        add(&m, u"qos-incompatible"_s, u"advanced.ros.qos.reliability"_s,
            out ? tr("%1: mqtt_client's subscription to '%2' cannot match a publisher: %3 (mqtt_client "
                     "issue #48).")
                      .arg(describe(m), t.name, why)
                : tr("%1: subscribers of '%2' cannot get mqtt_client's messages: %3 (mqtt_client issue "
                     "#48).")
                      .arg(describe(m), t.name, why),
            fix);
    }

    /// mqtt_client #67: a discovery client sees only what its server tells it.
    void discoveryServer()
    {
        if (m_discoveryServer.isEmpty() || m_config.layout != ConfigLayout::Ros2)
            return;
        // (what Bridgescope sees is on the Discover page: a count here would change the list)
        const QString seen = u' '
            + tr("Nodes that are discovery clients announce themselves to the server only: Bridgescope "
                 "joins the domain by simple discovery and does not see them either.");
        add(nullptr, u"fastdds-discovery-server"_s, QString(),
            tr("This lab uses a Fast DDS discovery server (ROS_DISCOVERY_SERVER=%1). A bridge started "
               "there as a plain client is told only of the endpoints it matches, and then bridges "
               "nothing of the ROS topics it has to find by name (mqtt_client issue #67).%2")
                .arg(m_discoveryServer, seen),
            tr("Start mqtt_client as a super client: export ROS_SUPER_CLIENT=TRUE, or give it a "
               "FASTRTPS_DEFAULT_PROFILES_FILE whose participant's discovery protocol is "
               "SUPER_CLIENT."));
    }

    const BridgeConfig& m_config;
    const MappingHealthEvaluator::Inputs& m_in;
    MqttClientRelease m_target;
    QString m_discoveryServer;
};

} // namespace

QList<Problem> DiscoveryLints::check(const BridgeConfig& config, const MappingHealthEvaluator::Inputs& in,
                                     const Options& options)
{
    Linter l(config, in, options);
    l.run();
    return l.problems;
}
