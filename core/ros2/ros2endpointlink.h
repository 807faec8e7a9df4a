// SPDX-License-Identifier: MIT
#pragma once

#include "ros2/ddschildpipe.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2protocol.h"
#include "ros2/ros2types.h"

#include <QHash>
#include <QObject>
#include <QString>

/// The parent side of this program's own endpoints in the child: the node announced, the writers
/// and readers asked for (advertise(), subscribe()), the samples published and received, and the
/// quarantine: a request the child ended while making (not answered by EndpointDone) is refused
/// and never asked again, of this child or the next. Part of Ros2Link, which replays it after each
/// restart. Its users reach it as Ros2Participant::node().
class Ros2EndpointLink : public QObject
{
    Q_OBJECT
public:
    explicit Ros2EndpointLink(DdsChildPipe& pipe, QObject* parent = nullptr);

    /// A new child runs: the node, writers and readers are asked of it again.
    void replay();
    /// Whether the child was making a request (Advertise, Subscribe not answered yet).
    bool makingRequests() const { return !m_unanswered.isEmpty(); }
    /// The child ended (`why`) while making the requests not answered: they are quarantined and
    /// refused (endpointRefused()).
    void quarantineUnanswered(const QString& why);
    /// The child's Received and EndpointDone frames; false when the body does not read.
    bool onReceived(const QByteArray& body);
    bool onEndpointDone(const QByteArray& body);

    /// The node announced in ros_discovery_info (rmw_dds_common's ParticipantEntitiesInfo) with the
    /// gids of the writers and readers made by advertise() and subscribe(); the participant's
    /// graph() shows it too. Default: none announced.
    void setNode(const QString& nameSpace, const QString& name);
    /// A DDS writer of ROS topic `topic` ("/chatter": DDS "rt/chatter") of ROS 2 type `type`
    /// ("std_msgs/msg/String": "std_msgs::msg::dds_::String_"), with QoS as rmw_cyclonedds_cpp's
    /// create_readwrite_qos (volatile or transient local, keep last `depth`; a depth below 1 is 10,
    /// rclcpp's default).
    ///
    /// False, with endpointRefused(), when the topic or type is not one DDS may be given
    /// (Ros2Names::isValidTopic, isValidType), or when this writer is quarantined: the child
    /// ended while it made it before (see endpointRefused()).
    bool advertise(const QString& topic, const QString& type, const Ros2Qos& qos = {});
    void unadvertise(const QString& topic);
    bool isAdvertised(const QString& topic) const { return m_advertised.contains(topic); }
    /// One sample: CDR bytes with their 4-byte encapsulation header (00 01 00 00). False, and
    /// counted by publishDropped(), when it cannot be sent now: not advertised, the child not
    /// running, the pipe holding the publish bound already, or a sample that is not CDR. A sample
    /// larger than the bound passes when nothing waits in the pipe.
    bool publish(const QString& topic, const QByteArray& cdr);
    /// Bytes of samples the pipe to the child may hold before publish() drops (default
    /// kMaxPendingPublishBytes).
    void setPublishBound(qint64 bytes) { m_publishBound = bytes; }
    quint64 publishDropped() const { return m_publishDropped; }
    /// A DDS reader of `topic` of `type` with `qos` (as advertise()'s), made at once whether or not
    /// the graph knows the topic. Every sample comes by received() as soon as the child passes it
    /// on. Samples are at most Ros2RawType's 64 MiB, queued in the child within a byte bound (the
    /// drops counted by droppedReceived()).
    /// False, with endpointRefused(), as advertise().
    bool subscribe(const QString& topic, const QString& type, const Ros2Qos& qos = {});
    void unsubscribe(const QString& topic);
    bool isSubscribed(const QString& topic) const { return m_subscribed.contains(topic); }
    /// Samples of subscribed topics the child dropped because too many waited for the pipe (since
    /// this object was made).
    quint64 droppedReceived() const;
    /// Requests quarantined since this object was made (see endpointRefused()).
    int quarantined() const { return int(m_quarantine.size()); }
    QString lastQuarantineReason() const { return m_lastQuarantine; }

    static constexpr qint64 kMaxPendingPublishBytes = 128 * 1024 * 1024;

signals:
    /// An advertise() or subscribe() that is not (or no longer) made, and why: a name DDS may not
    /// be given, Cyclone refused it, or the child ended (crashed, stalled) before it answered the
    /// request, which is then quarantined: not asked again after the restart, nor when asked
    /// again with the same topic and type (issue 41: a type that crashes Cyclone would crash
    /// every child after it). The rest goes on.
    void endpointRefused(const QString& topic, const QString& why);
    /// One sample of a subscribed topic (receivedNs: the wall clock in the child when it came).
    void received(const QString& topic, const Ros2Sample& sample);

private:
    static QString endpointKey(bool advertise, const Ros2Protocol::EndpointRequest& e);
    /// Sends an Advertise or Subscribe, waiting for its answer; false when it is refused at once.
    bool requestEndpoint(bool advertise, const Ros2Protocol::EndpointRequest& e);
    void refuseEndpoint(bool advertise, const QString& topic, const QString& why);

    DdsChildPipe& m_pipe;
    struct Node
    {
        QString nameSpace;
        QString name;
    };
    Node m_node;
    QHash<QString, Ros2Protocol::EndpointRequest> m_advertised; ///< across stop() and start()
    QHash<QString, Ros2Protocol::EndpointRequest> m_subscribed; ///< across stop() and start()
    /// Advertise and Subscribe requests the child has not answered (EndpointDone) yet, by key.
    QHash<QString, Ros2Protocol::EndpointRequest> m_unanswered;
    /// Requests during which a child ended, by key, with why: never sent again.
    QHash<QString, QString> m_quarantine;
    QString m_lastQuarantine;
    QHash<QString, quint64> m_receivedDropped; ///< the child's count, by topic, since its start
    quint64 m_receivedDroppedBefore = 0; ///< counted by children before this one
    quint64 m_publishDropped = 0;
    qint64 m_publishBound = kMaxPendingPublishBytes;
};
