// SPDX-License-Identifier: MIT
// An rmw_cyclonedds_cpp-style sertype in C (see peer_sertype.h); its structure follows rmw's
// serdata.cpp: a serdata is the serialized sample, header included, kept as bytes. Compiled as
// GNU C11: Cyclone's ddsi headers use the asm keyword.
#include "peer_sertype.h"

#include "peer_options.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <dds/ddsi/q_protocol.h>
#include <dds/ddsi/q_radmin.h>
#include <dds/ddsrt/endian.h>

struct peer_sertype {
    struct ddsi_sertype c;
    const dds_topic_descriptor_t *desc;
    const struct peer_raw *raw;   // NULL: samples are serialized
};

struct peer_serdata {
    struct ddsi_serdata c;
    uint32_t size;         // bytes in data: header, body, zero padding to a multiple of 4
    unsigned char *data;
};

static const struct ddsi_serdata_ops serdata_ops;

static const struct peer_sertype *sertype_of(const struct ddsi_serdata *d)
{
    return (const struct peer_sertype *)d->type;
}

// A serdata with room for size bytes, padded to a multiple of 4 with zeros (as rmw does). With
// pad false its size stays as given, but the buffer still holds the zeros: Cyclone pads every
// payload to a multiple of 4 on the wire and reads those bytes from the buffer too.
static struct peer_serdata *serdata_new_sized(const struct ddsi_sertype *type, enum ddsi_serdata_kind kind,
                                              size_t size, bool pad)
{
    if (size > UINT32_MAX - 3)
        return NULL;
    struct peer_serdata *d = calloc(1, sizeof *d);
    if (d == NULL)
        return NULL;
    ddsi_serdata_init(&d->c, type, kind);
    uint32_t padded = ((uint32_t)size + 3u) & ~3u;
    if (padded > 0) {
        d->data = calloc(1, padded);
        if (d->data == NULL) {
            free(d);
            return NULL;
        }
    }
    d->size = pad ? padded : (uint32_t)size;
    return d;
}

static struct peer_serdata *serdata_new(const struct ddsi_sertype *type, enum ddsi_serdata_kind kind,
                                        size_t size)
{
    return serdata_new_sized(type, kind, size, true);
}

static bool serdata_eqkey(const struct ddsi_serdata *a, const struct ddsi_serdata *b)
{
    (void)a;
    (void)b;
    return true;   // ROS 2 topics have no key
}

static uint32_t serdata_size(const struct ddsi_serdata *dcmn)
{
    return ((const struct peer_serdata *)dcmn)->size;
}

static void serdata_free(struct ddsi_serdata *dcmn)
{
    struct peer_serdata *d = (struct peer_serdata *)dcmn;
    free(d->data);
    free(d);
}

// Received: the fragments, in order, as bytes.
static struct ddsi_serdata *serdata_from_ser(const struct ddsi_sertype *type, enum ddsi_serdata_kind kind,
                                             const struct nn_rdata *fragchain, size_t size)
{
    struct peer_serdata *d = serdata_new(type, kind, size);
    if (d == NULL)
        return NULL;
    uint32_t off = 0;
    for (; fragchain != NULL; fragchain = fragchain->nextfrag) {
        if (fragchain->maxp1 > off && fragchain->maxp1 <= size && fragchain->min <= off) {
            const unsigned char *payload = NN_RMSG_PAYLOADOFF(fragchain->rmsg, NN_RDATA_PAYLOAD_OFF(fragchain));
            memcpy(d->data + off, payload + off - fragchain->min, fragchain->maxp1 - off);
            off = fragchain->maxp1;
        }
    }
    return &d->c;
}

static struct ddsi_serdata *serdata_from_ser_iov(const struct ddsi_sertype *type, enum ddsi_serdata_kind kind,
                                                 ddsrt_msg_iovlen_t niov, const ddsrt_iovec_t *iov, size_t size)
{
    struct peer_serdata *d = serdata_new(type, kind, size);
    if (d == NULL)
        return NULL;
    size_t off = 0;
    for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; i++) {
        size_t n = iov[i].iov_len < size - off ? iov[i].iov_len : size - off;
        memcpy(d->data + off, iov[i].iov_base, n);
        off += n;
    }
    return &d->c;
}

