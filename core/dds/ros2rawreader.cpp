// SPDX-License-Identifier: MIT
#include "dds/ros2rawreader.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <dds/ddsi/q_radmin.h>

// The sertype follows tests/ros2peer/peer_sertype.c (itself after rmw_cyclonedds_cpp's
// serdata.cpp) without its descriptor: a serdata is the sample's bytes, header included, as they
// came; nothing here looks inside them.

namespace {

struct RawSerdata
{
    ddsi_serdata c;
    uint32_t size; ///< bytes of the sample
    unsigned char* data; ///< size bytes, then zeros to a multiple of 4 (Cyclone reads those too)
};

const ddsi_serdata_ops& serdataOps();

RawSerdata* newSerdata(const ddsi_sertype* type, ddsi_serdata_kind kind, std::size_t size)
{
    if (size > Ros2RawType::kMaxSampleBytes)
        return nullptr; // dropped by Cyclone as a sample that does not deserialize
    auto* d = static_cast<RawSerdata*>(std::calloc(1, sizeof(RawSerdata)));
    if (!d)
        return nullptr;
    ddsi_serdata_init(&d->c, type, kind);
    const std::size_t padded = (size + 3) & ~std::size_t(3);
    if (padded > 0 && !(d->data = static_cast<unsigned char*>(std::calloc(1, padded)))) {
        std::free(d);
        return nullptr;
    }
    d->size = uint32_t(size);
    return d;
}

const RawSerdata* raw(const ddsi_serdata* d)
{
    return reinterpret_cast<const RawSerdata*>(d);
}

bool eqkey(const ddsi_serdata*, const ddsi_serdata*)
{
    return true; // ROS 2 topics have no key
}

uint32_t getSize(const ddsi_serdata* d)
{
    return raw(d)->size;
}

void freeSerdata(ddsi_serdata* d)
{
    std::free(raw(d)->data);
    std::free(d);
}

/// Received: the fragments, in order, as bytes (those that overlap what is there are skipped).
ddsi_serdata* fromSer(const ddsi_sertype* type, ddsi_serdata_kind kind, const nn_rdata* frag, std::size_t size)
{
    RawSerdata* d = newSerdata(type, kind, size);
    if (!d)
        return nullptr;
    uint32_t off = 0;
    for (; frag; frag = frag->nextfrag) {
        if (frag->maxp1 > off && frag->maxp1 <= size && frag->min <= off) {
            const unsigned char* payload = NN_RMSG_PAYLOADOFF(frag->rmsg, NN_RDATA_PAYLOAD_OFF(frag));
            std::memcpy(d->data + off, payload + off - frag->min, frag->maxp1 - off);
            off = frag->maxp1;
        }
    }
    return &d->c;
}

ddsi_serdata* fromSerIov(const ddsi_sertype* type, ddsi_serdata_kind kind, ddsrt_msg_iovlen_t niov,
                         const ddsrt_iovec_t* iov, std::size_t size)
{
    RawSerdata* d = newSerdata(type, kind, size);
    if (!d)
        return nullptr;
    std::size_t off = 0;
    for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; ++i) {
        const std::size_t n = std::min<std::size_t>(iov[i].iov_len, size - off);
        std::memcpy(d->data + off, iov[i].iov_base, n);
        off += n;
    }
    return &d->c;
}

ddsi_serdata* fromKeyhash(const ddsi_sertype* type, const ddsi_keyhash*)
{
    RawSerdata* d = newSerdata(type, SDK_KEY, 0);
    return d ? &d->c : nullptr;
}

/// Written (we do not write; kept whole for Cyclone): a Ros2RawSample's bytes as they are.
ddsi_serdata* fromSample(const ddsi_sertype* type, ddsi_serdata_kind kind, const void* sample)
{
    const auto* s = static_cast<const Ros2RawSample*>(sample);
    const std::size_t size = kind == SDK_DATA && s ? s->size : 0;
    RawSerdata* d = newSerdata(type, kind, size);
    if (d && size > 0)
        std::memcpy(d->data, s->data, size);
    return d ? &d->c : nullptr;
}

void toSer(const ddsi_serdata* dcmn, std::size_t off, std::size_t sz, void* buf)
{
    const RawSerdata* d = raw(dcmn);
    const std::size_t held = (std::size_t(d->size) + 3) & ~std::size_t(3);
    if (off <= held && sz <= held - off && sz > 0)
        std::memcpy(buf, d->data + off, sz);
}

ddsi_serdata* toSerRef(const ddsi_serdata* dcmn, std::size_t off, std::size_t sz, ddsrt_iovec_t* ref)
{
    ref->iov_base = raw(dcmn)->data + off;
    ref->iov_len = ddsrt_iov_len_t(sz);
    return ddsi_serdata_ref(dcmn);
}

void toSerUnref(ddsi_serdata* d, const ddsrt_iovec_t*)
{
    ddsi_serdata_unref(d);
}

/// Only dds_takecdr reads these samples: a typed read gets the bytes as a view.
bool toSample(const ddsi_serdata* dcmn, void* sample, void**, void*)
{
    auto* s = static_cast<Ros2RawSample*>(sample);
    s->data = dcmn->kind == SDK_DATA ? raw(dcmn)->data : nullptr;
    s->size = dcmn->kind == SDK_DATA ? raw(dcmn)->size : 0;
    return false; // the view would outlive the serdata: refused
}

ddsi_serdata* toUntyped(const ddsi_serdata* dcmn)
{
    RawSerdata* d = newSerdata(dcmn->type, SDK_KEY, 0);
    if (!d)
        return nullptr;
    d->c.type = nullptr;
    return &d->c;
}

bool untypedToSample(const ddsi_sertype*, const ddsi_serdata*, void*, void**, void*)
{
    return true; // no key fields to fill in
}

