// SPDX-License-Identifier: MIT
// bs_ros2peer: a ROS 2 Humble node as rmw_cyclonedds_cpp puts it on the wire, written directly on
// Cyclone DDS's C API, so that Bridgescope's tests (its ROS 2 side runs on Fast DDS) can prove wire
// interoperability with the other DDS implementation ROS 2 ships. Loopback only. See README.md.
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <dds/dds.h>
#include "peer_sertype.h"
#include "peer_msgs.h"
#include "peer_options.h"
#include "rmw_dds_common.h"

// Waitset attachment: what kind of entity woke us, and its index.
enum { ATTACH_PUB = 1, ATTACH_SUB, ATTACH_GRAPH, ATTACH_BUILTIN_PUB, ATTACH_BUILTIN_SUB };
#define ATTACH(kind, index) ((dds_attach_t)(((uint64_t)(kind) << 32) | (uint32_t)(index)))

#define TAKE_BATCH 16
#define CDR_SHOWN 16  // bytes printed by --cdr (the 4-byte encapsulation header first)

struct pub_state {
    const struct peer_endpoint *ep;
    dds_entity_t writer;
    struct peer_sample sample;
    uint64_t sent;
    double next;       // monotonic time of the next sample
    int32_t matched;   // last printed match count
    bool done;         // --count reached
};

struct sub_state {
    const struct peer_endpoint *ep;
    dds_entity_t reader;
    const dds_topic_descriptor_t *desc;
    uint64_t received;
    int32_t matched;
};

struct peer {
    struct peer_options opt;
    dds_entity_t domain, participant, publisher, subscriber, waitset;
    dds_entity_t graph_writer, graph_reader;               // ros_discovery_info
    dds_entity_t builtin_pub_reader, builtin_sub_reader;   // --show-discovery
    dds_guid_t guid;                                       // of the participant
    struct pub_state *pubs;                                // --pub, then --many
    unsigned npubs;
    struct peer_endpoint *many;                            // the endpoints of --many
    struct sub_state subs[PEER_MAX_ENDPOINTS];
};

static struct peer peer;
static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

static double now_mono(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static bool dds_ok(dds_return_t rc, const char *what)
{
    if (rc < 0) {
        fprintf(stderr, "bs_ros2peer: %s: %s\n", what, dds_strretcode(rc));
        return false;
    }
    return true;
}

// The domain's configuration: unicast on 127.0.0.1 only, SPDP to the standard discovery ports of
// participant indices 0..30 on 127.0.0.1, our own index picked automatically, the given lease.
static void make_config(const struct peer_options *o, char *buf, size_t len)
{
    char trace[PEER_MAX_PATH + 128] = "";
    if (o->trace_file[0] != '\0')
        snprintf(trace, sizeof trace,
                 "<Tracing><Verbosity>finest</Verbosity><OutputFile>%s</OutputFile></Tracing>",
                 o->trace_file);
    snprintf(buf, len,
             "<CycloneDDS><Domain Id=\"any\">"
             "<General>"
             "<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
             "<AllowMulticast>false</AllowMulticast>"
             "</General>"
             "<Discovery>"
             "<ParticipantIndex>auto</ParticipantIndex>"
             "<MaxAutoParticipantIndex>30</MaxAutoParticipantIndex>"
             "<Peers><Peer Address=\"127.0.0.1\"/></Peers>"
             "<LeaseDuration>%u ms</LeaseDuration>"
             "</Discovery>"
             "%s"
             "</Domain></CycloneDDS>",
             (unsigned)o->lease_ms, trace);
}

// rmw_cyclonedds_cpp's create_readwrite_qos for the profiles the command line can express:
// keep-last history, reliability, durability (with a durability service for transient local,
// as Cyclone keeps historical data by it), automatic liveliness, no autodispose.
static dds_qos_t *make_qos(bool reliable, bool transient_local, bool keep_all, int32_t depth,
                           bool ignore_local)
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_writer_data_lifecycle(qos, false);
    if (keep_all)
        dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, DDS_LENGTH_UNLIMITED);
    else
        dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, depth);
    if (reliable)
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_INFINITY);
    else
        dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
    if (transient_local) {
        dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
        dds_qset_durability_service(qos, 0, keep_all ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST,
                                    keep_all ? DDS_LENGTH_UNLIMITED : depth, DDS_LENGTH_UNLIMITED,
                                    DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    } else {
        dds_qset_durability(qos, DDS_DURABILITY_VOLATILE);
    }
    dds_qset_liveliness(qos, DDS_LIVELINESS_AUTOMATIC, DDS_INFINITY);
    if (ignore_local)
        dds_qset_ignorelocal(qos, DDS_IGNORELOCAL_PARTICIPANT);
    return qos;
}

