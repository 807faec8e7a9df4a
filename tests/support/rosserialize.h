// SPDX-License-Identifier: MIT
#pragma once

// For tests that link roscpp: a message as roscpp itself serializes it.
#include <QByteArray>
#include <ros/serialization.h>

template<typename M> QByteArray rosSerialize(const M& msg)
{
    const uint32_t n = ros::serialization::serializationLength(msg);
    QByteArray out(qsizetype(n), Qt::Uninitialized);
    ros::serialization::OStream stream(reinterpret_cast<uint8_t*>(out.data()), n);
    ros::serialization::serialize(stream, msg);
    return out;
}
