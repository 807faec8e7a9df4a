// SPDX-License-Identifier: MIT
// Fuzz target for the MQTT topic and ROS name rules of the validator, and MQTT filter matching.
//
// Input: a name, and after a NUL byte a second name used as a filter. Properties that follow from
// the MQTT 3.1.1 spec (4.7) and the ROS 1 graph name rules: a valid published topic is also a
// valid filter, has no wildcard and matches itself, and "#" and a "+" per level match it unless it
// starts with '$'; a ROS 2 (strict) name is a ROS 1 name; a rejected name says why.
#include "text/topicnames.h"
#include "fuzzcheck.h"

#include <QStringList>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const auto [first, second] = fuzz::splitAtNul(fuzz::bytes(data, size));
    const QString name = QString::fromUtf8(first);
    const QString filter = QString::fromUtf8(second);

    QString why;
    const bool ros1 = TopicNames::isValidRosName(name, false, &why);
    FUZZ_CHECK(ros1 || !why.isEmpty(), "a ROS name rejected without a reason");
    why.clear();
    const bool ros2 = TopicNames::isValidRosName(name, true, &why);
    FUZZ_CHECK(ros2 || !why.isEmpty(), "a ROS 2 name rejected without a reason");
    FUZZ_CHECK(!ros2 || ros1, "a valid ROS 2 name that is not a valid ROS 1 name");

    why.clear();
    const bool publish = TopicNames::isValidMqttTopic(name, true, &why);
    FUZZ_CHECK(publish || !why.isEmpty(), "a topic rejected without a reason");
    why.clear();
    const bool subscribe = TopicNames::isValidMqttTopic(name, false, &why);
    FUZZ_CHECK(subscribe || !why.isEmpty(), "a filter rejected without a reason");
    if (publish) {
        FUZZ_CHECK(subscribe, "a valid topic that is not a valid filter");
        FUZZ_CHECK(!TopicNames::hasWildcard(name), "a valid published topic with a wildcard");
        FUZZ_CHECK(TopicNames::topicMatches(name, name), "a topic that does not match itself");
        if (!name.startsWith(u'$')) {
            FUZZ_CHECK(TopicNames::topicMatches(QStringLiteral("#"), name), "'#' does not match a topic");
            QStringList plus = name.split(u'/');
            for (QString& level : plus)
                level = QStringLiteral("+");
            FUZZ_CHECK(TopicNames::topicMatches(plus.join(u'/'), name),
                       "'+' per level does not match a topic");
        }
    }
    (void)TopicNames::topicMatches(filter, name);
    (void)TopicNames::isValidMqttTopic(filter, false);
    return 0;
}
