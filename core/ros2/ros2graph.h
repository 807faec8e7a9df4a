// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "topics/topicgraph.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

/// The QoS of a ROS 2 endpoint as DDS discovery announces it. History depth does not travel in
/// DDS discovery (it is local to the writer or reader), so it is known only for our own endpoints.
struct Ros2Qos
{
    enum Reliability { BestEffort, Reliable };
    enum Durability { Volatile, TransientLocal, Transient, Persistent };
    Reliability reliability = Reliable;
    Durability durability = Volatile;
    int depth = -1; ///< -1: not known

    QString reliabilityText() const;
    QString durabilityText() const;
    /// As ROS 2 configs and `discover --json` spell them: "reliable", "best_effort"; "volatile",
    /// "transient_local", "transient", "persistent".
    QString reliabilityName() const;
    QString durabilityName() const;
    /// "reliable, volatile" (and ", depth 10" when known).
    QString text() const;
    bool operator==(const Ros2Qos& o) const
    {
        return reliability == o.reliability && durability == o.durability && depth == o.depth;
    }
};

/// Whether a subscription with QoS `sub` gets the samples of a publisher with QoS `pub`, by the
/// DDS request-offered rules (reliability and durability); `why` names the mismatch.
bool ros2QosCompatible(const Ros2Qos& pub, const Ros2Qos& sub, QString* why = nullptr);

/// One DDS writer or reader of a ROS 2 topic.
struct Ros2Endpoint
{
    QByteArray gid; ///< the 16-byte DDS GUID
    QString topic; ///< ROS 2 name, `/chatter`
    QString type; ///< ROS 2 name, `std_msgs/msg/String` (the DDS name when not in ROS form)
    bool publisher = true;
    Ros2Qos qos;
    QString node; ///< full node name, `/ns/talker`; empty until ros_discovery_info names it

    QByteArray participantGid() const { return gid.left(12); }
};

/// A node as ros_discovery_info announces it: which readers and writers are its own.
struct Ros2NodeInfo
{
    QString nameSpace;
    QString name;
    QList<QByteArray> readers; ///< 16-byte GUIDs
    QList<QByteArray> writers;
    QString fullName() const;
};

/// One participant's ros_discovery_info sample (rmw_dds_common/msg/ParticipantEntitiesInfo).
struct Ros2ParticipantInfo
{
    QByteArray gid; ///< 16-byte GUID of the participant
    QList<Ros2NodeInfo> nodes;
};

/// Reads a ros_discovery_info sample: CDR with its encapsulation header, the Gid of Humble
/// (`char[24]`) or of Iron and later (`uint8[16]`), whichever reads the whole sample. Bounded:
/// every sequence length is checked against the bytes left before anything is allocated.
class Ros2DiscoveryInfo
{
    Q_DECLARE_TR_FUNCTIONS(Ros2DiscoveryInfo)
public:
    static constexpr int kMaxNodes = 4096;
    static Result<Ros2ParticipantInfo> parse(const QByteArray& cdr);
};

/// A ROS 2 topic with its endpoints.
struct Ros2Topic
{
    QString name;
    QStringList types; ///< one unless publishers disagree
    QList<Ros2Endpoint> publishers;
    QList<Ros2Endpoint> subscribers;
    QString type() const { return types.value(0); }
};

/// A node with the topics it publishes and subscribes.
struct Ros2Node
{
    QString name; ///< full name
    QStringList publishes;
    QStringList subscribes;
};

/// A ROS 2 graph as seen from DDS discovery: topics (services and DDS-only topics left out),
/// nodes named by ros_discovery_info, and the number of participants.
struct Ros2Graph
{
    QList<Ros2Topic> topics; ///< sorted by name
    QList<Ros2Node> nodes; ///< sorted by name
    int participants = 0;
    int services = 0; ///< distinct service names seen (not listed)
    /// Endpoints (and nodes) discovered but not listed because they passed a bound: a name or type
    /// too long, too many of a participant or a topic, too many types on a topic, or a graph too
    /// large for one frame (issue 41). Shown wherever the graph is.
    quint64 omitted = 0;

    /// A topic keeps at most this many endpoints (publishers and subscribers together) and types;
    /// the rest are counted in `omitted`.
    static constexpr int kMaxEndpointsPerTopic = 10'000;
    static constexpr int kMaxTypesPerTopic = 16;

    const Ros2Topic* topic(const QString& name) const;
    /// "12 endpoints not listed (over a bound)", or empty: what `omitted` counts, for status lines.
    QString omittedText() const;
    /// The graph as every view shows one (graph-neutral): nodes as publishers and subscribers (an
    /// endpoint no node claims as its GUID in parentheses), every node.
    TopicGraph topicGraph() const;
    /// Puts endpoints and node announcements together; endpoints of DDS topics that are not ROS 2
    /// topics (`ros_discovery_info`, services) are counted, not listed. Each endpoint costs a few
    /// hash lookups (never a scan of what was seen before); an endpoint past a topic's bounds is
    /// counted in `omitted`.
    static Ros2Graph build(const QList<Ros2Endpoint>& endpoints, const QList<Ros2ParticipantInfo>& infos,
                           int participants, const QStringList& serviceTopics = {});
    bool operator==(const Ros2Graph& o) const;
};
