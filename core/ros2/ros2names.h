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

/// The longest topic name (after the DDS prefix `rt/`) and type name a ROS 2 endpoint of ours may
/// have: rcl's RMW_TOPIC_MAX_NAME_LENGTH. A name beyond it never reaches DDS (issue 41: Cyclone
/// crashed on a 70,000-character type, past RTPS's 16-bit parameter length).
constexpr int kMaxNameChars = 255;
/// Whether an endpoint of ours may be made of `type`: `pkg/msg/Type` (or `pkg/Type`), each part
/// ASCII letters, digits and underscores, starting with a letter, at most kMaxNameChars in all;
/// `why` says what is wrong, quoting at most 60 characters of it.
bool isValidType(const QString& type, QString* why = nullptr);
/// Whether an endpoint of ours may be made on `topic`: a valid ROS 2 name of at most
/// kMaxNameChars characters as DDS carries it.
bool isValidTopic(const QString& topic, QString* why = nullptr);

} // namespace Ros2Names
