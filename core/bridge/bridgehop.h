// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "bridge/bridgespec.h"
#include "wire/mqttclientwire.h"
#include "wire/stampcodec.h"

#include <algorithm>
#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <QByteArray>
#include <QHash>
#include <QString>

class MqttLink;

/// How a reference bridge runs, whichever ROS it runs on.
struct BridgeOptions
{
    static constexpr qint64 kDefaultMaxQueuedBytes = 64 * 1024 * 1024;

    QString brokerUrl; ///< overrides the config's broker (host, port, TLS) when set
    QString rosMaster; ///< ROS 1; empty: ROS_MASTER_URI
    QString nodeName; ///< empty: "mqtt_client" (ROS 2: the config's node key first)
    QHash<QString, QString> args; ///< values for `$(arg NAME)` in the config
    /// Added to this bridge's clock (stamps, injected times, latencies): a host whose clock is
    /// off, for the demo lab.
    qint64 clockOffsetNs = 0;
    /// Announce the type with every message, as mqtt_client does (and pay for it: see
    /// docs/formats.md); by default once per type and connection (it is retained).
    bool announceEveryMessage = false;
    /// The bridge's memory bound for messages on their way, in bytes (see each bridge).
    qint64 maxQueuedBytes = kDefaultMaxQueuedBytes;
};

/// What a reference bridge counted, whichever ROS it runs on (updated from any thread).
struct BridgeCounters
{
    std::atomic<quint64> toMqtt {0};
    std::atomic<quint64> toRos {0};
    /// Could not be sent or published: the broker away, a payload that does not read as its
    /// mapping's, a type not announced yet or refused, a ROS side that refused the message.
    std::atomic<quint64> failed {0};
    std::atomic<quint64> tooLarge {0}; ///< of those, refused unread: too large to convert (json mappings)
    // At the memory bound (updated by the bridge's counters()):
    std::atomic<quint64> droppedToMqtt {0}; ///< the oldest waiting for the broker
    std::atomic<quint64> droppedToRos {0}; ///< not handed to the ROS side, which held its half
    std::atomic<quint64> failedWaiting {0}; ///< waited for the broker, then could not be sent
    std::atomic<qint64> heldBytes {0}; ///< now: waiting for the broker, held by Paho and the ROS side

    /// Every counter by name ("to_mqtt=3 to_ros=5 ..."; not the heldBytes gauge), for the
    /// line `bridge --verbose` ends with.
    QString text() const;
};

/// A message as its ROS serializes it (ROS 1: ROS serialization; ROS 2: CDR), and its type.
struct BridgeMessage
{
    RosMsgTypeInfo type; ///< name; ROS 1 also md5 and definition
    QByteArray bytes;
};

/// The ROS side of a reference bridge, as BridgeHop uses it: its graph (publishers made and
/// used) and how its ROS writes what a hop adds (stamps, latencies, primitives, JSON). Called from
/// the threads the bridge forwards on.
class BridgeRosSide
{
public:
    enum class Sent { Ok, Full, Failed };

    virtual ~BridgeRosSide() = default;
    virtual RosTypeRegistry::Dialect dialect() const = 0;

    // The graph. Publisher ids are the side's own; -1 is none.
    /// A publisher of the mapping's ROS topic with `type` (the mapping's queue, latch or QoS);
    /// An error when the side refuses it.
    virtual Result<int> advertise(const BridgeRoute& route, const RosMsgTypeInfo& type) = 0;
    /// Stops publishing with `publisher` (its topic can be advertised anew with another type).
    virtual void retire(int publisher) = 0;
    /// A publisher of the suite's TimeStamped on `topic` (`<timestamp_topic_prefix>/in`, `/out`).
    virtual int advertiseStamps(const QString& topic) = 0;
    /// A publisher of std_msgs Float64 on mqtt_client's `~/latencies/<rosTopic>`.
    virtual int advertiseLatency(const QString& rosTopic) = 0;
    /// The line logged when a mapping's first publisher is made ("MQTT a -> ROS /a (type, ...)").
    virtual QString publisherLine(const BridgeRoute& route, const RosMsgTypeInfo& type) const = 0;
    /// A mapping's message, within the side's memory bound: Full (not published) beyond it.
    virtual Sent send(int publisher, const QByteArray& bytes) = 0;
    /// A stamp or a latency.
    virtual void publish(int publisher, const QByteArray& bytes) = 0;

