// SPDX-License-Identifier: MIT
#include "optionschema.h"

#include <QCoreApplication>

using namespace Qt::StringLiterals;

namespace {

OptionSpec opt(QString path, OptionKind kind, QString def, const char* summary)
{
    OptionSpec s;
    s.path = std::move(path);
    s.kind = kind;
    s.defaultText = std::move(def);
    s.summary = summary;
    return s;
}

OptionSpec intOpt(QString path, QString def, int min, int max, const char* summary)
{
    OptionSpec s = opt(std::move(path), OptionKind::Int, std::move(def), summary);
    s.minimum = min;
    s.maximum = max;
    return s;
}

OptionSpec enumOpt(QString path, QStringList values, const char* summary)
{
    OptionSpec s = opt(std::move(path), OptionKind::Enum, QString(), summary);
    s.enumValues = std::move(values);
    s.ros2Only = true;
    return s;
}

OptionSpec ros2(OptionSpec s)
{
    s.ros2Only = true;
    return s;
}

/// An option mqtt_client reads from `release` on.
OptionSpec since(MqttClientRelease release, OptionSpec s)
{
    s.since = release;
    return s;
}

OptionSpec secret(OptionSpec s)
{
    s.secret = true;
    return s;
}

OptionSpec extension(OptionSpec s)
{
    s.extension = true;
    return s;
}

QList<OptionSpec> brokerOptions()
{
    return {
        opt(u"host"_s, OptionKind::String, u"localhost"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "IP address or hostname of the MQTT broker")),
        intOpt(u"port"_s, u"1883"_s, 1, 65535,
               QT_TRANSLATE_NOOP("OptionSchema", "port the broker listens on")),
        opt(u"user"_s, OptionKind::String, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "user name for the broker (anonymous if empty)")),
        secret(opt(u"pass"_s, OptionKind::String, QString(),
                   QT_TRANSLATE_NOOP("OptionSchema", "password for the broker"))),
        opt(u"tls.enabled"_s, OptionKind::Bool, u"false"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "connect with SSL/TLS")),
        opt(u"tls.ca_certificate"_s, OptionKind::Path, u"/etc/ssl/certs/ca-certificates.crt"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "CA certificate the client trusts (relative to ROS_HOME)")),
    };
}

QList<OptionSpec> clientOptions()
{
    return {
        opt(u"id"_s, OptionKind::String, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "unique client ID (the broker may generate one if empty)")),
        intOpt(u"buffer.size"_s, u"0"_s, 0, 0,
               QT_TRANSLATE_NOOP("OptionSchema", "messages buffered while disconnected (needs a client ID)")),
        opt(u"buffer.directory"_s, OptionKind::Path, u"buffer"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "directory for buffered messages (relative to ROS_HOME)")),
        opt(u"buffer.enabled"_s, OptionKind::Bool, u"false"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "buffer messages while disconnected")),
        opt(u"last_will.topic"_s, OptionKind::String, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "topic of the last-will message (none if empty)")),
        opt(u"last_will.message"_s, OptionKind::String, u"offline"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "last-will message")),
        intOpt(u"last_will.qos"_s, u"0"_s, 0, 2,
               QT_TRANSLATE_NOOP("OptionSchema", "QoS of the last-will message")),
        opt(u"last_will.retained"_s, OptionKind::Bool, u"false"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "retain the last-will message")),
        opt(u"clean_session"_s, OptionKind::Bool, u"true"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "start a clean session on every connect")),
        opt(u"keep_alive_interval"_s, OptionKind::Double, u"60.0"_s,
            QT_TRANSLATE_NOOP("OptionSchema", "keep-alive interval in seconds")),
        intOpt(u"max_inflight"_s, u"65535"_s, 1, 65535,
               QT_TRANSLATE_NOOP("OptionSchema", "maximum number of messages in flight")),
        opt(u"tls.certificate"_s, OptionKind::Path, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "client certificate (relative to ROS_HOME)")),
        opt(u"tls.key"_s, OptionKind::Path, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "client private key (relative to ROS_HOME)")),
        secret(opt(u"tls.password"_s, OptionKind::String, QString(),
                   QT_TRANSLATE_NOOP("OptionSchema", "password of the client private key"))),
        opt(u"tls.version"_s, OptionKind::Int, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "TLS version as Paho's ssl_options value (3 = TLS 1.2)")),
        opt(u"tls.verify"_s, OptionKind::Bool, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "verify the broker's certificate")),
        opt(u"tls.alpn_protos"_s, OptionKind::StringList, QString(),
            QT_TRANSLATE_NOOP("OptionSchema", "ALPN protocols to negotiate (e.g. x-amzn-mqtt-ca)")),
        since(MqttClientRelease::V2_4_1,
              ros2(opt(
                  u"tls.server_cert_auth"_s, OptionKind::Bool, u"true"_s,
                  QT_TRANSLATE_NOOP("OptionSchema", "verify the broker's certificate (mqtt_client 2.4.1)")))),
    };
}

const QStringList kReliability = {u"auto"_s, u"system_default"_s, u"reliable"_s, u"best_effort"_s};
const QStringList kDurability = {u"auto"_s, u"system_default"_s, u"volatile"_s, u"transient_local"_s};