// rmw's gid: the 16-byte DDS GUID, then zeros up to 24 bytes.
static bool entity_gid(dds_entity_t e, rmw_dds_common_msg_dds__Gid_ *gid)
{
    dds_guid_t guid;
    memset(gid, 0, sizeof *gid);
    if (!dds_ok(dds_get_guid(e, &guid), "dds_get_guid"))
        return false;
    memcpy(gid->data, guid.v, sizeof guid.v);
    return true;
}

// Publishes this participant's ParticipantEntitiesInfo on ros_discovery_info: our node with its
// readers and writers (those not yet deleted), or no node at all (after it is destroyed).
static bool publish_graph(bool with_node)
{
    rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ info;
    rmw_dds_common_msg_dds__NodeEntitiesInfo_ node;
    rmw_dds_common_msg_dds__Gid_ readers[PEER_MAX_ENDPOINTS];
    rmw_dds_common_msg_dds__Gid_ *writers = calloc(peer.npubs > 0 ? peer.npubs : 1, sizeof *writers);
    if (writers == NULL) {
        fprintf(stderr, "bs_ros2peer: out of memory\n");
        return false;
    }
    memset(&info, 0, sizeof info);
    memset(&node, 0, sizeof node);
    memcpy(info.gid.data, peer.guid.v, sizeof peer.guid.v);
    if (with_node) {
        // Both fit: parsing limits them to PEER_MAX_NAME (200) bytes, the type to 256.
        snprintf(node.node_namespace, sizeof node.node_namespace, "%s", peer.opt.node_namespace);
        snprintf(node.node_name, sizeof node.node_name, "%s", peer.opt.node_name);
        uint32_t nr = 0, nw = 0;
        for (unsigned i = 0; i < peer.opt.nsubs; i++)
            if (peer.subs[i].reader > 0 && entity_gid(peer.subs[i].reader, &readers[nr]))
                nr++;
        for (unsigned i = 0; i < peer.npubs; i++)
            if (peer.pubs[i].writer > 0 && entity_gid(peer.pubs[i].writer, &writers[nw]))
                nw++;
        node.reader_gid_seq._buffer = readers;
        node.reader_gid_seq._length = node.reader_gid_seq._maximum = nr;
        node.writer_gid_seq._buffer = writers;
        node.writer_gid_seq._length = node.writer_gid_seq._maximum = nw;
        info.node_entities_info_seq._buffer = &node;
        info.node_entities_info_seq._length = info.node_entities_info_seq._maximum = 1;
    }
    bool ok = dds_ok(dds_write(peer.graph_writer, &info), "dds_write ros_discovery_info");
    free(writers);
    return ok;
}

