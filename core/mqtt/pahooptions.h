// SPDX-License-Identifier: MIT
#pragma once

#include "mqttprofile.h"

#include <mqtt/connect_options.h>
#include <string>

/// Paho's view of a connection profile, shared by every client in core/mqtt.
namespace PahoOptions {
/// The profile's client id, or a random "bridgescope-…" one.
std::string clientId(const MqttProfile& profile);
/// Keep-alive, MQTT version and clean session, credentials and TLS; reconnects with backoff.
mqtt::connect_options_builder connectOptions(const MqttProfile& profile);
} // namespace PahoOptions
