// SPDX-License-Identifier: MIT
// The MQTT half of bench_watch's peer, as Bridgescope receives it: a bare Paho MQTT C++ subscriber
// (async_client, a message callback that counts and drops). Beside mosquitto_sub it says what the
// MQTT library alone costs per message. Paho outside core/mqtt on purpose: this is a peer.
//
//   bench_pahosub HOST PORT TOPIC_FILTER
// Prints the count of messages received so far once a second, until SIGTERM.
#include "peercount.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mqtt/async_client.h>
#include <string>
#include <unistd.h>

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: bench_pahosub HOST PORT TOPIC_FILTER\n");
        return 2;
    }
    PeerCount::stopOnTerm();
    const std::string uri = std::string("tcp://") + argv[1] + ":" + argv[2];
    mqtt::async_client client(uri, "bench_pahosub_" + std::to_string(getpid()), mqtt::create_options(MQTTVERSION_3_1_1));
    client.set_message_callback([](mqtt::const_message_ptr) { ++PeerCount::received; });
    try {
        client.connect(mqtt::connect_options_builder().clean_session(true).finalize())->wait();
        client.subscribe(argv[3], 0)->wait();
    } catch (const mqtt::exception& e) {
        std::fprintf(stderr, "bench_pahosub: %s\n", e.what());
        return 1;
    }
    PeerCount::printUntilTerm();
    std::_Exit(0);
}
