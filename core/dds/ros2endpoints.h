// SPDX-License-Identifier: MIT
#pragma once

// The writers and readers this program makes on a ROS 2 graph (Ros2Participant's advertise(),
// subscribe() and setNode()), and the node that owns them in ros_discovery_info. Included by
// ros2engine.cpp only: Cyclone stays out of every header other layers see.

#include "dds/ros2engine.h"
#include "ros2/ros2graph.h"
#include "ros2/ros2types.h"

#include <atomic>
#include <dds/dds.h>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <QByteArray>
#include <QString>
#include <utility>
#include <vector>

struct Ros2RawReader;

/// Endpoints of one participant, each with the raw-bytes sertype (Ros2RawType), QoS as
/// rmw_cyclonedds_cpp's create_readwrite_qos. Samples of the readers are queued on Cyclone's
/// listener thread within kMaxQueuedBytes and kMaxQueuedSamples over all readers (a sample over
/// either is dropped and counted), and `wake` is called there when the queues were empty and get
/// one; takeReceived() takes them on the owner thread, a batch at a time.
class Ros2Endpoints
{
public:
    /// Bytes of received samples waiting for takeReceived(), over all subscriptions.
    static constexpr qint64 kMaxQueuedBytes = 128 * 1024 * 1024;
    static constexpr std::size_t kMaxQueuedSamples = 100'000;

    Ros2Endpoints(dds_entity_t participant, std::function<void()> wake);
    ~Ros2Endpoints();

    void setNode(const QString& nameSpace, const QString& name);
    /// False with `why` when Cyclone refuses.
    Status advertise(const QString& topic, const QString& type, const Ros2Qos& qos);
    void unadvertise(const QString& topic);
    /// False when the topic is not advertised or Cyclone refuses the sample.
    bool publish(const QString& topic, const QByteArray& cdr);
    Status subscribe(const QString& topic, const QString& type, const Ros2Qos& qos);
    void unsubscribe(const QString& topic);

    /// The subscriptions' oldest samples, about `maxBytes` of them (at least one), topic by topic
    /// (with each one's drops since it was made). They leave the bound as they are taken, so the
    /// owner takes what it can pass on now: samples taken while the pipe to the parent is full
    /// would be held beside a queue filling again (twice the bound).
    std::vector<Ros2Engine::Received> takeReceived(qint64 maxBytes);

    /// Our own endpoints and node, for the graph (discovery does not show a participant its own).
    QList<Ros2Endpoint> ownEndpoints() const;
    QList<Ros2ParticipantInfo> ownInfo() const;
    /// Bumped at every change of ownEndpoints() or ownInfo().
    quint64 changes() const { return m_changes; }

    /// A ParticipantEntitiesInfo sample as rmw_dds_common (Humble) writes it: CDR with its
    /// encapsulation header, gids of 24 bytes (the 16-byte GUID, then zeros).
    static QByteArray encodeInfo(const QByteArray& participantGid, const QString& nameSpace, const QString& name,
                                 const QList<QByteArray>& readers, const QList<QByteArray>& writers);

private:
    struct Writer
    {
        dds_entity_t topic = 0;
        dds_entity_t writer = 0;
        Ros2Endpoint endpoint;
    };
    struct Subscription
    {
        std::unique_ptr<Ros2RawReader> reader;
        Ros2Endpoint endpoint;
        std::vector<Ros2Sample> queue; ///< under m_mutex
        quint64 dropped = 0; ///< under m_mutex
    };
    void onSample(const QString& topic, const unsigned char* data, std::size_t size);
    void announce();

    dds_entity_t m_participant;
    std::function<void()> m_wake;
    QByteArray m_gid; ///< the participant's 16-byte GUID
    QString m_nameSpace;
    QString m_name;
    dds_entity_t m_infoTopic = 0;
    dds_entity_t m_infoWriter = 0;
    std::map<QString, Writer> m_writers;
    std::map<QString, std::unique_ptr<Subscription>> m_subscriptions; ///< entries under m_mutex
    mutable std::mutex m_mutex;
    qint64 m_queuedBytes = 0; ///< under m_mutex
    std::size_t m_queuedSamples = 0; ///< under m_mutex
    std::atomic<bool> m_woken {false};
    quint64 m_changes = 1;
};
