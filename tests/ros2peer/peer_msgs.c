// SPDX-License-Identifier: MIT
// Content of the published samples and summaries of received ones (see peer_msgs.h).
#define _POSIX_C_SOURCE 200809L
#include "peer_msgs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define POINTFIELD_FLOAT32 7  // sensor_msgs/msg/PointField FLOAT32
#define POINT_STEP 16u        // x, y, z, intensity: four FLOAT32

const dds_topic_descriptor_t *peer_type_descriptor(enum peer_type type)
{
    switch (type) {
    case PEER_STRING: return &std_msgs_msg_dds__String__desc;
    case PEER_POSE_STAMPED: return &geometry_msgs_msg_dds__PoseStamped__desc;
    case PEER_POINT_CLOUD2: return &sensor_msgs_msg_dds__PointCloud2__desc;
    case PEER_OPAQUE: return &bridgescope_test_msg_dds__Opaque__desc;
    case PEER_TIME_STAMPED: return &benchmarking_suite_msg_dds__TimeStamped__desc;
    case PEER_FLOAT64: return &std_msgs_msg_dds__Float64__desc;
    default: return NULL;
    }
}

int peer_sample_init(struct peer_sample *s, enum peer_type type, uint32_t size)
{
    memset(s, 0, sizeof *s);
    s->type = type;
    strcpy(s->frame_id, "map");
    if (size > PEER_MAX_SIZE)
        size = PEER_MAX_SIZE;
    switch (type) {
    case PEER_STRING:
        s->msg.string.data = s->text;
        break;
    case PEER_POSE_STAMPED:
        s->msg.pose.header.frame_id = s->frame_id;
        s->msg.pose.pose.orientation.w = 1.0;
        break;
    case PEER_POINT_CLOUD2: {
        sensor_msgs_msg_dds__PointCloud2_ *c = &s->msg.cloud;
        static const char *const names[4] = { "x", "y", "z", "intensity" };
        for (unsigned i = 0; i < 4; i++) {
            strcpy(s->field_names[i], names[i]);
            s->fields[i].name = s->field_names[i];
            s->fields[i].offset = 4u * i;
            s->fields[i].datatype = POINTFIELD_FLOAT32;
            s->fields[i].count = 1;
        }
        uint32_t width = size / POINT_STEP;
        s->bytes = width > 0 ? malloc((size_t)width * POINT_STEP) : NULL;
        if (width > 0 && s->bytes == NULL)
            return -1;
        c->header.frame_id = s->frame_id;
        c->height = 1;
        c->width = width;
        c->fields._buffer = s->fields;
        c->fields._length = c->fields._maximum = 4;
        c->is_bigendian = false;
        c->point_step = POINT_STEP;
        c->row_step = width * POINT_STEP;
        c->data._buffer = s->bytes;
        c->data._length = c->data._maximum = width * POINT_STEP;
        c->is_dense = true;
        break;
    }
    case PEER_TIME_STAMPED:
        s->msg.stamped.header.frame_id = s->frame_id;
        break;
    case PEER_FLOAT64:
        break;
    case PEER_OPAQUE:
        s->bytes = size > 0 ? malloc(size) : NULL;
        if (size > 0 && s->bytes == NULL)
            return -1;
        for (uint32_t i = 0; i < size; i++)
            s->bytes[i] = (uint8_t)(i & 0xffu);
        s->msg.opaque.blob._buffer = s->bytes;
        s->msg.opaque.blob._length = s->msg.opaque.blob._maximum = size;
        break;
    default:
        return -1;
    }
    return 0;
}

void peer_sample_fini(struct peer_sample *s)
{
    free(s->bytes);
    s->bytes = NULL;
}

static void stamp_now(builtin_interfaces_msg_dds__Time_ *t)
{
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    t->sec = (int32_t)ts.tv_sec;
    t->nanosec = (uint32_t)ts.tv_nsec;
}

// ns since the epoch into a builtin_interfaces Time.
static void set_time(builtin_interfaces_msg_dds__Time_ *t, int64_t ns)
{
    t->sec = (int32_t)(ns / 1000000000);
    t->nanosec = (uint32_t)(ns % 1000000000);
}

// The process's first stamp, in whole ms: the same for every topic.
static int64_t stamp_base_ns(void)
{
    static int64_t base = 0;
    if (base == 0) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        base = ((int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000) * 1000000;
    }
    return base;
}

