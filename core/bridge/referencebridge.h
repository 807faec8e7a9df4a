// SPDX-License-Identifier: MIT
#pragma once

#include "config/bridgeconfig.h"
#include "mqtt/mqttprofile.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <vector>

struct RosRawMessage;

/// std_msgs primitives as text, the way mqtt_client sends `primitive: true` mappings.
namespace PrimitiveText {
/// The text of a std_msgs primitive message (String, Bool, Int*/UInt*, Float32/64, Char, Byte);
/// nullopt for other types.
std::optional<QByteArray> toText(const QString& type, const QByteArray& bytes);
/// A std_msgs message for received text: Bool for "true"/"false", Int32 for an integer that
/// fits, Float64 for another number, else String.
RosRawMessage fromText(const QByteArray& text);
} // namespace PrimitiveText

/// The reference bridge: runs an mqtt_client config (ROS 1 layout; ROS 2 and mqtt_bridge
/// layouts are converted) between one ROS master and one broker, speaking mqtt_client v2.2.1's
/// wire protocol byte for byte (see docs/formats.md), plus the benchmarking suite's
/// `timestamp_topic_prefix`: TimeStamped on `<prefix>/in` when a message enters the bridge and
/// `<prefix>/out` when it has left.
///
/// Messages are forwarded on the receiving library's thread, without queueing in between, while
/// the libraries take them. Memory is bounded (Options::maxQueuedBytes): towards the broker, what
/// Paho holds and what waits for it take half the bound, the oldest waiting dropped beyond it;
/// towards ROS, what roscpp holds (its queues towards slow subscribers) takes the other half, and
/// a message that would go beyond is dropped. Both are counted.
class ReferenceBridge
{
    Q_DECLARE_TR_FUNCTIONS(ReferenceBridge)
public:
    using Log = std::function<void(const QString& line)>;
    static constexpr qint64 kDefaultMaxQueuedBytes = 64 * 1024 * 1024;

    struct Options
    {
        QString brokerUrl; ///< overrides the config's broker (host, port, TLS) when set
        QString rosMaster; ///< empty: ROS_MASTER_URI
        QString nodeName; ///< empty: "mqtt_client"
        QHash<QString, QString> args; ///< values for `$(arg NAME)` in the config
        /// Added to this bridge's clock (stamps, injected times, latencies): a host whose clock
        /// is off, for the demo lab.
        qint64 clockOffsetNs = 0;
        /// Announce the type with every message, as mqtt_client v2.2.1 does (and pay for it: see
        /// docs/formats.md); by default once per type and connection (it is retained).
        bool announceEveryMessage = false;
        /// The bridge's memory bound for messages on their way (see the class), in bytes.
        qint64 maxQueuedBytes = kDefaultMaxQueuedBytes;
    };

    struct Counters
    {
        std::atomic<quint64> toMqtt {0};
        std::atomic<quint64> toRos {0};
        std::atomic<quint64> failed {0}; ///< could not be sent (broker away, bad payload)
        std::atomic<quint64> tooLarge {0}; ///< of those, refused unread: too large to convert (json mappings)
        // At the memory bound (updated by counters()):
        std::atomic<quint64> droppedToMqtt {0}; ///< the oldest waiting for the broker
        std::atomic<quint64> droppedToRos {0}; ///< not handed to roscpp, which held its half
        std::atomic<quint64> failedWaiting {0}; ///< waited for the broker, then could not be sent
        std::atomic<qint64> heldBytes {0}; ///< now: waiting for the broker, held by Paho and roscpp

        /// Every counter by name ("to_mqtt=3 to_ros=5 ..."; not the heldBytes gauge), for the
        /// line `bridge --verbose` ends with.
        QString text() const;
    };

    explicit ReferenceBridge(Log log);
    ~ReferenceBridge();

    /// Reads the config (any layout). Errors: not a bridge config, no mapping, bad values.
    bool load(const QByteArray& yaml, const Options& options, QString* error);
    /// Connects to broker and master (waiting for the master while `keepWaiting`) and bridges.
    bool start(const std::function<bool()>& keepWaiting, QString* error);
    void stop();

    const Counters& counters() const;
    /// The broker profile in use (from the config, or --broker).
    const MqttProfile& profile() const;
    int mappingCount() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};
