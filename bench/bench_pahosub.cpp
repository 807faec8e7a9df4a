// SPDX-License-Identifier: MIT
// The MQTT half of bench_watch's peer, as Bridgescope receives it: a bare Paho MQTT C++ subscriber
// (async_client, a message callback that counts and drops). Beside mosquitto_sub it says what the
// MQTT library alone costs per message. Paho outside core/mqtt on purpose: this is a peer.
//
//   bench_pahosub HOST PORT TOPIC_FILTER
// Prints the count of messages received so far once a second, until SIGTERM.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mqtt/async_client.h>
#include <string>
#include <unistd.h>

namespace {
std::atomic<unsigned long long> g_received {0};
std::atomic<bool> g_stop {false};
void onTerm(int) { g_stop = true; }
} // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: bench_pahosub HOST PORT TOPIC_FILTER\n");
        return 2;
    }
    std::signal(SIGTERM, onTerm);
    const std::string uri = std::string("tcp://") + argv[1] + ":" + argv[2];
    mqtt::async_client client(uri, "bench_pahosub_" + std::to_string(getpid()), mqtt::create_options(MQTTVERSION_3_1_1));
    client.set_message_callback([](mqtt::const_message_ptr) { ++g_received; });
    try {
        client.connect(mqtt::connect_options_builder().clean_session(true).finalize())->wait();
        client.subscribe(argv[3], 0)->wait();
    } catch (const mqtt::exception& e) {
        std::fprintf(stderr, "bench_pahosub: %s\n", e.what());
        return 1;
    }
    for (int tenths = 0; !g_stop; ++tenths) {
        usleep(100000);
        if (tenths % 10 == 0) {
            std::printf("%llu\n", static_cast<unsigned long long>(g_received));
            std::fflush(stdout);
        }
    }
    std::_Exit(0);
}
