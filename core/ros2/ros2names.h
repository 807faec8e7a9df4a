// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

/// ROS 2 names as DDS carries them (REP 2008 and the rmw implementations): the topic `/foo` is
/// the DDS topic `rt/foo` (services `rq/fooRequest` and `rr/fooReply`), the type `pkg/msg/Type`
/// is `pkg::msg::dds_::Type_`. Pure string work; no DDS here.
namespace Ros2Names {

enum class TopicKind { Topic, ServiceRequest, ServiceReply, Other };

/// What a DDS topic name stands for. `rosName` gets the ROS 2 name (`/foo`) for topics and
/// services (without the Request/Reply suffix), the DDS name itself for others.
TopicKind classifyDdsTopic(const QString& ddsTopic, QString* rosName = nullptr);
/// `rt/foo` for `/foo` (a name without a leading slash is taken as if it had one).
QString ddsTopic(const QString& rosTopic);
/// `pkg/msg/Type` for `pkg::msg::dds_::Type_` (and `pkg::srv::dds_::Type_Request_`); a name not in
/// that form comes back unchanged.
QString rosType(const QString& ddsType);
/// `pkg::msg::dds_::Type_` for `pkg/msg/Type` or `pkg/Type`; an empty string for a name that is
/// not `pkg/[msg/]Type`.
QString ddsType(const QString& rosType);

} // namespace Ros2Names