static bool create_entities(void)
{
    const struct peer_options *o = &peer.opt;
    char config[2048];
    make_config(o, config, sizeof config);
    peer.domain = dds_create_domain(o->domain, config);
    if (!dds_ok(peer.domain, "dds_create_domain"))
        return false;

    // rmw_cyclonedds_cpp: one participant per context, its user data "enclave=<enclave>;".
    static const char user_data[] = "enclave=/;";
    dds_qos_t *qos = dds_create_qos();
    dds_qset_userdata(qos, user_data, sizeof user_data - 1);
    peer.participant = dds_create_participant(o->domain, qos, NULL);
    dds_delete_qos(qos);
    if (!dds_ok(peer.participant, "dds_create_participant"))
        return false;
    if (!dds_ok(dds_get_guid(peer.participant, &peer.guid), "dds_get_guid participant"))
        return false;
    peer.publisher = dds_create_publisher(peer.participant, NULL, NULL);
    peer.subscriber = dds_create_subscriber(peer.participant, NULL, NULL);
    peer.waitset = dds_create_waitset(peer.participant);
    if (!dds_ok(peer.publisher, "dds_create_publisher") || !dds_ok(peer.subscriber, "dds_create_subscriber")
        || !dds_ok(peer.waitset, "dds_create_waitset"))
        return false;

    // The graph: ros_discovery_info (no rt/ prefix), reliable, transient local, depth 1; rmw's
    // reader keeps all and ignores its own participant's samples.
    dds_entity_t graph_topic = peer_create_topic(peer.participant,
                                                 &rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc,
                                                 "ros_discovery_info", &o->graph_raw);
    if (!dds_ok(graph_topic, "dds_create_topic ros_discovery_info"))
        return false;
    qos = make_qos(true, true, false, 1, false);
    peer.graph_writer = dds_create_writer(peer.publisher, graph_topic, qos, NULL);
    dds_delete_qos(qos);
    qos = make_qos(true, true, true, 0, true);
    peer.graph_reader = dds_create_reader(peer.subscriber, graph_topic, qos, NULL);
    dds_delete_qos(qos);
    if (!dds_ok(peer.graph_writer, "dds_create_writer ros_discovery_info")
        || !dds_ok(peer.graph_reader, "dds_create_reader ros_discovery_info"))
        return false;
    dds_set_status_mask(peer.graph_reader, DDS_DATA_AVAILABLE_STATUS);
    dds_waitset_attach(peer.waitset, peer.graph_reader, ATTACH(ATTACH_GRAPH, 0));

    if (o->show_discovery) {
        // Local readers of Cyclone's built-in topics: nothing of them goes on the wire.
        peer.builtin_pub_reader = dds_create_reader(peer.participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, NULL, NULL);
        peer.builtin_sub_reader = dds_create_reader(peer.participant, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, NULL, NULL);
        if (!dds_ok(peer.builtin_pub_reader, "dds_create_reader DCPSPublication")
            || !dds_ok(peer.builtin_sub_reader, "dds_create_reader DCPSSubscription"))
            return false;
        dds_set_status_mask(peer.builtin_pub_reader, DDS_DATA_AVAILABLE_STATUS);
        dds_set_status_mask(peer.builtin_sub_reader, DDS_DATA_AVAILABLE_STATUS);
        dds_waitset_attach(peer.waitset, peer.builtin_pub_reader, ATTACH(ATTACH_BUILTIN_PUB, 0));
        dds_waitset_attach(peer.waitset, peer.builtin_sub_reader, ATTACH(ATTACH_BUILTIN_SUB, 0));
    }

    // --pub, then --many's N publishers on PREFIX<FIRST>, PREFIX<FIRST + 1>, ...
    unsigned npubs = o->npubs + o->many.count;
    peer.pubs = calloc(npubs > 0 ? npubs : 1, sizeof *peer.pubs);
    peer.many = calloc(o->many.count > 0 ? o->many.count : 1, sizeof *peer.many);
    if (peer.pubs == NULL || peer.many == NULL) {
        fprintf(stderr, "bs_ros2peer: out of memory\n");
        return false;
    }
    peer.npubs = npubs;
    size_t prefix_len = strlen(o->many.ep.topic);   // parsing left room for the four digits
    for (unsigned i = 0; i < o->many.count; i++) {
        peer.many[i] = o->many.ep;
        unsigned index = o->many.first + i;          // below 10000: parsing checked FIRST + N
        char *digits = peer.many[i].topic + prefix_len;
        for (int k = (int)PEER_MANY_DIGITS - 1; k >= 0; k--, index /= 10)
            digits[k] = (char)('0' + index % 10);
        digits[PEER_MANY_DIGITS] = '\0';
    }

    // ROS topic /foo is DDS topic rt/foo; the type is pkg::msg::dds_::Type_ (the descriptor's name).
    char dds_topic[PEER_MAX_NAME + 8];
    for (unsigned i = 0; i < peer.npubs; i++) {
        struct pub_state *p = &peer.pubs[i];
        p->ep = i < o->npubs ? &o->pubs[i] : &peer.many[i - o->npubs];
        p->done = p->ep->rate_hz <= 0.0; // --many with RATE_HZ 0: never publishes
        snprintf(dds_topic, sizeof dds_topic, "rt%s", p->ep->topic);
        dds_entity_t topic = peer_create_topic(peer.participant, peer_type_descriptor(p->ep->type), dds_topic,
                                               &p->ep->raw);
        if (!dds_ok(topic, "dds_create_topic"))
            return false;
        qos = make_qos(p->ep->reliable, p->ep->transient_local, false, p->ep->depth, false);
        p->writer = dds_create_writer(peer.publisher, topic, qos, NULL);
        dds_delete_qos(qos);
        if (!dds_ok(p->writer, "dds_create_writer"))
            return false;
        if (peer_sample_init(&p->sample, p->ep->type, o->size) != 0) {
            fprintf(stderr, "bs_ros2peer: out of memory\n");
            return false;
        }
        p->sample.stamp_delay_ns = p->ep->stamp_delay_ns;
        p->sample.salt = i + 1;
        p->sample.period_ns = p->ep->rate_hz > 0.0 ? (int64_t)(1e9 / p->ep->rate_hz + 0.5) : 1000000;
        dds_set_status_mask(p->writer, DDS_PUBLICATION_MATCHED_STATUS);
        dds_waitset_attach(peer.waitset, p->writer, ATTACH(ATTACH_PUB, i));
    }
    // --flood-graph: writers that never publish, only announced (hostile discovery, issue 41)
    if (o->flood_count > 0) {
        size_t cap = (size_t)o->flood_name_len + 64;
        char *flood_topic = malloc(cap);
        if (flood_topic == NULL) {
            fprintf(stderr, "bs_ros2peer: out of memory\n");
            return false;
        }
        qos = make_qos(true, false, false, 1, false);
        for (unsigned i = 0; i < o->flood_count; i++) {
            char type_name[96];
            if (o->flood_name_len == 0) {
                snprintf(flood_topic, cap, "rt/flood");
                snprintf(type_name, sizeof type_name, "flood_msgs::msg::dds_::T%u_", i);
            } else {
                int n = snprintf(flood_topic, cap, "rt/flood%05u_", i);
                memset(flood_topic + n, 'x', o->flood_name_len - (size_t)n + 3);
                flood_topic[o->flood_name_len + 3] = '\0';
                snprintf(type_name, sizeof type_name, "std_msgs::msg::dds_::String_");
            }
            dds_entity_t topic = peer_create_topic_named(peer.participant, peer_type_descriptor(PEER_STRING),
                                                         flood_topic, type_name);
            if (!dds_ok(topic, "dds_create_topic (--flood-graph)")
                || !dds_ok(dds_create_writer(peer.publisher, topic, qos, NULL), "dds_create_writer (--flood-graph)")) {
                free(flood_topic);
                dds_delete_qos(qos);
                return false;
            }
        }
        dds_delete_qos(qos);
        free(flood_topic);
    }
    for (unsigned i = 0; i < o->nsubs; i++) {
        struct sub_state *s = &peer.subs[i];
        s->ep = &o->subs[i];
        s->desc = peer_type_descriptor(s->ep->type);
        snprintf(dds_topic, sizeof dds_topic, "rt%s", s->ep->topic);
        dds_entity_t topic = peer_create_topic(peer.participant, s->desc, dds_topic, NULL);
        if (!dds_ok(topic, "dds_create_topic"))
            return false;
        // rclcpp's default: local publications are not ignored.
        qos = make_qos(s->ep->reliable, s->ep->transient_local, false, s->ep->depth, false);
        s->reader = dds_create_reader(peer.subscriber, topic, qos, NULL);
        dds_delete_qos(qos);
        if (!dds_ok(s->reader, "dds_create_reader"))
            return false;
        dds_set_status_mask(s->reader, DDS_DATA_AVAILABLE_STATUS | DDS_SUBSCRIPTION_MATCHED_STATUS);
        dds_waitset_attach(peer.waitset, s->reader, ATTACH(ATTACH_SUB, i));
    }
    return publish_graph(true);
}

