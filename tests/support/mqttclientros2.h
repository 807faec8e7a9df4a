// SPDX-License-Identifier: MIT
#pragma once

// For tests that link fastcdr: what mqtt_client for ROS 2 (ika-rwth-aachen/mqtt_client v2.0 to
// v2.5) puts on the broker, made with eProsima Fast CDR the way its RMW does.
//
// mqtt_client serializes with rclcpp::Serialization, which is rmw_serialize(). rmw_fastrtps_cpp
// (Humble, rmw_serialize.cpp) makes a Fast CDR `Cdr(buffer, DEFAULT_ENDIAN, DDS_CDR)`, writes the
// encapsulation (TypeSupport::serializeROSmessage: `ser.serialize_encapsulation()`) and then each
// member in order as rosidl_typesupport_fastrtps_cpp generates it (`cdr << ros_message.name` for a
// string, `cdr << (ros_message.stamped ? true : false)` for a bool); the length it reports is 4 +
// the members' size, so nothing is padded after the last member. rmw_cyclonedds_cpp writes the
// same bytes (header 00 01 00 00 on a little-endian host, strings as length + 1, bytes, NUL).
//
// - the type announcement (retained on mqtt_client/ros_msg_type/<topic>):
//   mqtt_client_interfaces/msg/RosMsgType {string md5, string name, string definition,
//   bool stamped}; ros2mqtt() fills name and stamped only (MqttClient.cpp at 517fa53, lines 1016-1018).
// - a stamped payload: builtin_interfaces/msg/Time serialized on its own (header, int32 sec,
//   uint32 nanosec: mqtt_client's stamp_length_, 12 bytes), then the message serialized on its own.
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <QByteArray>
#include <string>
#include <vector>

namespace MqttClientRos2 {

using eprosima::fastcdr::Cdr;

/// Serializes with Fast CDR as rmw_fastrtps does: the encapsulation, then `write`. Fast CDR
/// skips alignment padding without writing it, so padding holds what the buffer held before
/// (rmw_serialize's buffer is not cleared either): `fill` here, zero unless a test says otherwise.
template<typename Write>
QByteArray serialize(Write write, Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS, char fill = 0)
{
    std::vector<char> buffer(4 << 20, fill);
    eprosima::fastcdr::FastBuffer fb(buffer.data(), buffer.size());
    Cdr cdr(fb, endianness, Cdr::DDS_CDR);
    cdr.serialize_encapsulation();
    write(cdr);
    return QByteArray(buffer.data(), qsizetype(cdr.getSerializedDataLength()));
}

/// mqtt_client_interfaces/msg/RosMsgType, member by member.
inline QByteArray announcement(const std::string& name, bool stamped,
                               Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS,
                               const std::string& md5 = {}, const std::string& definition = {}, char fill = 0)
{
    return serialize([&](Cdr& cdr) { cdr << md5 << name << definition << (stamped ? true : false); },
                     endianness, fill);
}

/// builtin_interfaces/msg/Time, as mqtt_client serializes its send stamp.
inline QByteArray stamp(int32_t sec, uint32_t nanosec, Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS)
{
    return serialize([&](Cdr& cdr) { cdr << sec << nanosec; }, endianness);
}

/// std_msgs/msg/String.
inline QByteArray string(const std::string& data, Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS)
{
    return serialize([&](Cdr& cdr) { cdr << data; }, endianness);
}

/// The payload of a stamped mapping: [stamp, message], nothing between.
inline QByteArray stamped(int32_t sec, uint32_t nanosec, const QByteArray& message,
                          Cdr::Endianness endianness = Cdr::LITTLE_ENDIANNESS)
{
    return stamp(sec, nanosec, endianness).append(message);
}

} // namespace MqttClientRos2
