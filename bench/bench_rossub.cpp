// SPDX-License-Identifier: MIT
// The ROS half of bench_watch's peer: a bare roscpp subscriber, what any roscpp tool pays to
// receive a topic and drop it (topic_tools' ShapeShifter, one AsyncSpinner thread, as `rostopic hz`
// would do in C++). It subscribes to every topic the master lists under PREFIX during its first
// SECONDS_TO_FIND_TOPICS and prints the count of messages received so far once a second, until
// SIGTERM. roscpp outside core/ros on purpose: this is
// the peer, not Bridgescope.
//
// It says on stderr "topics N" after each look, and stops looking once it has EXPECTED topics.
//
// With TOPICS_FILE (one ROS topic a line) it subscribes to every topic in it at once instead, before
// any is advertised, as `bridgescope watch` does, and prints "RECEIVED HEARD" once a second: HEARD
// is how many of those topics have received a message (bench_watch's fleet form: the peer of the
// watch's time until every link is live).
//
//   bench_rossub MASTER_URI PREFIX SECONDS_TO_FIND_TOPICS EXPECTED [TOPICS_FILE]
#include "peercount.h"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <ros/master.h>
#include <ros/ros.h>
#include <string>
#include <topic_tools/shape_shifter.h>
#include <unistd.h>
#include <vector>

namespace {
std::atomic<unsigned long long> heard {0};

/// TOPICS_FILE's form: every topic at once, a flag a topic for its first message.
int subscribeUpfront(ros::NodeHandle& node, const char* path)
{
    std::ifstream in(path);
    std::vector<std::string> names;
    for (std::string line; std::getline(in, line) && names.size() < 100000;)
        if (!line.empty())
            names.push_back(line);
    const auto flags = std::make_shared<std::vector<std::atomic<bool>>>(names.size());
    std::vector<ros::Subscriber> subs;
    subs.reserve(names.size());
    for (std::size_t i = 0; i < names.size(); ++i) {
        const boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> count
            = [flags, i](const topic_tools::ShapeShifter::ConstPtr&) {
                  ++PeerCount::received;
                  if (!(*flags)[i].exchange(true))
                      ++heard;
              };
        subs.push_back(node.subscribe<topic_tools::ShapeShifter>(names[i], 10, count));
    }
    std::fprintf(stderr, "topics %zu\n", subs.size());
    for (int tenths = 0; !PeerCount::stop; ++tenths) {
        usleep(100000);
        if (tenths % 10 == 0) {
            std::printf("%llu %llu\n", static_cast<unsigned long long>(PeerCount::received),
                        static_cast<unsigned long long>(heard));
            std::fflush(stdout);
        }
    }
    std::_Exit(0); // roscpp's static teardown is not the subject
}
} // namespace

int main(int argc, char** argv)
{
    if (argc != 5 && argc != 6) {
        std::fprintf(stderr,
                     "usage: bench_rossub MASTER_URI PREFIX SECONDS_TO_FIND_TOPICS EXPECTED [TOPICS_FILE]\n");
        return 2;
    }
    PeerCount::stopOnTerm();
    ros::M_string remappings {{"__master", argv[1]}};
    ros::init(remappings, "bench_rossub", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
    ros::NodeHandle node;
    const std::string prefix = argv[2];
    const int wantSeconds = std::atoi(argv[3]);
    const std::size_t expected = std::size_t(std::max(0, std::atoi(argv[4])));
    std::vector<ros::Subscriber> subs;
    std::vector<std::string> have;
    ros::AsyncSpinner spinner(1);
    spinner.start();
    if (argc == 6)
        return subscribeUpfront(node, argv[5]);
    // Topics appear as the bridge advertises them: look again for a while.
    for (int i = 0; i < wantSeconds * 2 && !PeerCount::stop && subs.size() < expected; ++i) {
        ros::master::V_TopicInfo topics;
        ros::master::getTopics(topics);
        for (const auto& t : topics) {
            if (t.name.compare(0, prefix.size(), prefix) != 0
                || std::find(have.begin(), have.end(), t.name) != have.end())
                continue;
            have.push_back(t.name);
            const boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> count
                = [](const topic_tools::ShapeShifter::ConstPtr&) { ++PeerCount::received; };
            subs.push_back(node.subscribe<topic_tools::ShapeShifter>(t.name, 10, count));
        }
        std::fprintf(stderr, "topics %zu\n", subs.size());
        if (subs.size() < expected)
            usleep(500000);
    }
    PeerCount::printUntilTerm();
    spinner.stop();
    std::_Exit(0); // roscpp's static teardown is not the subject
}