static struct ddsi_serdata *serdata_from_keyhash(const struct ddsi_sertype *type, const struct ddsi_keyhash *keyhash)
{
    (void)keyhash;
    struct peer_serdata *d = serdata_new(type, SDK_KEY, 0);
    return d != NULL ? &d->c : NULL;
}

// Published: header 00 01 00 00, then the sample in XCDR1 little endian, then zeros to a
// multiple of 4. A key-only serdata (unregister, dispose) is empty, as in rmw.
static struct ddsi_serdata *serdata_from_sample(const struct ddsi_sertype *type, enum ddsi_serdata_kind kind,
                                                const void *sample)
{
    if (kind != SDK_DATA) {
        struct peer_serdata *d = serdata_new(type, kind, 0);
        return d != NULL ? &d->c : NULL;
    }
    const struct peer_sertype *tp = (const struct peer_sertype *)type;
    if (tp->raw != NULL) {   // exactly the bytes given, not padded
        struct peer_serdata *d = serdata_new_sized(type, kind, tp->raw->len, false);
        if (d != NULL && tp->raw->len > 0)
            memcpy(d->data, tp->raw->bytes, tp->raw->len);
        return d != NULL ? &d->c : NULL;
    }
    dds_ostreamLE_t os;
    dds_ostreamLE_init(&os, 0, CDR_ENC_VERSION_1);
    dds_stream_writeLE(&os, sample, tp->desc->m_ops);
    struct peer_serdata *d = serdata_new(type, kind, 4 + (size_t)os.x.m_index);
    if (d != NULL) {
        d->data[0] = 0x00;   // CDR_LE: 00 01
        d->data[1] = 0x01;
        d->data[2] = 0x00;   // options: none
        d->data[3] = 0x00;
        if (os.x.m_index > 0)
            memcpy(d->data + 4, os.x.m_buffer, os.x.m_index);
    }
    dds_ostreamLE_fini(&os);
    return d != NULL ? &d->c : NULL;
}

static void serdata_to_ser(const struct ddsi_serdata *dcmn, size_t off, size_t sz, void *buf)
{
    const struct peer_serdata *d = (const struct peer_serdata *)dcmn;
    const uint32_t held = (d->size + 3u) & ~3u;   // the buffer, padding included
    if (off <= held && sz <= held - off && sz > 0)
        memcpy(buf, d->data + off, sz);
}

static struct ddsi_serdata *serdata_to_ser_ref(const struct ddsi_serdata *dcmn, size_t off, size_t sz,
                                               ddsrt_iovec_t *ref)
{
    const struct peer_serdata *d = (const struct peer_serdata *)dcmn;
    ref->iov_base = d->data + off;
    ref->iov_len = (ddsrt_iov_len_t)sz;
    return ddsi_serdata_ref(dcmn);
}

static void serdata_to_ser_unref(struct ddsi_serdata *dcmn, const ddsrt_iovec_t *ref)
{
    (void)ref;
    ddsi_serdata_unref(dcmn);
}