// A name from the network, safe to print as one word.
static void print_word(const char *s, size_t max)
{
    for (size_t i = 0; i < max && s[i] != '\0'; i++) {
        unsigned char c = (unsigned char)s[i];
        putchar(c <= 0x20 || c == 0x7f ? '?' : (int)c);
    }
}

static void check_matched(const char *topic, int32_t current, int32_t *last)
{
    if (current != *last) {
        *last = current;
        printf("matched %s %d\n", topic, (int)current);
    }
}

static void on_writer_status(struct pub_state *p)
{
    dds_publication_matched_status_t st;
    if (dds_get_publication_matched_status(p->writer, &st) >= 0)
        check_matched(p->ep->topic, (int32_t)st.current_count, &p->matched);
}

// Takes every sample as serialized data: --cdr shows the bytes as they came (the encapsulation
// header first), then the sample is deserialized for its summary.
static void on_reader_status(struct sub_state *s)
{
    uint32_t status = 0;
    dds_take_status(s->reader, &status, DDS_SUBSCRIPTION_MATCHED_STATUS | DDS_DATA_AVAILABLE_STATUS);
    dds_subscription_matched_status_t st;
    if (dds_get_subscription_matched_status(s->reader, &st) >= 0)
        check_matched(s->ep->topic, (int32_t)st.current_count, &s->matched);

    struct ddsi_serdata *sd[TAKE_BATCH];
    dds_sample_info_t si[TAKE_BATCH];
    dds_return_t n;
    while ((n = dds_takecdr(s->reader, sd, TAKE_BATCH, si, DDS_ANY_STATE)) > 0) {
        for (dds_return_t i = 0; i < n; i++) {
            if (si[i].valid_data) {
                s->received++;
                if (peer.opt.cdr) {
                    unsigned char bytes[CDR_SHOWN];
                    uint32_t size = peer_cdr_size(sd[i]);
                    uint32_t shown = size < CDR_SHOWN ? size : CDR_SHOWN;
                    peer_cdr_bytes(sd[i], shown, bytes);
                    printf("cdr %s %llu %u", s->ep->topic, (unsigned long long)s->received, (unsigned)size);
                    for (uint32_t k = 0; k < shown; k++)
                        printf(" %02x", bytes[k]);
                    printf("\n");
                }
                char summary[128] = "?";
                void *msg = peer_cdr_to_sample(sd[i], s->desc);
                if (msg != NULL) {
                    peer_summary(s->ep->type, msg, summary, sizeof summary);
                    dds_sample_free(msg, s->desc, DDS_FREE_ALL);
                }
                printf("recv %s %llu %s\n", s->ep->topic, (unsigned long long)s->received, summary);
            }
            peer_cdr_release(sd[i]);
        }
    }
}

