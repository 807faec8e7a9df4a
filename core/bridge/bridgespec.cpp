// SPDX-License-Identifier: MIT
#include "bridge/bridgespec.h"

#include "config/configreader.h"

#include <functional>
#include <QCoreApplication>
#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace {
QString substituteArgs(QString text, const QHash<QString, QString>& args, QStringList* missing)
{
    static const QRegularExpression arg(u"\\$\\(arg\\s+([A-Za-z0-9_]+)\\)"_s);
    QRegularExpressionMatch m;
    qsizetype from = 0;
    while ((m = arg.match(text, from)).hasMatch()) {
        const QString name = m.captured(1);
        if (!args.contains(name)) {
            missing->append(name);
            from = m.capturedEnd();
            continue;
        }
        text.replace(m.capturedStart(), m.capturedLength(), args.value(name));
        from = m.capturedStart() + args.value(name).size();
    }
    return text;
}

/// The broker: a --broker URL wins over the config's host and port (and credentials in it over
/// the config's); the client's id, session, keep-alive and certificate.
MqttProfile brokerProfile(const BridgeConfig& c, const QString& brokerUrl,
                          const std::function<QString(OptionScope, const QString&)>& setting)
{
    MqttProfile p;
    if (!brokerUrl.isEmpty()) {
        p = MqttProfile::fromUrl(brokerUrl);
        if (p.caFile.isEmpty() && setting(OptionScope::Broker, u"tls.enabled"_s) == u"true"_s)
            p.caFile = setting(OptionScope::Broker, u"tls.ca_certificate"_s); // the config's CA still holds
    } else {
        const bool tls = setting(OptionScope::Broker, u"tls.enabled"_s) == u"true"_s;
        p = MqttProfile::fromUrl(u"%1://%2:%3"_s.arg(tls ? u"ssl"_s : u"tcp"_s,
                                                     setting(OptionScope::Broker, u"host"_s),
                                                     setting(OptionScope::Broker, u"port"_s)));
        if (tls)
            p.caFile = setting(OptionScope::Broker, u"tls.ca_certificate"_s);
    }
    if (p.username.isEmpty() && p.password.isEmpty()) {
        p.username = setting(OptionScope::Broker, u"user"_s);
        p.password = setting(OptionScope::Broker, u"pass"_s);
    }
    p.clientId = setting(OptionScope::Client, u"id"_s);
    p.cleanSession = setting(OptionScope::Client, u"clean_session"_s) != u"false"_s;
    p.keepAliveSeconds = qMax(1, int(setting(OptionScope::Client, u"keep_alive_interval"_s).toDouble()));
    if (c.client.values.has(u"tls.certificate"_s)) {
        p.certFile = setting(OptionScope::Client, u"tls.certificate"_s);
        p.keyFile = setting(OptionScope::Client, u"tls.key"_s);
        p.keyPassword = setting(OptionScope::Client, u"tls.password"_s);
    }
    return p;
}
} // namespace

Result<BridgeSpec> BridgeSpec::load(const QByteArray& yaml, const QString& brokerUrl,
                                    const QHash<QString, QString>& args)
{
    // The texts are the ROS 1 bridge's, which read configs first: its translations hold for both.
    ConfigReadResult read = ConfigReader::read(yaml);
    if (!read.parsed) {
        // Located, as `config validate` says it: "LINE:COL: error: ...".
        const QString first = read.problems.isEmpty() ? QString() : read.problems.first().format(QString()).mid(1);
        return LocatedError {
            QCoreApplication::translate("ReferenceBridge", "not a bridge config: %1").arg(first)};
    }
    BridgeSpec spec;
    spec.config = read.config;
    const BridgeConfig& c = spec.config;
    QStringList missing;
    const auto setting = [&](OptionScope scope, const QString& path) {
        return substituteArgs(c.effective(scope, path), args, &missing);
    };
    spec.profile = brokerProfile(c, brokerUrl, setting);
    if (Status valid = spec.profile.validate(); !valid)
        return valid.error();
    spec.will.topic = setting(OptionScope::Client, u"last_will.topic"_s);
    spec.will.message = setting(OptionScope::Client, u"last_will.message"_s).toUtf8();
    spec.will.qos = setting(OptionScope::Client, u"last_will.qos"_s).toInt();
    spec.will.retained = setting(OptionScope::Client, u"last_will.retained"_s) == u"true"_s;

    const auto unresolved = [&missing] {
        missing.removeDuplicates();
        QStringList uses;
        QStringList gives;
        for (const QString& name : std::as_const(missing)) {
            uses << u"$(arg %1)"_s.arg(name);
            gives << u"--arg %1=VALUE"_s.arg(name);
        }
        return LocatedError {
            QCoreApplication::translate("ReferenceBridge", "the config uses %1: give the values with %2")
                .arg(uses.join(u", "_s), gives.join(u' '))};
    };
    for (const Mapping& m : c.mappings) {
        const auto value = [&](const QString& path) { return substituteArgs(m.effective(path), args, &missing); };
        BridgeRoute r;
        r.direction = m.direction;
        r.rosTopic = value(u"ros_topic"_s);
        r.mqttTopic = value(u"mqtt_topic"_s);
        r.primitive = value(u"primitive"_s) == u"true"_s;
        r.stamped = value(u"inject_timestamp"_s) == u"true"_s;
        r.json = value(u"json"_s) == u"true"_s;
        r.rosType = value(u"ros_type"_s).trimmed();
        bool ok = false;
        r.qos = value(u"advanced.mqtt.qos"_s).toInt(&ok);
        if (!missing.isEmpty())
            return unresolved();
        if (!ok || r.qos < 0 || r.qos > 2)
            return LocatedError {
                QCoreApplication::translate(
                    "ReferenceBridge",
                    "%1: qos must be 0, 1 or 2 (give $(arg ...) values with --arg NAME=VALUE)")
                    .arg(m.sourceTopic())};
        r.retained = value(u"advanced.mqtt.retained"_s) == u"true"_s;
        r.latched = value(u"advanced.ros.latched"_s) == u"true"_s;
        r.queueSize = qMax(1, value(u"advanced.ros.queue_size"_s).toInt());
        r.reliability = m.isSet(u"advanced.ros.qos.reliability"_s) ? value(u"advanced.ros.qos.reliability"_s) : QString();
        r.durability = m.isSet(u"advanced.ros.qos.durability"_s) ? value(u"advanced.ros.qos.durability"_s) : QString();
        r.stampPrefix = value(u"timestamp_topic_prefix"_s);
        if (r.rosTopic.isEmpty() || r.mqttTopic.isEmpty())
            return LocatedError {
                QCoreApplication::translate("ReferenceBridge", "a mapping without ros_topic or mqtt_topic")};
        if (!missing.isEmpty())
            return unresolved();
        spec.routes.push_back(std::move(r));
    }
    if (spec.routes.empty())
        return LocatedError {
            QCoreApplication::translate("ReferenceBridge", "the config has no mapping to bridge")};
    return spec;
}