// Checks the bytes (bounds, and byte order when the sender's differs) with Cyclone's normalizer
// on a copy, then reads them into the sample.
static bool serdata_to_sample(const struct ddsi_serdata *dcmn, void *sample, void **bufptr, void *buflim)
{
    (void)bufptr;
    (void)buflim;
    const struct peer_serdata *d = (const struct peer_serdata *)dcmn;
    if (d->c.kind != SDK_DATA)
        return true;
    if (d->size < 4)
        return false;
    bool little;
    uint32_t xcdr;
    // The representation identifier, as on the wire: 00 00 CDR big endian, 00 01 CDR little
    // endian, 00 06 / 00 07 the same in XCDR2. Options (bytes 2 and 3) are ignored.
    if (d->data[0] != 0x00)
        return false;
    switch (d->data[1]) {
    case 0x00: little = false; xcdr = CDR_ENC_VERSION_1; break;
    case 0x01: little = true; xcdr = CDR_ENC_VERSION_1; break;
    case 0x06: little = false; xcdr = CDR_ENC_VERSION_2; break;
    case 0x07: little = true; xcdr = CDR_ENC_VERSION_2; break;
    default: return false;
    }
    uint32_t body = d->size - 4;
    char *copy = malloc(body > 0 ? body : 1);
    if (copy == NULL)
        return false;
    memcpy(copy, d->data + 4, body);
    const uint32_t *ops = sertype_of(dcmn)->desc->m_ops;
    uint32_t off = 0;
    bool bswap = little != (DDSRT_ENDIAN == DDSRT_LITTLE_ENDIAN);
    bool ok = dds_stream_normalize_data(copy, &off, body, bswap, xcdr, ops) != NULL;
    if (ok) {
        dds_istream_t is;
        dds_istream_init(&is, body, copy, xcdr);
        dds_stream_read(&is, sample, ops);
        dds_istream_fini(&is);
    }
    free(copy);
    return ok;
}

static struct ddsi_serdata *serdata_to_untyped(const struct ddsi_serdata *dcmn)
{
    struct peer_serdata *d = serdata_new(dcmn->type, SDK_KEY, 0);
    if (d == NULL)
        return NULL;
    d->c.type = NULL;
    return &d->c;
}

static bool serdata_untyped_to_sample(const struct ddsi_sertype *type, const struct ddsi_serdata *d, void *sample,
                                      void **bufptr, void *buflim)
{
    (void)type;
    (void)d;
    (void)sample;
    (void)bufptr;
    (void)buflim;
    return true;   // no key fields to fill in
}

static size_t serdata_print(const struct ddsi_sertype *type, const struct ddsi_serdata *dcmn, char *buf, size_t bufsize)
{
    (void)type;
    int n = snprintf(buf, bufsize, "(%u bytes)", (unsigned)((const struct peer_serdata *)dcmn)->size);
    return n < 0 ? 0 : (size_t)n;
}

static void serdata_get_keyhash(const struct ddsi_serdata *d, struct ddsi_keyhash *buf, bool force_md5)
{
    (void)d;
    (void)force_md5;
    memset(buf, 0, sizeof *buf);
}

static const struct ddsi_serdata_ops serdata_ops = {
    .eqkey = serdata_eqkey,
    .get_size = serdata_size,
    .from_ser = serdata_from_ser,
    .from_ser_iov = serdata_from_ser_iov,
    .from_keyhash = serdata_from_keyhash,
    .from_sample = serdata_from_sample,
    .to_ser = serdata_to_ser,
    .to_ser_ref = serdata_to_ser_ref,
    .to_ser_unref = serdata_to_ser_unref,
    .to_sample = serdata_to_sample,
    .to_untyped = serdata_to_untyped,
    .untyped_to_sample = serdata_untyped_to_sample,
    .free = serdata_free,
    .print = serdata_print,
    .get_keyhash = serdata_get_keyhash,
    // Shared memory (iceoryx) stays off in our configuration: no iox operations.
};

static void sertype_free(struct ddsi_sertype *tpcmn)
{
    ddsi_sertype_fini(tpcmn);
    free(tpcmn);
}

// Samples for loans (dds_take without buffers): arrays of the descriptor's C struct.
static void sertype_zero_samples(const struct ddsi_sertype *tpcmn, void *samples, size_t count)
{
    memset(samples, 0, ((const struct peer_sertype *)tpcmn)->desc->m_size * count);
}

static void sertype_realloc_samples(void **ptrs, const struct ddsi_sertype *tpcmn, void *old, size_t oldcount,
                                    size_t count)
{
    size_t size = ((const struct peer_sertype *)tpcmn)->desc->m_size;
    char *p = oldcount == count ? old : dds_realloc(old, size * count);
    if (p != NULL && count > oldcount)
        memset(p + size * oldcount, 0, size * (count - oldcount));
    for (size_t i = 0; i < count; i++)
        ptrs[i] = p != NULL ? p + i * size : NULL;
}

