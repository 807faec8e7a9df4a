// SPDX-License-Identifier: MIT
#pragma once

#include "wire/contentkey.h"
#include "wire/mqttclientwire.h"
#include "wire/primitivetext.h"
#include "wire/rosmessage.h"
#include "wire/stampcodec.h"

#include <optional>
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

/// Which graph a message came from, and so how its bytes are serialized: ROS 1 (ROS
/// serialization), ROS 2 (CDR after an encapsulation header), MQTT (a payload: mqtt_client's wire
/// when a type was announced for it, else whatever the device sent).
enum class SourceGraph { Ros1, Ros2, Mqtt };

/// One message as a source hands it over: which graph and topic, its ROS type (empty on MQTT
/// without an announcement), when Bridgescope got it (wall clock) and its bytes.
struct SourceArrival
{
    SourceGraph graph = SourceGraph::Mqtt;
    QString topic;
    QString type;
    qint64 receivedNs = 0;
    QByteArray bytes;
};

/// The first bytes of one message, for consumers that need every message but not all of it (Watch):
/// enough for a ROS 1 Header's seq and stamp or a std_msgs Float64. On ROS 2 they are the message's
/// first bytes after its 4-byte encapsulation header (a ROS 2 Header has no seq).
struct SourceHead
{
    static constexpr int kHeadBytes = 16;
    SourceGraph graph = SourceGraph::Ros1;
    QString topic;
    qint64 receivedNs = 0; ///< wall clock
    int size = 0; ///< serialized bytes (on ROS 2 the encapsulation header included)
    QByteArray head; ///< the first kHeadBytes bytes (fewer when the message is shorter)
    /// The whole message's content, for matching a bridge's two ends without stamps (issue 45):
    /// ROS 1 its serialization, ROS 2 its CDR with the encapsulation header, MQTT its payload after
    /// `keySkipped` bytes (the injected stamp of a topic announced as stamped). None when the source
    /// computed none.
    std::optional<ContentKey> key;
    qint8 keySkipped = 0;
    /// On ROS, for a std_msgs primitive: the key of the text mqtt_client's `primitive` sends for it
    /// (PrimitiveText), so that a primitive link's ends match too. On MQTT, for a payload of at most
    /// PrimitiveText::kMaxRoundTripBytes: the key of the text its primitive ROS message has, when
    /// that is not the payload (else `key` is it).
    std::optional<ContentKey> textKey = std::nullopt;
    /// On MQTT, for a topic a `json` link reads (MqttSource::setJsonTypes()): the key of the ROS 2
    /// message (CDR, its encapsulation header included) the payload converts to as the link's type,
    /// the way mqtt_client v2.5 converts it; none when it does not convert.
    std::optional<ContentKey> jsonKey = std::nullopt;

    /// The head of a whole ROS message (`graph` Ros1 or Ros2) of `type`, as the ROS sources make it.
    static SourceHead ofRos(SourceGraph graph, const QString& topic, QStringView type, qint64 receivedNs,
                            const QByteArray& bytes);
};

/// What one arrival on a stamp topic or a latency topic gives: a stamp, a latency, or why neither.
struct StampReading
{
    std::optional<StampEvent> stamp;
    std::optional<LatencyValue> latency;
    QString error; ///< set when neither
};

/// How the messages of one topic decode: its graph and ROS type, and on MQTT the type mqtt_client
/// announced (its dialect and whether payloads carry a stamp).
struct SourceType
{
    SourceGraph graph = SourceGraph::Mqtt;
    QString type;
    std::optional<RosMsgTypeInfo> announced;
    /// A ROS type is known to decode with (ROS 1 and 2 always, MQTT with an announcement).
    bool isRos() const { return graph != SourceGraph::Mqtt || announced.has_value(); }
};

/// The one place that picks a decoder for a (graph, type): the field plots, the Discover page's
/// detail pane, the MQTT topic tree's check of announced payloads and the stamp sources all decode
/// through it.
class SourceMessage
{
    Q_DECLARE_TR_FUNCTIONS(SourceMessage)
public:
    /// The message as a value: ROS 1 with RosMessageDecoder::decode(), ROS 2 with decodeCdr(), an
    /// announced MQTT payload with MqttClientWire::decodePayload() (after its stamp, in its dialect).
    /// Not for MQTT payloads without an announcement (an error saying so): those are
    /// JSON or opaque, the caller's to show.
    static Result<RosValue> decode(const RosTypeRegistry& registry, const SourceType& type,
                                   const QByteArray& bytes, const RosDecodeLimits& limits = {});
    /// A `benchmarking_suite/TimeStamped` of the graph's form (ROS 1 serialized, ROS 2 CDR).
    static Result<StampCodec::Decoded> decodeStamp(SourceGraph graph, const QByteArray& bytes);
    /// A std_msgs Float64 latency in seconds, as ns, of the graph's form.
    static std::optional<qint64> decodeLatency(SourceGraph graph, const QByteArray& bytes);
    /// An arrival of a stamp topic (`latency` false: a TimeStamped named by its topic) or of a
    /// latency topic (a Float64, a series named by its topic), decoded as its graph serializes.
    /// The caller has checked the type.
    static StampReading readStamp(const SourceArrival& arrival, bool latency);
    /// The stamp type's name in the graph ("benchmarking_suite/TimeStamped" on ROS 1,
    /// "benchmarking_suite/msg/TimeStamped" on ROS 2).
    static QString stampType(SourceGraph graph);
};