    // The wire.
    /// Whether messages of `type` start with a std_msgs Header.
    virtual bool startsWithHeader(const RosMsgTypeInfo& type) = 0;
    /// The Header a message starts with (its stamp as sampleNs); nullopt when it does not read.
    virtual std::optional<StampCodec::Decoded> header(const QByteArray& bytes) = 0;
    virtual QByteArray timeStamped(const StampCodec::Decoded& stamp) = 0;
    virtual QByteArray float64(double value) = 0;
    /// A std_msgs primitive as mqtt_client's `primitive` mappings send it; nullopt for other types.
    virtual std::optional<QByteArray> toText(const BridgeMessage& message) = 0;
    /// Text from the broker as the mapping's primitive (its fixed type, else what the text reads as).
    virtual std::optional<BridgeMessage> fromText(const BridgeRoute& route, const QByteArray& text) = 0;
    /// json mappings (ROS 2 only): the message as a JSON object, and the other way.
    virtual Result<QByteArray> toJson(const BridgeMessage&) { return LocatedError {notJson()}; }
    virtual Result<QByteArray> fromJson(const QString& /*type*/, const QByteArray& /*json*/)
    {
        return LocatedError {notJson()};
    }

private:
    static QString notJson() { return QStringLiteral("json mappings are ROS 2 only"); }
};

/// One mapping of a reference bridge, one direction, as mqtt_client forwards it on either ROS:
/// what is counted, sampled and stamped (timestamp_topic_prefix), announced, advertised, logged
/// and the latency of stamped messages. The bridge subscribes on its side and hands each message
/// over (fromRos(), fromMqtt(), announce()); everything else goes through its BridgeRosSide and
/// the MqttLink. ros2mqtt calls come from one thread at a time, mqtt2ros calls from one thread at
/// a time; reconnected() from any.
class BridgeHop
{
public:
    using Log = std::function<void(const QString& line)>;
    /// A mapping's announced type may change this often a minute (each change is a new publisher
    /// of the topic: with ROS 2 a DDS topic and writer in the DDS process); a change beyond is
    /// refused, said once a minute, and the messages of the new type are counted as failed (issue
    /// 41: a client flipping the announced type with every message kept the DDS process from its
    /// heartbeats until it was killed).
    static constexpr int kMaxTypeChangesPerMinute = 10;
    /// Anyone on the broker can flip a topic's type with every message: the first changes are
    /// logged, the rest only counted.
    static constexpr quint64 kLoggedChanges = 5;

    BridgeHop(const BridgeRoute& route, const BridgeOptions& options, BridgeCounters& counters, Log log);

    const BridgeRoute& route() const { return m_route; }
    /// Advertises the stamp topics and, for a fixed type towards ROS, the mapping's topic (as
    /// mqtt_client v2.5's setupPublishers() does, before any message).
    void start(BridgeRosSide& ros, MqttLink& mqtt);

    /// ros2mqtt: a message from ROS, taken at `receivedNs` (this host's wall clock).
    void fromRos(const BridgeMessage& message, qint64 receivedNs);
    /// ros2mqtt: the broker connection is new; the type is announced again with the next message.
    void reconnected() { m_typeSent = false; }

    /// mqtt2ros: a type announcement (`mqtt_client/ros_msg_type/<topic>`).
    void announce(const QByteArray& payload);
    /// mqtt2ros: a message from the broker, taken at `receivedNs`.
    void fromMqtt(const QByteArray& payload, qint64 receivedNs);
    /// mqtt2ros: the ROS side refused the publisher it had made (it died making it): said once
    /// per type, not asked again; the next type announced is.
    void refused(const QString& why);

    /// json mappings: refuses a payload of `bytes` that is too large to convert; true when it is
    /// (counted, the first one logged).
    bool tooLargeForJson(const QString& from, qsizetype bytes);

private:
    StampCodec::Decoded sampleOf(const BridgeMessage& m);
    void publishStamp(int publisher, const StampCodec::Decoded& sample, qint64 timeNs);
    qint64 now() const;
    bool sendToMqtt(const BridgeMessage& m, qint64* outNs);
    std::optional<BridgeMessage> readMqtt(const QByteArray& payload, std::optional<qint64>* sentNs);
    bool advertise(const RosMsgTypeInfo& type);
    bool typeChangeAllowed();
    void refuse(const QString& type, const QString& why);
    void publishLatency(qint64 receivedNs, qint64 sentNs);

    BridgeRoute m_route;
    const BridgeOptions& m_options;
    BridgeCounters& m_counters;
    Log m_log;
    BridgeRosSide* m_ros = nullptr;
    MqttLink* m_mqtt = nullptr;
    int m_stampIn = -1;
    int m_stampOut = -1;
    // The Header check of the last type seen (the calling thread's).
    QString m_headerType;
    QString m_headerMd5;
    bool m_headerFirst = false;
    // ros2mqtt
    std::atomic<bool> m_typeSent {false}; ///< announced on this connection
    RosMsgTypeInfo m_sentType; ///< the type announced
    // mqtt2ros (under m_mutex: the type announced, the publisher of the type advertised)
    std::mutex m_mutex;
    std::optional<RosMsgTypeInfo> m_announced;
    bool m_dialectSaid = false; ///< an announcement for the other ROS was logged
    RosMsgTypeInfo m_advertised; ///< the publisher's type (name empty: none)
    int m_publisher = -1;
    QString m_refusedType; ///< a type whose publisher was refused: not asked again
    quint64 m_typeChanges = 0;
    qint64 m_changeWindowNs = 0; ///< when the current minute of type changes began
    int m_changesInWindow = 0;
    int m_latencyPublisher = -1;
};