// A float as 4 little-endian bytes, whatever the host's byte order.
static void put_float_le(uint8_t *p, float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    p[0] = (uint8_t)u;
    p[1] = (uint8_t)(u >> 8);
    p[2] = (uint8_t)(u >> 16);
    p[3] = (uint8_t)(u >> 24);
}

void peer_sample_fill(struct peer_sample *s, uint64_t n)
{
    switch (s->type) {
    case PEER_STRING:
        snprintf(s->text, sizeof s->text, "hello %llu", (unsigned long long)n);
        break;
    case PEER_POSE_STAMPED: {
        geometry_msgs_msg_dds__PoseStamped_ *p = &s->msg.pose;
        stamp_now(&p->header.stamp);
        p->pose.position.x = (double)n;
        p->pose.position.y = 2.0 * (double)n;
        p->pose.position.z = 0.5;
        p->pose.orientation.x = 0.0;
        p->pose.orientation.y = 0.0;
        p->pose.orientation.z = 0.0;
        p->pose.orientation.w = 1.0;
        break;
    }
    case PEER_POINT_CLOUD2: {
        sensor_msgs_msg_dds__PointCloud2_ *c = &s->msg.cloud;
        stamp_now(&c->header.stamp);
        for (uint32_t i = 0; i < c->width; i++) {
            uint8_t *pt = s->bytes + (size_t)i * POINT_STEP;
            put_float_le(pt, (float)i);
            put_float_le(pt + 4, 2.0f * (float)i);
            put_float_le(pt + 8, (float)n);
            put_float_le(pt + 12, 0.5f);
        }
        break;
    }
    case PEER_OPAQUE:
        s->msg.opaque.n = (uint32_t)n;
        break;
    case PEER_FLOAT64: // a latency as mqtt_client's ~/latencies/<topic>: 10 to 19 ms, in seconds
        s->msg.float64.data = (double)(10 + n % 10) / 1000.0;
        break;
    case PEER_TIME_STAMPED: {
        // splitmix64's finalizer of (n, salt): a jitter spread evenly over 0..999 us
        uint64_t mix = n * 0x9E3779B97F4A7C15ull + (uint64_t)s->salt * 0xBF58476D1CE4E5B9ull;
        mix = (mix ^ (mix >> 31)) * 0x94D049BB133111EBull;
        mix = (mix ^ (mix >> 29)) % 1000u;
        s->stamp_ns = stamp_base_ns() + (int64_t)n * s->period_ns;
        s->time_ns = s->stamp_ns + s->stamp_delay_ns + (int64_t)mix * 1000;
        set_time(&s->msg.stamped.header.stamp, s->stamp_ns);
        set_time(&s->msg.stamped.time, s->time_ns);
        break;
    }
    default:
        break;
    }
}

void peer_summary(enum peer_type type, const void *msg, char *out, size_t outlen)
{
    if (outlen == 0)
        return;
    switch (type) {
    case PEER_STRING: {
        const char *d = ((const std_msgs_msg_dds__String_ *)msg)->data;
        size_t i = 0;
        for (; d != NULL && d[i] != '\0' && i + 1 < outlen; i++) {
            unsigned char c = (unsigned char)d[i];
            out[i] = (c < 0x20 || c == 0x7f) ? '?' : (char)c;
        }
        out[i] = '\0';
        break;
    }
    case PEER_POSE_STAMPED:
        snprintf(out, outlen, "x=%.17g", ((const geometry_msgs_msg_dds__PoseStamped_ *)msg)->pose.position.x);
        break;
    case PEER_POINT_CLOUD2: {
        const sensor_msgs_msg_dds__PointCloud2_ *c = msg;
        snprintf(out, outlen, "width=%u data=%u", (unsigned)c->width, (unsigned)c->data._length);
        break;
    }
    case PEER_OPAQUE: {
        const bridgescope_test_msg_dds__Opaque_ *o = msg;
        snprintf(out, outlen, "n=%u blob=%u", (unsigned)o->n, (unsigned)o->blob._length);
        break;
    }
    case PEER_FLOAT64:
        snprintf(out, outlen, "data=%.17g", ((const std_msgs_msg_dds__Float64_ *)msg)->data);
        break;
    case PEER_TIME_STAMPED: {
        const benchmarking_suite_msg_dds__TimeStamped_ *t = msg;
        snprintf(out, outlen, "stamp=%lld time=%lld",
                 (long long)t->header.stamp.sec * 1000000000 + t->header.stamp.nanosec,
                 (long long)t->time.sec * 1000000000 + t->time.nanosec);
        break;
    }
    default:
        snprintf(out, outlen, "?");
        break;
    }
}