// Other participants' ros_discovery_info: one line per node (with --show-discovery).
static void on_graph_data(void)
{
    for (;;) {
        void *buf[TAKE_BATCH] = { NULL };   // NULL: let Cyclone lend the samples
        dds_sample_info_t si[TAKE_BATCH];
        dds_return_t n = dds_take(peer.graph_reader, buf, si, TAKE_BATCH, TAKE_BATCH);
        if (n <= 0)
            break;
        for (dds_return_t i = 0; i < n && peer.opt.show_discovery; i++) {
            if (!si[i].valid_data)
                continue;
            const rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ *info = buf[i];
            for (uint32_t k = 0; k < info->node_entities_info_seq._length; k++) {
                const rmw_dds_common_msg_dds__NodeEntitiesInfo_ *node = &info->node_entities_info_seq._buffer[k];
                printf("node ");
                print_word(node->node_namespace, sizeof node->node_namespace);
                printf(" ");
                print_word(node->node_name, sizeof node->node_name);
                printf(" %u %u\n", (unsigned)node->reader_gid_seq._length, (unsigned)node->writer_gid_seq._length);
            }
        }
        dds_return_loan(peer.graph_reader, buf, n);
    }
}

// Endpoints of other participants as DDS discovery (SEDP) announced them (with --show-discovery).
static void on_builtin_data(dds_entity_t reader, const char *kind)
{
    for (;;) {
        void *buf[TAKE_BATCH] = { NULL };
        dds_sample_info_t si[TAKE_BATCH];
        dds_return_t n = dds_take(reader, buf, si, TAKE_BATCH, TAKE_BATCH);
        if (n <= 0)
            break;
        for (dds_return_t i = 0; i < n; i++) {
            const dds_builtintopic_endpoint_t *ep = buf[i];
            if (!si[i].valid_data || si[i].instance_state != DDS_IST_ALIVE
                || memcmp(ep->participant_key.v, peer.guid.v, sizeof peer.guid.v) == 0)
                continue;
            printf("endpoint %s ", kind);
            print_word(ep->topic_name ? ep->topic_name : "?", 512);
            printf(" ");
            print_word(ep->type_name ? ep->type_name : "?", 512);
            printf("\n");
        }
        dds_return_loan(reader, buf, n);
    }
}

static void publish_due(double t)
{
    for (unsigned i = 0; i < peer.npubs; i++) {
        struct pub_state *p = &peer.pubs[i];
        if (!p->done && peer.opt.start_matched && p->matched <= 0) {
            p->next = t + 0.5; // --start-matched: half a second after the first reader matched
            continue;
        }
        if (p->done || t < p->next)
            continue;
        uint64_t n = p->sent + 1;
        peer_sample_fill(&p->sample, n);
        if (!dds_ok(dds_write(p->writer, &p->sample.msg), "dds_write"))
            continue;
        p->sent = n;
        printf("sent %s %llu\n", p->ep->topic, (unsigned long long)n);
        if (p->ep->type == PEER_TIME_STAMPED && !p->ep->raw.set)
            printf("stamp %s %llu %lld %lld\n", p->ep->topic, (unsigned long long)n,
                   (long long)p->sample.stamp_ns, (long long)p->sample.time_ns);
        if (peer.opt.count != 0 && n >= peer.opt.count)
            p->done = true;
        // The next slot; after a stall, start again from now rather than send a burst.
        p->next += 1.0 / p->ep->rate_hz;
        if (p->next <= t)
            p->next = t + 1.0 / p->ep->rate_hz;
    }
}