static void sertype_free_samples(const struct ddsi_sertype *tpcmn, void **ptrs, size_t count, dds_free_op_t op)
{
    if (count == 0 || ptrs[0] == NULL)
        return;
    const struct peer_sertype *tp = (const struct peer_sertype *)tpcmn;
    if (op & DDS_FREE_CONTENTS_BIT)
        for (size_t i = 0; i < count; i++)
            dds_stream_free_sample(ptrs[i], tp->desc->m_ops);
    if (op & DDS_FREE_ALL_BIT)
        dds_free(ptrs[0]);
}

static bool sertype_equal(const struct ddsi_sertype *a, const struct ddsi_sertype *b)
{
    const struct peer_sertype *x = (const struct peer_sertype *)a, *y = (const struct peer_sertype *)b;
    return x->desc == y->desc && x->raw == y->raw;
}

static uint32_t sertype_hash(const struct ddsi_sertype *tpcmn)
{
    return ((const struct peer_sertype *)tpcmn)->desc->m_size;
}

static const struct ddsi_sertype_ops sertype_ops = {
    .version = ddsi_sertype_v0,
    .arg = NULL,
    .free = sertype_free,
    .zero_samples = sertype_zero_samples,
    .realloc_samples = sertype_realloc_samples,
    .free_samples = sertype_free_samples,
    .equal = sertype_equal,
    .hash = sertype_hash,
    // As rmw: no type identifier, type map or type information (no XTypes type discovery), no
    // derived data representations, no serialization into loaned (shared memory) buffers.
};

static dds_entity_t create_topic(dds_entity_t participant, const dds_topic_descriptor_t *desc, const char *name,
                                 const struct peer_raw *raw, const char *type_name)
{
    struct peer_sertype *st = calloc(1, sizeof *st);
    if (st == NULL)
        return DDS_RETCODE_OUT_OF_RESOURCES;
    ddsi_sertype_init_flags(&st->c, type_name, &sertype_ops, &serdata_ops,
                            DDSI_SERTYPE_FLAG_TOPICKIND_NO_KEY);
    st->c.allowed_data_representation = DDS_DATA_REPRESENTATION_FLAG_XCDR1;
    st->desc = desc;
    st->raw = raw != NULL && raw->set ? raw : NULL;
    struct ddsi_sertype *stp = &st->c;
    dds_entity_t topic = dds_create_topic_sertype(participant, name, &stp, NULL, NULL, NULL);
    if (topic < 0)
        ddsi_sertype_unref(stp);
    return topic;
}

dds_entity_t peer_create_topic(dds_entity_t participant, const dds_topic_descriptor_t *desc, const char *name,
                               const struct peer_raw *raw)
{
    return create_topic(participant, desc, name, raw, desc->m_typename);
}

dds_entity_t peer_create_topic_named(dds_entity_t participant, const dds_topic_descriptor_t *desc,
                                     const char *name, const char *type_name)
{
    return create_topic(participant, desc, name, NULL, type_name);
}

uint32_t peer_cdr_size(const struct ddsi_serdata *sd)
{
    return ddsi_serdata_size(sd);
}

void peer_cdr_bytes(const struct ddsi_serdata *sd, size_t n, unsigned char *out)
{
    ddsi_serdata_to_ser(sd, 0, n, out);
}

void *peer_cdr_to_sample(const struct ddsi_serdata *sd, const dds_topic_descriptor_t *desc)
{
    void *sample = dds_alloc(desc->m_size);   // zeroed, as reading into it wants
    if (sample != NULL && !ddsi_serdata_to_sample(sd, sample, NULL, NULL)) {
        dds_sample_free(sample, desc, DDS_FREE_ALL);
        sample = NULL;
    }
    return sample;
}

void peer_cdr_release(struct ddsi_serdata *sd)
{
    ddsi_serdata_unref(sd);
}
