// SPDX-License-Identifier: MIT
#pragma once

#include "base/result.h"
#include "bridge/bridgehop.h"
#include "mqtt/mqttprofile.h"

#include <memory>
#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

struct RosRawMessage;

/// std_msgs primitives as text, the way mqtt_client (up to 2.3, the last for ROS 1) sends
/// `primitive: true` mappings (wire/primitivetext.h has the rest of the namespace).
namespace PrimitiveText {
/// The text of a std_msgs primitive message (String, Bool, Int*/UInt*, Float32/64, Char);
/// nullopt for other types (ofRos1()).
std::optional<QByteArray> toText(const QString& type, const QByteArray& bytes);
/// The std_msgs message mqtt2primitive() makes of received text (parse()): Bool for "true" or
/// "false" in any case, Int32 for a whole integer that fits, Float32 for another whole number,
/// else String.
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
///
/// Each mapping is forwarded by a BridgeHop, as in Ros2Bridge; this class gives it its roscpp
/// side (RosEndpoint) and the broker.
class ReferenceBridge
{
    Q_DECLARE_TR_FUNCTIONS(ReferenceBridge)
public:
    using Log = BridgeHop::Log;
    using Options = BridgeOptions;
    using Counters = BridgeCounters;
    static constexpr qint64 kDefaultMaxQueuedBytes = BridgeOptions::kDefaultMaxQueuedBytes;

    explicit ReferenceBridge(Log log);
    ~ReferenceBridge();

    /// Reads the config (any layout). Errors: not a bridge config, no mapping, bad values.
    Status load(const QByteArray& yaml, const Options& options);
    /// Connects to broker and master (waiting for the master while `keepWaiting`) and bridges.
    Status start(const std::function<bool()>& keepWaiting);
    void stop();

    const Counters& counters() const;
    /// The broker profile in use (from the config, or --broker).
    const MqttProfile& profile() const;
    int mappingCount() const;

private:
    struct Private;
    std::unique_ptr<Private> d;
};
