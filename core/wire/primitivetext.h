// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <QByteArray>
#include <QByteArrayView>
#include <QStringView>

/// What mqtt_client sends for a `primitive` mapping (issue 45): a std_msgs primitive's value as
/// text, the way its primitiveRosMessageToString() writes it (ROS 1 up to 2.3 and ROS 2 alike):
/// String its data, Bool "true" or "false", integers in decimal, Float32 and Float64 as
/// std::to_string ("%f"), UInt8MultiArray (ROS 2, 2.4.2) its data bytes. With it, a primitive
/// link's two ends have one ContentKey: the ROS message's text and the MQTT payload.
namespace PrimitiveText {

/// std::to_string of a float or double: printf's "%f" (rounded to even, as Qt's 'f' is not), in
/// the C locale.
QByteArray fixed(double v);

/// The text of a ROS 1 message (its serialization) of a std_msgs primitive `type`
/// ("std_msgs/Int32"); nullopt for another type or bytes that are not one such message.
std::optional<QByteArray> ofRos1(QStringView type, QByteArrayView bytes);
/// The same of a ROS 2 message (CDR with its encapsulation header), `type` "std_msgs/msg/Int32".
std::optional<QByteArray> ofCdr(QStringView type, QByteArrayView cdr);
/// What mqtt_client's mqtt2primitive() makes of a payload (ROS 1 and ROS 2 alike): "true" or
/// "false" in any case a Bool, a text std::stoi reads whole an Int32, one std::stof reads whole a
/// Float32 (both skip leading white space, neither trailing), else a String.
struct Parsed
{
    enum class Kind { Bool, Int32, Float32, String } kind = Kind::String;
    bool boolean = false;
    qint32 integer = 0;
    float real = 0;
};
Parsed parse(QByteArrayView payload);

/// The text the primitive message mqtt_client makes of a payload has on the ROS side (parse(),
/// written as ofRos1() writes it).
/// Payloads longer than kMaxRoundTripBytes are texts, not numbers: their key is the payload's.
QByteArray roundTrip(QByteArrayView payload);
/// roundTrip() when it is not the payload itself (nullopt for most payloads: texts, binary data).
std::optional<QByteArray> roundTripChanged(QByteArrayView payload);
inline constexpr qsizetype kMaxRoundTripBytes = 64;

} // namespace PrimitiveText
