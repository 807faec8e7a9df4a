// SPDX-License-Identifier: MIT
#pragma once

#include "mqtt/mqttprofile.h"

#include <mqtt/connect_options.h>
#include <string>

namespace mqtt {
class async_client;
}

/// Paho's view of a connection profile, shared by every client in core/mqtt.
namespace PahoOptions {
/// The profile's client id, or a random "bridgescope-…" one.
std::string clientId(const MqttProfile& profile);
/// The longest wait between two connection attempts. A lab broker that restarts is back within
/// seconds; a longer backoff only loses the data of the seconds after it is back.
inline constexpr int kMaxRetrySeconds = 2;
/// Keep-alive, MQTT version and clean session, credentials and TLS; reconnects by themselves, the
/// wait doubling from 1 s to kMaxRetrySeconds.
mqtt::connect_options_builder connectOptions(const MqttProfile& profile);
/// Called from a connection-lost handler: the first attempt is made at once instead of after the
/// shortest wait (Paho counts its waits in whole seconds).
void reconnectNow(mqtt::async_client& client);
} // namespace PahoOptions