QList<OptionSpec> mappingOptions(OptionScope scope)
{
    const bool out = scope == OptionScope::Ros2Mqtt;
    QList<OptionSpec> list;
    const OptionSpec rosTopic = opt(u"ros_topic"_s, OptionKind::String, QString(),
                                    out ? QT_TRANSLATE_NOOP("OptionSchema", "ROS topic to subscribe to")
                                        : QT_TRANSLATE_NOOP("OptionSchema", "ROS topic to publish on"));
    const OptionSpec mqttTopic = opt(u"mqtt_topic"_s, OptionKind::String, QString(),
                                     out ? QT_TRANSLATE_NOOP("OptionSchema", "MQTT topic to publish on")
                                         : QT_TRANSLATE_NOOP("OptionSchema", "MQTT topic to subscribe to"));
    if (out)
        list << rosTopic << mqttTopic;
    else
        list << mqttTopic << rosTopic;
    list << opt(u"primitive"_s, OptionKind::Bool, u"false"_s,
                QT_TRANSLATE_NOOP("OptionSchema", "send std_msgs primitives as plain text"))
         << since(MqttClientRelease::V2_5,
                  ros2(opt(u"json"_s, OptionKind::Bool, u"false"_s,
                           QT_TRANSLATE_NOOP("OptionSchema", "send messages as JSON (needs ros_type)"))))
         << since(MqttClientRelease::V2_3,
                  ros2(opt(
                      u"ros_type"_s, OptionKind::String, QString(),
                      QT_TRANSLATE_NOOP("OptionSchema", "fixed ROS message type, e.g. std_msgs/msg/Bool"))));
    if (out)
        list << opt(u"inject_timestamp"_s, OptionKind::Bool, u"false"_s,
                    QT_TRANSLATE_NOOP("OptionSchema", "prepend a send time stamp for latency measurement"));
    list << intOpt(u"advanced.ros.queue_size"_s, u"1"_s, 0, 0,
                   out ? QT_TRANSLATE_NOOP("OptionSchema", "ROS subscriber queue size")
                       : QT_TRANSLATE_NOOP("OptionSchema", "ROS publisher queue size"));
    if (!out)
        list << opt(u"advanced.ros.latched"_s, OptionKind::Bool, u"false"_s,
                    QT_TRANSLATE_NOOP("OptionSchema", "latch the ROS publisher"));
    // "auto" (the QoS of the publishers the bridge discovers) is ros2mqtt's default; mqtt2ros has
    // no publishers to follow: mqtt_client 2.3-2.5 exits on it ("Unexpected reliability auto").
    const auto qos = [out](const QString& path, QStringList values, const char* summary) {
        if (!out)
            values.removeAll(u"auto"_s);
        OptionSpec spec = since(MqttClientRelease::V2_3, enumOpt(path, std::move(values), summary));
        spec.defaultText = out ? u"auto"_s : u"system_default"_s;
        return spec;
    };
    list << qos(u"advanced.ros.qos.reliability"_s, kReliability,
                QT_TRANSLATE_NOOP("OptionSchema", "ROS 2 QoS reliability"))
         << qos(u"advanced.ros.qos.durability"_s, kDurability,
                QT_TRANSLATE_NOOP("OptionSchema", "ROS 2 QoS durability"))
         << intOpt(u"advanced.mqtt.qos"_s, u"0"_s, 0, 2,
                   QT_TRANSLATE_NOOP("OptionSchema", "MQTT QoS (0, 1 or 2)"));
    if (out)
        list << opt(u"advanced.mqtt.retained"_s, OptionKind::Bool, u"false"_s,
                    QT_TRANSLATE_NOOP("OptionSchema", "publish retained on MQTT"));
    list << extension(
        opt(u"timestamp_topic_prefix"_s, OptionKind::String, QString(),
            QT_TRANSLATE_NOOP("OptionSchema",
                              "benchmarking suite: publish in/out time stamps under this prefix")));
    return list;
}

} // namespace

namespace OptionSchema {

const QList<OptionSpec>& options(OptionScope scope)
{
    static const QList<OptionSpec> broker = brokerOptions();
    static const QList<OptionSpec> client = clientOptions();
    static const QList<OptionSpec> ros2mqtt = mappingOptions(OptionScope::Ros2Mqtt);
    static const QList<OptionSpec> mqtt2ros = mappingOptions(OptionScope::Mqtt2Ros);
    switch (scope) {
    case OptionScope::Broker:
        return broker;
    case OptionScope::Client:
        return client;
    case OptionScope::Ros2Mqtt:
        return ros2mqtt;
    case OptionScope::Mqtt2Ros:
        return mqtt2ros;
    }
    return broker;
}

const OptionSpec* find(OptionScope scope, const QString& path)
{
    for (const OptionSpec& spec : options(scope)) {
        if (spec.path == path)
            return &spec;
    }
    return nullptr;
}

QString summary(const OptionSpec& spec)
{
    return QCoreApplication::translate("OptionSchema", spec.summary);
}

QString scopeKey(OptionScope scope)
{
    switch (scope) {
    case OptionScope::Broker:
        return u"broker"_s;
    case OptionScope::Client:
        return u"client"_s;
    case OptionScope::Ros2Mqtt:
        return u"ros2mqtt"_s;
    case OptionScope::Mqtt2Ros:
        return u"mqtt2ros"_s;
    }
    return QString();
}

bool isSection(OptionScope scope, const QString& path)
{
    const QString prefix = path + u'.';
    for (const OptionSpec& spec : options(scope)) {
        if (spec.path.startsWith(prefix))
            return true;
    }
    return false;
}

} // namespace OptionSchema