static void run(void)
{
    double start = now_mono(), end = start + peer.opt.duration_s;
    for (unsigned i = 0; i < peer.npubs; i++)
        peer.pubs[i].next = start;
    dds_attach_t xs[2 * PEER_MAX_ENDPOINTS + 3];
    while (!stop_requested) {
        double t = now_mono();
        if (t >= end)
            break;
        publish_due(t);
        // Sleep until the next sample is due, at most 100 ms so that a signal is seen quickly.
        double wake = end;
        for (unsigned i = 0; i < peer.npubs; i++)
            if (!peer.pubs[i].done && peer.pubs[i].next < wake)
                wake = peer.pubs[i].next;
        double wait = wake - now_mono();
        if (wait > 0.1)
            wait = 0.1;
        if (wait < 0.0)
            wait = 0.0;
        dds_return_t n = dds_waitset_wait(peer.waitset, xs, sizeof xs / sizeof xs[0], (dds_duration_t)(wait * 1e9));
        for (dds_return_t k = 0; k < n && k < (dds_return_t)(sizeof xs / sizeof xs[0]); k++) {
            unsigned kind = (unsigned)(xs[k] >> 32), index = (unsigned)(xs[k] & 0xffffffffu);
            switch (kind) {
            case ATTACH_PUB:
                if (index < peer.npubs)
                    on_writer_status(&peer.pubs[index]);
                break;
            case ATTACH_SUB:
                if (index < peer.opt.nsubs)
                    on_reader_status(&peer.subs[index]);
                break;
            case ATTACH_GRAPH:
                on_graph_data();
                break;
            case ATTACH_BUILTIN_PUB:
                on_builtin_data(peer.builtin_pub_reader, "pub");
                break;
            case ATTACH_BUILTIN_SUB:
                on_builtin_data(peer.builtin_sub_reader, "sub");
                break;
            default:
                break;
            }
        }
    }
}

// As rclcpp and rmw do on shutdown: the node's endpoints go (the graph is published without
// them), then the node (the graph is published without it), then the participant. Deleting
// them makes Cyclone unregister their data and announce that they are gone.
static void shut_down(void)
{
    if (peer.participant > 0 && peer.graph_writer > 0) {
        for (unsigned i = 0; i < peer.npubs; i++) {
            if (peer.pubs[i].writer > 0)
                dds_delete(peer.pubs[i].writer);
            peer.pubs[i].writer = 0;
        }
        for (unsigned i = 0; i < peer.opt.nsubs; i++) {
            if (peer.subs[i].reader > 0)
                dds_delete(peer.subs[i].reader);
            peer.subs[i].reader = 0;
        }
        publish_graph(true);
        publish_graph(false);
    }
    if (peer.domain > 0)
        dds_delete(peer.domain);
    for (unsigned i = 0; i < peer.npubs && peer.pubs != NULL; i++)
        peer_sample_fini(&peer.pubs[i].sample);
    free(peer.pubs);
    free(peer.many);
    peer_free_options(&peer.opt);
    peer.pubs = NULL;
    peer.many = NULL;
    peer.npubs = 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char err[256] = "";
    switch (peer_parse_options(argc, argv, &peer.opt, err, sizeof err)) {
    case PEER_PARSE_HELP:
        peer_print_usage(stdout, "bs_ros2peer");
        return 0;
    case PEER_PARSE_ERROR:
        fprintf(stderr, "bs_ros2peer: %s\n", err);
        return 2;
    case PEER_PARSE_OK:
        break;
    }

    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    if (!create_entities()) {
        if (peer.opt.exit_hard)
            _exit(1);
        shut_down();
        return 1;
    }
    printf("ready\n");
    run();
    if (peer.opt.exit_hard) {
        // Vanish without a goodbye: no entity deleted, no dispose, no SPDP "gone" message.
        fflush(stdout);
        _exit(0);
    }
    shut_down();
    return 0;
}