std::size_t print(const ddsi_sertype*, const ddsi_serdata* d, char* buf, std::size_t size)
{
    const int n = std::snprintf(buf, size, "(%u bytes)", unsigned(raw(d)->size));
    return n < 0 ? 0 : std::size_t(n);
}

void getKeyhash(const ddsi_serdata*, ddsi_keyhash* buf, bool)
{
    std::memset(buf, 0, sizeof *buf);
}

const ddsi_serdata_ops& serdataOps()
{
    static const ddsi_serdata_ops ops = [] {
        ddsi_serdata_ops o {};
        o.eqkey = eqkey;
        o.get_size = getSize;
        o.from_ser = fromSer;
        o.from_ser_iov = fromSerIov;
        o.from_keyhash = fromKeyhash;
        o.from_sample = fromSample;
        o.to_ser = toSer;
        o.to_ser_ref = toSerRef;
        o.to_ser_unref = toSerUnref;
        o.to_sample = toSample;
        o.to_untyped = toUntyped;
        o.untyped_to_sample = untypedToSample;
        o.free = freeSerdata;
        o.print = print;
        o.get_keyhash = getKeyhash;
        return o;
    }();
    return ops;
}

void freeSertype(ddsi_sertype* t)
{
    ddsi_sertype_fini(t);
    delete t;
}

void zeroSamples(const ddsi_sertype*, void* samples, std::size_t count)
{
    std::memset(samples, 0, sizeof(Ros2RawSample) * count);
}

void reallocSamples(void** ptrs, const ddsi_sertype*, void* old, std::size_t oldCount, std::size_t count)
{
    const std::size_t size = sizeof(Ros2RawSample);
    auto* p = static_cast<char*>(oldCount == count ? old : dds_realloc(old, size * count));
    if (p && count > oldCount)
        std::memset(p + size * oldCount, 0, size * (count - oldCount));
    for (std::size_t i = 0; i < count; ++i)
        ptrs[i] = p ? p + i * size : nullptr;
}

void freeSamples(const ddsi_sertype*, void** ptrs, std::size_t count, dds_free_op_t op)
{
    if (count > 0 && ptrs[0] && (op & DDS_FREE_ALL_BIT))
        dds_free(ptrs[0]); // views: no contents of their own
}

bool equal(const ddsi_sertype*, const ddsi_sertype*)
{
    return true; // Cyclone compared the names and the operations already
}

uint32_t hash(const ddsi_sertype*)
{
    return 0;
}

const ddsi_sertype_ops& sertypeOps()
{
    static const ddsi_sertype_ops ops = [] {
        ddsi_sertype_ops o {};
        o.version = ddsi_sertype_v0;
        o.free = freeSertype;
        o.zero_samples = zeroSamples;
        o.realloc_samples = reallocSamples;
        o.free_samples = freeSamples;
        o.equal = equal;
        o.hash = hash;
        return o;
    }();
    return ops;
}

void onDataAvailable(dds_entity_t, void* arg)
{
    // bounded: what is there now, not what keeps coming while we take
    static_cast<Ros2RawReader*>(arg)->take(1000);
}

void onMatched(dds_entity_t, dds_subscription_matched_status_t status, void* arg)
{
    static_cast<Ros2RawReader*>(arg)->matched = int(status.current_count);
}

void onLost(dds_entity_t, dds_sample_lost_status_t status, void* arg)
{
    static_cast<Ros2RawReader*>(arg)->lost = quint64(status.total_count);
}

} // namespace

dds_entity_t Ros2RawType::createTopic(dds_entity_t participant, const std::string& name, const std::string& type)
{
    auto* st = new ddsi_sertype {};
    ddsi_sertype_init_flags(st, type.c_str(), &sertypeOps(), &serdataOps(), DDSI_SERTYPE_FLAG_TOPICKIND_NO_KEY);
    // whatever representation the writer's samples are in: they are bytes to us
    st->allowed_data_representation = DDS_DATA_REPRESENTATION_FLAG_XCDR1 | DDS_DATA_REPRESENTATION_FLAG_XCDR2;
    ddsi_sertype* stp = st;
    const dds_entity_t topic = dds_create_topic_sertype(participant, name.c_str(), &stp, nullptr, nullptr, nullptr);
    if (topic < 0)
        ddsi_sertype_unref(stp);
    return topic;
}

bool Ros2RawReader::open(dds_entity_t participant, const dds_qos_t* qos, bool listen)
{
    dds_listener_t* listener = dds_create_listener(this);
    if (listen)
        dds_lset_data_available(listener, onDataAvailable);
    dds_lset_subscription_matched(listener, onMatched);
    dds_lset_sample_lost(listener, onLost);
    reader = dds_create_reader(participant, topic, qos, listener);
    dds_delete_listener(listener);
    if (reader < 0)
        reader = 0;
    return reader > 0;
}

int Ros2RawReader::take(int max)
{
    constexpr uint32_t kBatch = 16;
    ddsi_serdata* samples[kBatch];
    dds_sample_info_t infos[kBatch];
    int taken = 0;
    while (taken < max) {
        const dds_return_t n = dds_takecdr(reader, samples, kBatch, infos, DDS_ANY_STATE);
        if (n <= 0)
            break;
        for (dds_return_t i = 0; i < n; ++i) {
            const RawSerdata* d = raw(samples[i]);
            if (infos[i].valid_data && onSample)
                onSample(Ros2RawSample {d->data, d->size}, infos[i]);
            ddsi_serdata_unref(samples[i]);
        }
        taken += n;
    }
    return taken;
}

void Ros2RawReader::close()
{
    if (reader > 0)
        dds_delete(reader);
    if (topic > 0)
        dds_delete(topic);
    reader = 0;
    topic = 0;
}
