// SPDX-License-Identifier: MIT
#pragma once

// ROS messages as bytes, for the code in core/ros (and ROS test nodes): roscpp's types meet
// QByteArray here and nowhere else.
#include <QByteArray>
#include <ros/serialization.h>
#include <topic_tools/shape_shifter.h>

namespace RosBytes {
/// A message serialized as ROS sends it.
template<typename M> QByteArray of(const M& message)
{
    QByteArray bytes(qsizetype(ros::serialization::serializationLength(message)), Qt::Uninitialized);
    ros::serialization::OStream out(reinterpret_cast<uint8_t*>(bytes.data()), uint32_t(bytes.size()));
    ros::serialization::serialize(out, message);
    return bytes;
}

/// A message of a compiled type back from its bytes.
template<typename M> M read(const QByteArray& bytes)
{
    M message;
    ros::serialization::IStream in(reinterpret_cast<uint8_t*>(const_cast<char*>(bytes.constData())),
                                   uint32_t(bytes.size()));
    ros::serialization::deserialize(in, message);
    return message;
}

/// What a generic subscription received, as bytes.
inline QByteArray of(const topic_tools::ShapeShifter& message)
{
    QByteArray bytes(qsizetype(message.size()), Qt::Uninitialized);
    ros::serialization::OStream out(reinterpret_cast<uint8_t*>(bytes.data()), uint32_t(bytes.size()));
    message.write(out);
    return bytes;
}

/// A message of a type known by name, md5 and definition only, ready to publish.
inline topic_tools::ShapeShifter shaped(const std::string& md5, const std::string& type,
                                        const std::string& definition, const QByteArray& bytes)
{
    topic_tools::ShapeShifter s;
    s.morph(md5, type, definition, "");
    // ShapeShifter::read copies from the stream; IStream wants a mutable pointer it never writes.
    ros::serialization::IStream in(reinterpret_cast<uint8_t*>(const_cast<char*>(bytes.constData())),
                                   uint32_t(bytes.size()));
    s.read(in);
    return s;
}
} // namespace RosBytes
