// SPDX-License-Identifier: MIT
// Parsing and checking of bs_ros2peer's command line. ROS names follow rmw's validation rules
// (rmw_validate_full_topic_name, rmw_validate_namespace, rmw_validate_node_name).
#define _POSIX_C_SOURCE 200809L
#include "peer_options.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static const char *const type_names[PEER_NTYPES] = {
    "std_msgs/msg/String",
    "geometry_msgs/msg/PoseStamped",
    "sensor_msgs/msg/PointCloud2",
    "bridgescope_test/msg/Opaque",
    "benchmarking_suite/msg/TimeStamped",
    "std_msgs/msg/Float64",
};

const char *peer_type_ros_name(enum peer_type type)
{
    return (unsigned)type < PEER_NTYPES ? type_names[type] : "?";
}

void peer_print_usage(FILE *out, const char *prog)
{
    fprintf(out,
        "Usage: %s --domain N [options]\n"
        "A ROS 2 Humble node as rmw_cyclonedds_cpp puts it on the wire (Cyclone DDS, loopback only),\n"
        "for Bridgescope's interoperability tests.\n"
        "\n"
        "  --domain N                 DDS domain id, 0..%u (required)\n"
        "  --node /NS/NAME | NAME     node namespace and name (default /bs_peer)\n"
        "  --pub TOPIC:TYPE[:RATE_HZ[:QOS]]   publish (repeatable, up to %u); RATE_HZ default 10\n"
        "  --sub TOPIC:TYPE[:QOS]     subscribe and print each sample (repeatable, up to %u)\n"
        "  --many N[@FIRST]:PREFIX:TYPE[:RATE_HZ[:QOS]]   N more publishers (at most %u, once), on\n"
        "                             PREFIX0000.. or PREFIX<FIRST>..; RATE_HZ 0: they never publish\n"
        "  --count N                  stop each publisher after N samples (default unlimited)\n"
        "  --duration SEC             exit after SEC seconds (default 30, at most 3600)\n"
        "  --size BYTES               PointCloud2 data and Opaque blob size (default 1024, at most %u)\n"
        "  --lease-ms MS              participant lease duration (default 2000, 100..3600000)\n"
        "  --exit-hard                end with _exit(0), deleting nothing (no goodbye on the wire)\n"
        "  --cdr                      also print the first serialized bytes of each received sample\n"
        "  --show-discovery           print remote endpoints and the nodes of ros_discovery_info\n"
        "  --trace FILE               write Cyclone DDS's trace (verbosity finest) to FILE\n"
        "  --stamp-delay TOPIC:MS     a TimeStamped --pub TOPIC stamps sample N at its header.stamp\n"
        "                             + MS ms + a jitter below 1 ms (repeatable; default 0)\n"
        "  --start-matched            a publisher starts once a subscriber matched it, 0.5 s later\n"
        "  --raw TOPIC:HEX            every sample of --pub TOPIC is these bytes (header included,\n"
        "                             1 to %u of them): hostile CDR (repeatable)\n"
        "  --graph-raw HEX            the ros_discovery_info samples are these bytes\n"
        "  --flood-graph N:NAMELEN    N more writers that never publish (hostile discovery, at most\n"
        "                             20000): NAMELEN 0: all on /flood, each of a type of its own;\n"
        "                             else each on a topic of its own of NAMELEN characters (<= 60000)\n"
        "  --help                     this text\n"
        "\n"
        "TYPE: std_msgs/msg/String, geometry_msgs/msg/PoseStamped, sensor_msgs/msg/PointCloud2,\n"
        "      bridgescope_test/msg/Opaque (uint32 n, uint8[] blob), benchmarking_suite/msg/TimeStamped,\n"
        "      std_msgs/msg/Float64\n"
        "QOS:  comma list of reliable|best_effort, volatile|transient_local, depth=N\n"
        "      (default reliable,volatile,depth=10, as rclcpp's default)\n"
        "\n"
        "Output, one line per event: ready | sent TOPIC N | recv TOPIC N SUMMARY | matched TOPIC COUNT\n"
        "(TimeStamped: also stamp TOPIC N HEADER_STAMP_NS TIME_NS after sent)\n"
        "(with --cdr: cdr TOPIC N SIZE HEX...; with --show-discovery: endpoint pub|sub DDS_TOPIC\n"
        "DDS_TYPE and node NAMESPACE NAME READERS WRITERS).\n"
        "Exit status: 0 done, 1 DDS error, 2 bad arguments.\n",
        prog, PEER_MAX_DOMAIN, PEER_MAX_ENDPOINTS, PEER_MAX_ENDPOINTS, PEER_MAX_MANY, PEER_MAX_SIZE,
        PEER_MAX_RAW);
}

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

