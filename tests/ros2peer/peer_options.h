// SPDX-License-Identifier: MIT
// bs_ros2peer's command line: what it may ask for, checked and bounded before any DDS call.
#ifndef BS_ROS2PEER_OPTIONS_H
#define BS_ROS2PEER_OPTIONS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define PEER_MAX_ENDPOINTS 32u                // per kind (--pub, --sub)
#define PEER_MAX_NAME 200u                    // bytes of a ROS namespace, node or topic name
#define PEER_MAX_SIZE (4u * 1024u * 1024u)    // --size: PointCloud2 data and Opaque blob bytes
#define PEER_MAX_DEPTH 10000                  // depth=N of a QoS
#define PEER_MAX_DOMAIN 232u                  // highest domain id whose ports fit in 16 bits
#define PEER_MAX_PATH 512u                    // --trace FILE
#define PEER_MAX_MANY 5000u                   // --many: publishers
#define PEER_MANY_END 10000u                  // --many: FIRST + N, so that indices have 4 digits
#define PEER_MANY_DIGITS 4u
#define PEER_MAX_MANY_BYTES (64u * 1024u * 1024u)   // --many: N x --size for PointCloud2, Opaque
#define PEER_MAX_STAMP_DELAY_MS 60000u      // --stamp-delay
#define PEER_MAX_FLOOD 20000u                // --flood-graph: writers
#define PEER_MAX_FLOOD_NAME 60000u           // --flood-graph: topic name length
#define PEER_MAX_RAW 65536u                   // --raw, --graph-raw: bytes of a hand-made sample

enum peer_type {
    PEER_STRING,         // std_msgs/msg/String
    PEER_POSE_STAMPED,   // geometry_msgs/msg/PoseStamped
    PEER_POINT_CLOUD2,   // sensor_msgs/msg/PointCloud2
    PEER_OPAQUE,         // bridgescope_test/msg/Opaque
    PEER_TIME_STAMPED,   // benchmarking_suite/msg/TimeStamped
    PEER_FLOAT64,        // std_msgs/msg/Float64
    PEER_NTYPES
};

// Bytes sent as they are instead of a serialized sample (--raw, --graph-raw): malformed CDR, huge
// sequence lengths, whatever a hostile node could put on the wire.
struct peer_raw {
    bool set;
    uint32_t len;                    // 1..PEER_MAX_RAW
    unsigned char *bytes;            // malloc'd
};

// One --pub or --sub.
struct peer_endpoint {
    char topic[PEER_MAX_NAME + 1];   // fully qualified ROS name ("/chatter")
    enum peer_type type;
    double rate_hz;                  // publishers only
    bool reliable;                   // else best effort
    bool transient_local;            // else volatile
    int32_t depth;                   // history keep-last depth
    struct peer_raw raw;             // publishers: --raw TOPIC:HEX for this topic
    int64_t stamp_delay_ns;          // TimeStamped publishers: --stamp-delay TOPIC:MS
};

// --many N[@FIRST]:PREFIX:TYPE[:RATE_HZ[:QOS]]: publishers on PREFIX0000, PREFIX0001, ...
struct peer_many {
    uint32_t count;                  // 0: no --many
    uint32_t first;                  // index of the first topic
    struct peer_endpoint ep;         // topic: the prefix; type, rate (0: never publish) and QoS
};

struct peer_options {
    uint32_t domain;
    char node_namespace[PEER_MAX_NAME + 1];   // "/" or "/a/b"
    char node_name[PEER_MAX_NAME + 1];
    struct peer_endpoint pubs[PEER_MAX_ENDPOINTS];
    unsigned npubs;
    struct peer_endpoint subs[PEER_MAX_ENDPOINTS];
    unsigned nsubs;
    struct peer_many many;
    uint64_t count;          // samples per publisher, 0: unlimited
    double duration_s;
    uint32_t size;
    uint32_t lease_ms;
    bool exit_hard;
    bool cdr;                // print each received sample's first serialized bytes
    bool show_discovery;     // print remote endpoints and ros_discovery_info nodes
    bool start_matched;      // a publisher starts once a reader matched it (and 0.5 s more)
    char trace_file[PEER_MAX_PATH + 1];   // Cyclone DDS trace, "" for none
    struct peer_raw graph_raw;       // --graph-raw HEX: ros_discovery_info sample bytes
    uint32_t flood_count;            // --flood-graph N:NAMELEN: N writers that never publish
    uint32_t flood_name_len;         // 0: all on /flood, each of its own type; else each on a
                                     // topic of its own, NAMELEN characters long
};

// "std_msgs/msg/String" and so on.
const char *peer_type_ros_name(enum peer_type type);

enum peer_parse_result { PEER_PARSE_OK, PEER_PARSE_HELP, PEER_PARSE_ERROR };

// Fills *options from argv. On PEER_PARSE_ERROR, err holds a one-line reason.
enum peer_parse_result peer_parse_options(int argc, char **argv, struct peer_options *options,
                                          char *err, size_t errlen);

// Frees what parsing allocated (the --raw bytes).
void peer_free_options(struct peer_options *options);

void peer_print_usage(FILE *out, const char *prog);

#endif
