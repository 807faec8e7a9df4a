// SPDX-License-Identifier: MIT
#include "pahooptions.h"

#include <mqtt/async_client.h>
#include <QUuid>

using namespace Qt::StringLiterals;

namespace PahoOptions {

std::string clientId(const MqttProfile& p)
{
    return p.clientId.isEmpty()
        ? u"bridgescope-%1"_s.arg(QUuid::createUuid().toString(QUuid::Id128).left(12)).toStdString()
        : p.clientId.toStdString();
}

mqtt::connect_options_builder connectOptions(const MqttProfile& p)
{
    auto builder = mqtt::connect_options_builder();
    builder.keep_alive_interval(std::chrono::seconds(std::max(1, p.keepAliveSeconds)))
        .automatic_reconnect(std::chrono::seconds(1), std::chrono::seconds(kMaxRetrySeconds))
        .connect_timeout(std::chrono::seconds(5));
    if (p.mqttVersion == 5)
        builder.mqtt_version(MQTTVERSION_5).clean_start(p.cleanSession);
    else
        builder.mqtt_version(MQTTVERSION_3_1_1).clean_session(p.cleanSession);
    if (!p.username.isEmpty())
        builder.user_name(p.username.toStdString()).password(p.password.toStdString());
    if (p.isTls()) {
        mqtt::ssl_options ssl;
        if (!p.caFile.isEmpty())
            ssl.set_trust_store(p.caFile.toStdString());
        if (!p.certFile.isEmpty()) {
            ssl.set_key_store(p.certFile.toStdString());
            ssl.set_private_key(p.keyFile.toStdString());
            if (!p.keyPassword.isEmpty())
                ssl.set_private_key_password(p.keyPassword.toStdString());
        }
        ssl.set_enable_server_cert_auth(p.verifyServer);
        ssl.set_verify(p.verifyServer);
        // No ssl error handler: Paho C++ 1.2 hands OpenSSL a pointer to the ssl_options object
        // it was set on, which its copies leave dangling.
        builder.ssl(std::move(ssl));
    }
    return builder;
}

void reconnectNow(mqtt::async_client& client)
{
    try {
        client.reconnect();
    } catch (const mqtt::exception&) {
        // Not connected before, or reconnecting already: the scheduled attempts go on.
    }
}

} // namespace PahoOptions
