// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"

#include <functional>
#include <memory>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// A ROS message as bytes, with the type it travels as.
struct RosRawMessage
{
    QByteArray bytes; ///< ROS-serialized
    QString type; ///< e.g. "sensor_msgs/PointCloud2"
    QString md5;
    QString definition; ///< full, with dependencies
};

/// The ROS side of a bridge process: one named roscpp node that subscribes to any topic
/// generically and publishes raw serialized messages of any type (as mqtt_client does with
/// topic_tools::ShapeShifter).
///
/// Unlike RosNode (the GUI's shared, anonymous node), this one is made for a process of its own
/// (`bridgescope bridge`): callbacks run on roscpp's spinner threads and must not block;
/// publish() may be called from any thread.
class RosEndpoint
{
    Q_DECLARE_TR_FUNCTIONS(RosEndpoint)
public:
    using Handler = std::function<void(const RosRawMessage& message, qint64 receivedNs)>;

    RosEndpoint();
    ~RosEndpoint();
    RosEndpoint(const RosEndpoint&) = delete;
    RosEndpoint& operator=(const RosEndpoint&) = delete;

    /// Starts the node `name` (no SIGINT handler: the caller stops) once `masterUri` answers;
    /// `keepWaiting` is asked every half second while the master is not there.
    Status start(const QString& name, const QString& masterUri, const std::function<bool()>& keepWaiting);
    void shutdown();
    /// Gets a line when the node registers again with a restarted master (on a thread of its own).
    void setNoticeHandler(std::function<void(const QString& line)> notice);
    /// The node's full name, e.g. "/mqtt_client".
    QString nodeName() const;
    /// `name` resolved as roscpp does ("~/x" is private to the node, "//" collapses).
    QString resolve(const QString& name) const;

    /// An error without text when the node has not started.
    Status subscribe(const QString& topic, int queueSize, Handler handler);
    /// Advertises `topic` with the given type; returns a publisher id, or an error (also when roscpp
    /// refuses it: a topic this node already publishes with another type; without text when the
    /// node has not started).
    Result<int> advertise(const QString& topic, const QString& type, const QString& md5,
                          const QString& definition, int queueSize, bool latched);
    /// Stops publishing with `publisher` (its topic can then be advertised with another type); the id
    /// is invalid afterwards and may be handed out again.
    void retire(int publisher);
    bool publish(int publisher, const QByteArray& bytes);
    enum class Sent { Ok, Full, Failed };
    /// publish() within the bound of setMaxHeldBytes(): Full, and not published, when roscpp would
    /// then hold more.
    Sent send(int publisher, const QByteArray& bytes);
    /// Bounds the bytes roscpp holds of the messages published here (queued towards subscribers
    /// that read slower, at most queue_size each, and a latched topic's last message); one message
    /// always passes. 0 (the default): no bound.
    void setMaxHeldBytes(qint64 bytes);
    /// The bytes roscpp holds now of the messages published here.
    qint64 heldBytes() const;
    int subscriberCount(int publisher) const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};