// An unsigned integer in [min, max], digits only.
static bool parse_u64(const char *s, uint64_t min, uint64_t max, uint64_t *out)
{
    if (s == NULL || *s < '0' || *s > '9')
        return false;
    errno = 0;
    char *end = NULL;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < min || v > max)
        return false;
    *out = v;
    return true;
}

// A finite decimal number in (min, max] (min excluded when open, else included).
static bool parse_double(const char *s, double min, bool open, double max, double *out)
{
    if (s == NULL || *s == '\0')
        return false;
    errno = 0;
    char *end = NULL;
    double v = strtod(s, &end);
    if (errno != 0 || *end != '\0' || !isfinite(v) || v > max || v < min || (open && v == min))
        return false;
    *out = v;
    return true;
}

static bool is_alpha_(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

static bool is_digit(char c)
{
    return c >= '0' && c <= '9';
}

// A node name: [A-Za-z_][A-Za-z0-9_]*.
static bool valid_node_name(const char *s)
{
    size_t n = strlen(s);
    if (n == 0 || n > PEER_MAX_NAME || !is_alpha_(s[0]))
        return false;
    for (size_t i = 1; i < n; i++)
        if (!is_alpha_(s[i]) && !is_digit(s[i]))
            return false;
    return true;
}

// An absolute ROS name: "/" then tokens of [A-Za-z0-9_] that do not start with a digit, joined by
// single slashes, no slash at the end. The namespace "/" alone is allowed when root_ok.
static bool valid_absolute_name(const char *s, bool root_ok)
{
    size_t n = strlen(s);
    if (n == 0 || n > PEER_MAX_NAME || s[0] != '/')
        return false;
    if (n == 1)
        return root_ok;
    if (s[n - 1] == '/')
        return false;
    for (size_t i = 1; i < n; i++) {
        char c = s[i];
        if (c == '/') {
            if (s[i - 1] == '/')
                return false;
        } else if (is_digit(c)) {
            if (s[i - 1] == '/')
                return false;
        } else if (!is_alpha_(c)) {
            return false;
        }
    }
    return true;
}

static bool parse_type(const char *s, enum peer_type *out)
{
    for (unsigned i = 0; i < PEER_NTYPES; i++) {
        if (strcmp(s, type_names[i]) == 0) {
            *out = (enum peer_type)i;
            return true;
        }
    }
    return false;
}

// "reliable,transient_local,depth=5" (any order, each item optional).
static bool parse_qos(const char *s, struct peer_endpoint *ep, char *err, size_t errlen)
{
    char buf[128];
    if (strlen(s) >= sizeof buf) {
        set_err(err, errlen, "QoS too long: %s", s);
        return false;
    }
    strcpy(buf, s);
    char *save = NULL;
    for (char *item = strtok_r(buf, ",", &save); item != NULL; item = strtok_r(NULL, ",", &save)) {
        uint64_t depth = 0;
        if (strcmp(item, "reliable") == 0)
            ep->reliable = true;
        else if (strcmp(item, "best_effort") == 0)
            ep->reliable = false;
        else if (strcmp(item, "volatile") == 0)
            ep->transient_local = false;
        else if (strcmp(item, "transient_local") == 0)
            ep->transient_local = true;
        else if (strncmp(item, "depth=", 6) == 0 && parse_u64(item + 6, 1, PEER_MAX_DEPTH, &depth))
            ep->depth = (int32_t)depth;
        else {
            set_err(err, errlen, "bad QoS item '%s' (reliable|best_effort, volatile|transient_local, "
                    "depth=1..%d)", item, PEER_MAX_DEPTH);
            return false;
        }
    }
    return true;
}

// TOPIC:TYPE[:RATE_HZ[:QOS]] for a publisher, TOPIC:TYPE[:QOS] for a subscriber. The topic is
// kept as given; peer_parse_options makes relative names absolute once the node is known.
static bool parse_endpoint(const char *arg, bool publisher, bool rate_zero_ok, struct peer_endpoint *ep,
                           char *err, size_t errlen)
{
    char buf[PEER_MAX_NAME + 256];
    if (strlen(arg) >= sizeof buf) {
        set_err(err, errlen, "endpoint too long: %.40s...", arg);
        return false;
    }
    strcpy(buf, arg);
    char *parts[4] = { NULL, NULL, NULL, NULL };
    unsigned nparts = 0;
    char *p = buf;
    while (p != NULL) {
        if (nparts == (publisher ? 4u : 3u)) {
            set_err(err, errlen, "too many ':' in '%s'", arg);
            return false;
        }
        parts[nparts++] = p;
        char *colon = strchr(p, ':');
        if (colon != NULL)
            *colon++ = '\0';
        p = colon;
    }
    if (nparts < 2 || parts[0][0] == '\0') {
        set_err(err, errlen, "want TOPIC:TYPE%s, got '%s'", publisher ? "[:RATE_HZ[:QOS]]" : "[:QOS]",
                arg);
        return false;
    }
    memset(ep, 0, sizeof *ep);
    ep->rate_hz = 10.0;
    ep->reliable = true;
    ep->transient_local = false;
    ep->depth = 10;
    if (strlen(parts[0]) > PEER_MAX_NAME) {
        set_err(err, errlen, "topic name longer than %u bytes", PEER_MAX_NAME);
        return false;
    }
    strcpy(ep->topic, parts[0]);
    if (!parse_type(parts[1], &ep->type)) {
        set_err(err, errlen, "unknown type '%s' (std_msgs/msg/String, geometry_msgs/msg/PoseStamped, "
                "sensor_msgs/msg/PointCloud2, bridgescope_test/msg/Opaque, benchmarking_suite/msg/TimeStamped, "
                "std_msgs/msg/Float64)",
                parts[1]);
        return false;
    }
    const char *qos = NULL;
    if (publisher) {
        if (nparts >= 3 && parts[2][0] != '\0'
            && !parse_double(parts[2], 0.0, !rate_zero_ok, 1000.0, &ep->rate_hz)) {
            set_err(err, errlen, "bad rate '%s' (Hz, %s 0, at most 1000)", parts[2],
                    rate_zero_ok ? "at least" : "more than");
            return false;
        }
        qos = nparts >= 4 ? parts[3] : NULL;
    } else {
        qos = nparts >= 3 ? parts[2] : NULL;
    }
    return qos == NULL || parse_qos(qos, ep, err, errlen);
}

// "/ns/name" -> namespace "/ns", name "name"; "/name" -> "/", "name"; "name" -> "/", "name".
static bool parse_node(const char *arg, struct peer_options *o, char *err, size_t errlen)
{
    if (strlen(arg) > PEER_MAX_NAME) {
        set_err(err, errlen, "node name longer than %u bytes", PEER_MAX_NAME);
        return false;
    }
    const char *slash = strrchr(arg, '/');
    if (slash == NULL) {
        strcpy(o->node_namespace, "/");
        strcpy(o->node_name, arg);
    } else if (arg[0] != '/') {
        set_err(err, errlen, "node '%s': want /NAMESPACE/NAME or NAME", arg);
        return false;
    } else {
        size_t nslen = (size_t)(slash - arg);
        if (nslen == 0) {
            strcpy(o->node_namespace, "/");
        } else {
            memcpy(o->node_namespace, arg, nslen);
            o->node_namespace[nslen] = '\0';
        }
        strcpy(o->node_name, slash + 1);
    }
    if (!valid_absolute_name(o->node_namespace, true)) {
        set_err(err, errlen, "bad node namespace '%s'", o->node_namespace);
        return false;
    }
    if (!valid_node_name(o->node_name)) {
        set_err(err, errlen, "bad node name '%s' ([A-Za-z_][A-Za-z0-9_]*)", o->node_name);
        return false;
    }
    return true;
}

// Makes a relative topic absolute in the node's namespace and checks it.
static bool resolve_topic(struct peer_endpoint *ep, const struct peer_options *o, char *err,
                          size_t errlen)
{
    if (ep->topic[0] != '/') {
        if (ep->topic[0] == '~') {
            set_err(err, errlen, "private topic names (~) are not supported: %s", ep->topic);
            return false;
        }
        char full[2 * PEER_MAX_NAME + 2];
        snprintf(full, sizeof full, "%s/%s", strcmp(o->node_namespace, "/") == 0 ? "" : o->node_namespace,
                 ep->topic);
        if (strlen(full) > PEER_MAX_NAME) {
            set_err(err, errlen, "topic name longer than %u bytes: %s", PEER_MAX_NAME, full);
            return false;
        }
        strcpy(ep->topic, full);
    }
    if (!valid_absolute_name(ep->topic, false)) {
        set_err(err, errlen, "bad ROS topic name '%s'", ep->topic);
        return false;
    }
    return true;
}

// N[@FIRST]:PREFIX:TYPE[:RATE_HZ[:QOS]]. The prefix is kept as given; peer_parse_options makes it
// absolute once the node is known and checks that PREFIX plus four digits is a topic name.
static bool parse_many(const char *arg, struct peer_many *m, char *err, size_t errlen)
{
    char head[32];
    const char *colon = strchr(arg, ':');
    size_t len = colon != NULL ? (size_t)(colon - arg) : 0;
    if (colon == NULL || len == 0 || len >= sizeof head) {
        set_err(err, errlen, "want N[@FIRST]:PREFIX:TYPE[:RATE_HZ[:QOS]], got '%.60s'", arg);
        return false;
    }
    memcpy(head, arg, len);
    head[len] = '\0';
    char shown[sizeof head];
    strcpy(shown, head);
    char *at = strchr(head, '@');
    if (at != NULL)
        *at++ = '\0';
    uint64_t n = 0, first = 0;
    if (!parse_u64(head, 1, PEER_MAX_MANY, &n) || (at != NULL && !parse_u64(at, 0, PEER_MANY_END - 1, &first))
        || n + first > PEER_MANY_END) {
        set_err(err, errlen, "bad --many count '%s' (N from 1 to %u, FIRST + N at most %u)", shown, PEER_MAX_MANY,
                PEER_MANY_END);
        return false;
    }
    if (!parse_endpoint(colon + 1, true, true, &m->ep, err, errlen))
        return false;
    m->count = (uint32_t)n;
    m->first = (uint32_t)first;
    return true;
}

// The prefix of --many made absolute; PREFIX0000 must be a valid topic name.
static bool resolve_many(struct peer_many *m, const struct peer_options *o, char *err, size_t errlen)
{
    if (strlen(m->ep.topic) + PEER_MANY_DIGITS > PEER_MAX_NAME) {
        set_err(err, errlen, "--many prefix longer than %u bytes", PEER_MAX_NAME - PEER_MANY_DIGITS);
        return false;
    }
    strcat(m->ep.topic, "0000");
    if (!resolve_topic(&m->ep, o, err, errlen))
        return false;
    m->ep.topic[strlen(m->ep.topic) - PEER_MANY_DIGITS] = '\0';
    return true;
}

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

// An even number of hex digits, 1 to PEER_MAX_RAW bytes. (No empty payloads: Cyclone sends a
// sample of no bytes as a DATA without payload, which is RTPS plumbing, not CDR.)
static bool parse_hex(const char *s, struct peer_raw *raw, char *err, size_t errlen)
{
    size_t n = strlen(s);
    if (n == 0 || n % 2 != 0 || n / 2 > PEER_MAX_RAW) {
        set_err(err, errlen, "raw bytes: want an even number of hex digits, 1 to %u bytes", PEER_MAX_RAW);
        return false;
    }
    free(raw->bytes);
    raw->bytes = NULL;
    if (n > 0 && (raw->bytes = malloc(n / 2)) == NULL) {
        set_err(err, errlen, "out of memory");
        return false;
    }
    for (size_t i = 0; i < n; i += 2) {
        int hi = hex_digit(s[i]), lo = hex_digit(s[i + 1]);
        if (hi < 0 || lo < 0) {
            set_err(err, errlen, "raw bytes: '%c%c' is not a hex byte", s[i], s[i + 1]);
            return false;
        }
        raw->bytes[i / 2] = (unsigned char)(hi * 16 + lo);
    }
    raw->len = (uint32_t)(n / 2);
    raw->set = true;
    return true;
}

// The TOPIC of "TOPIC:VALUE" (colon: the ':' before VALUE, or NULL), resolved into ep->topic.
// false when there is none (`want` says what was wanted) or it is no valid name.
static bool arg_topic(const char *arg, const char *colon, const char *want, struct peer_endpoint *ep,
                      const struct peer_options *o, char *err, size_t errlen)
{
    memset(ep, 0, sizeof *ep);
    size_t len = colon != NULL ? (size_t)(colon - arg) : 0;
    if (colon == NULL || len == 0 || len > PEER_MAX_NAME) {
        set_err(err, errlen, "want %s, got '%.60s'", want, arg);
        return false;
    }
    memcpy(ep->topic, arg, len);
    ep->topic[len] = '\0';
    return resolve_topic(ep, o, err, errlen);
}

// --stamp-delay TOPIC:MS, for a TimeStamped --pub of TOPIC.
static bool attach_delay(const char *arg, struct peer_options *o, char *err, size_t errlen)
{
    const char *colon = strrchr(arg, ':');
    struct peer_endpoint ep;
    uint64_t ms = 0;
    if (!arg_topic(arg, colon, "--stamp-delay TOPIC:MS", &ep, o, err, errlen))
        return false;
    if (!parse_u64(colon + 1, 0, PEER_MAX_STAMP_DELAY_MS, &ms)) {
        set_err(err, errlen, "bad --stamp-delay '%.60s' (ms, 0..%u)", arg, PEER_MAX_STAMP_DELAY_MS);
        return false;
    }
    for (unsigned i = 0; i < o->npubs; i++) {
        if (strcmp(o->pubs[i].topic, ep.topic) == 0 && o->pubs[i].type == PEER_TIME_STAMPED) {
            o->pubs[i].stamp_delay_ns = (int64_t)ms * 1000000;
            return true;
        }
    }
    set_err(err, errlen, "--stamp-delay %s: no TimeStamped --pub of that topic", ep.topic);
    return false;
}

// --raw TOPIC:HEX, after the topics are resolved: TOPIC must be a --pub of this peer (and no --sub
// of it: a topic has one type in a participant, and a raw one is not the plain one).
static bool attach_raw(const char *arg, struct peer_options *o, char *err, size_t errlen)
{
    const char *colon = strchr(arg, ':');
    struct peer_endpoint ep;
    if (!arg_topic(arg, colon, "--raw TOPIC:HEX", &ep, o, err, errlen))
        return false;
    for (unsigned i = 0; i < o->nsubs; i++) {
        if (strcmp(o->subs[i].topic, ep.topic) == 0) {
            set_err(err, errlen, "--raw %s: this peer also subscribes to it", ep.topic);
            return false;
        }
    }
    for (unsigned i = 0; i < o->npubs; i++) {
        if (strcmp(o->pubs[i].topic, ep.topic) == 0) {
            if (o->pubs[i].raw.set) {
                set_err(err, errlen, "--raw %s given twice", ep.topic);
                return false;
            }
            return parse_hex(colon + 1, &o->pubs[i].raw, err, errlen);
        }
    }
    set_err(err, errlen, "--raw %s: no --pub of that topic", ep.topic);
    return false;
}

void peer_free_options(struct peer_options *o)
{
    for (unsigned i = 0; i < o->npubs; i++) {
        free(o->pubs[i].raw.bytes);
        o->pubs[i].raw.bytes = NULL;
    }
    free(o->graph_raw.bytes);
    o->graph_raw.bytes = NULL;
}

enum peer_parse_result peer_parse_options(int argc, char **argv, struct peer_options *o, char *err,
                                          size_t errlen)
{
    memset(o, 0, sizeof *o);
    strcpy(o->node_namespace, "/");
    strcpy(o->node_name, "bs_peer");
    o->duration_s = 30.0;
    o->size = 1024;
    o->lease_ms = 2000;
    bool have_domain = false;
    const char *raws[PEER_MAX_ENDPOINTS];
    unsigned nraw = 0;
    const char *delays[PEER_MAX_ENDPOINTS];
    unsigned ndelay = 0;

    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i];
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0)
            return PEER_PARSE_HELP;
        if (strcmp(opt, "--exit-hard") == 0) {
            o->exit_hard = true;
            continue;
        }
        if (strcmp(opt, "--cdr") == 0) {
            o->cdr = true;
            continue;
        }
        if (strcmp(opt, "--show-discovery") == 0) {
            o->show_discovery = true;
            continue;
        }
        if (strcmp(opt, "--start-matched") == 0) {
            o->start_matched = true;
            continue;
        }
        // Every other option takes a value.
        static const char *const with_value[] = { "--domain", "--node", "--pub", "--sub", "--many", "--count",
                                                  "--duration", "--size", "--lease-ms", "--trace",
                                                  "--raw", "--graph-raw", "--stamp-delay", "--flood-graph" };
        bool known = false;
        for (size_t k = 0; k < sizeof with_value / sizeof with_value[0]; k++)
            known = known || strcmp(opt, with_value[k]) == 0;
        if (!known) {
            set_err(err, errlen, "unknown option '%s' (see --help)", opt);
            return PEER_PARSE_ERROR;
        }
        if (i + 1 >= argc) {
            set_err(err, errlen, "%s needs a value", opt);
            return PEER_PARSE_ERROR;
        }
        const char *val = argv[++i];
        uint64_t u = 0;
        if (strcmp(opt, "--domain") == 0) {
            if (!parse_u64(val, 0, PEER_MAX_DOMAIN, &u)) {
                set_err(err, errlen, "bad --domain '%s' (0..%u)", val, PEER_MAX_DOMAIN);
                return PEER_PARSE_ERROR;
            }
            o->domain = (uint32_t)u;
            have_domain = true;
        } else if (strcmp(opt, "--node") == 0) {
            if (!parse_node(val, o, err, errlen))
                return PEER_PARSE_ERROR;
        } else if (strcmp(opt, "--pub") == 0 || strcmp(opt, "--sub") == 0) {
            bool pub = strcmp(opt, "--pub") == 0;
            unsigned *n = pub ? &o->npubs : &o->nsubs;
            if (*n >= PEER_MAX_ENDPOINTS) {
                set_err(err, errlen, "more than %u %s", PEER_MAX_ENDPOINTS, opt);
                return PEER_PARSE_ERROR;
            }
            if (!parse_endpoint(val, pub, false, pub ? &o->pubs[*n] : &o->subs[*n], err, errlen))
                return PEER_PARSE_ERROR;
            (*n)++;
        } else if (strcmp(opt, "--flood-graph") == 0) {
            const char *colon = strchr(val, ':');
            char head[16];
            uint64_t len = 0;
            if (colon == NULL || (size_t)(colon - val) >= sizeof head) {
                set_err(err, errlen, "bad --flood-graph '%.40s' (N:NAMELEN)", val);
                return PEER_PARSE_ERROR;
            }
            memcpy(head, val, (size_t)(colon - val));
            head[colon - val] = '\0';
            if (!parse_u64(head, 1, PEER_MAX_FLOOD, &u) || !parse_u64(colon + 1, 0, PEER_MAX_FLOOD_NAME, &len)
                || (len > 0 && len < 16)) {
                set_err(err, errlen, "bad --flood-graph '%.40s' (N 1..%u, NAMELEN 0 or 16..%u)", val, PEER_MAX_FLOOD,
                        PEER_MAX_FLOOD_NAME);
                return PEER_PARSE_ERROR;
            }
            o->flood_count = (uint32_t)u;
            o->flood_name_len = (uint32_t)len;
        } else if (strcmp(opt, "--many") == 0) {
            if (o->many.count > 0) {
                set_err(err, errlen, "--many given twice");
                return PEER_PARSE_ERROR;
            }
            if (!parse_many(val, &o->many, err, errlen))
                return PEER_PARSE_ERROR;
        } else if (strcmp(opt, "--count") == 0) {
            if (!parse_u64(val, 1, UINT32_MAX, &u)) {
                set_err(err, errlen, "bad --count '%s' (1..%u)", val, UINT32_MAX);
                return PEER_PARSE_ERROR;
            }
            o->count = u;
        } else if (strcmp(opt, "--duration") == 0) {
            if (!parse_double(val, 0.0, true, 3600.0, &o->duration_s)) {
                set_err(err, errlen, "bad --duration '%s' (seconds, more than 0, at most 3600)", val);
                return PEER_PARSE_ERROR;
            }
        } else if (strcmp(opt, "--size") == 0) {
            if (!parse_u64(val, 0, PEER_MAX_SIZE, &u)) {
                set_err(err, errlen, "bad --size '%s' (0..%u bytes)", val, PEER_MAX_SIZE);
                return PEER_PARSE_ERROR;
            }
            o->size = (uint32_t)u;
        } else if (strcmp(opt, "--lease-ms") == 0) {
            if (!parse_u64(val, 100, 3600000, &u)) {
                set_err(err, errlen, "bad --lease-ms '%s' (100..3600000)", val);
                return PEER_PARSE_ERROR;
            }
            o->lease_ms = (uint32_t)u;
        } else if (strcmp(opt, "--raw") == 0) {
            if (nraw >= PEER_MAX_ENDPOINTS) {
                set_err(err, errlen, "more than %u --raw", PEER_MAX_ENDPOINTS);
                return PEER_PARSE_ERROR;
            }
            raws[nraw++] = val; // attached to their --pub once all topics are resolved
        } else if (strcmp(opt, "--stamp-delay") == 0) {
            if (ndelay >= PEER_MAX_ENDPOINTS) {
                set_err(err, errlen, "more than %u --stamp-delay", PEER_MAX_ENDPOINTS);
                return PEER_PARSE_ERROR;
            }
            delays[ndelay++] = val;
        } else if (strcmp(opt, "--graph-raw") == 0) {
            if (o->graph_raw.set) {
                set_err(err, errlen, "--graph-raw given twice");
                return PEER_PARSE_ERROR;
            }
            if (!parse_hex(val, &o->graph_raw, err, errlen))
                return PEER_PARSE_ERROR;
        } else { // --trace
            // The name goes into Cyclone's XML configuration: no markup characters.
            if (val[0] == '\0' || strlen(val) > PEER_MAX_PATH || strpbrk(val, "<>&\"'$") != NULL) {
                set_err(err, errlen, "bad --trace file name");
                return PEER_PARSE_ERROR;
            }
            strcpy(o->trace_file, val);
        }
    }
    if (!have_domain) {
        set_err(err, errlen, "--domain is required (see --help)");
        return PEER_PARSE_ERROR;
    }
    for (unsigned i = 0; i < o->npubs; i++)
        if (!resolve_topic(&o->pubs[i], o, err, errlen))
            return PEER_PARSE_ERROR;
    for (unsigned i = 0; i < o->nsubs; i++)
        if (!resolve_topic(&o->subs[i], o, err, errlen))
            return PEER_PARSE_ERROR;
    for (unsigned i = 0; i < nraw; i++)
        if (!attach_raw(raws[i], o, err, errlen))
            return PEER_PARSE_ERROR;
    for (unsigned i = 0; i < ndelay; i++)
        if (!attach_delay(delays[i], o, err, errlen))
            return PEER_PARSE_ERROR;
    if (o->many.count > 0) {
        if (!resolve_many(&o->many, o, err, errlen))
            return PEER_PARSE_ERROR;
        // every publisher of --many has a sample of its own, with --size bytes for these types
        if ((o->many.ep.type == PEER_POINT_CLOUD2 || o->many.ep.type == PEER_OPAQUE)
            && (uint64_t)o->many.count * o->size > PEER_MAX_MANY_BYTES) {
            set_err(err, errlen, "--many %u x --size %u bytes is more than %u bytes of samples", o->many.count,
                    o->size, PEER_MAX_MANY_BYTES);
            return PEER_PARSE_ERROR;
        }
    }
    return PEER_PARSE_OK;
}
