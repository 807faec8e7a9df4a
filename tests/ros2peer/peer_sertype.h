// SPDX-License-Identifier: MIT
// Topics typed as rmw_cyclonedds_cpp types them: its own Cyclone "sertype" rather than the one
// dds_create_topic makes from an idlc descriptor. What that changes on the wire: every sample
// starts with the encapsulation header 00 01 00 00 (CDR, little endian, options 0) and is padded
// with zeros to a multiple of 4, where Cyclone's own serializer records the padding in the
// options (00 01 00 01..03); the type allows XCDR1 only; no XTypes type information. The bytes
// in between come from Cyclone's CDR stream code driven by the idlc-generated descriptor.
#ifndef BS_ROS2PEER_SERTYPE_H
#define BS_ROS2PEER_SERTYPE_H

#include <stddef.h>
#include <stdint.h>

#include <dds/dds.h>

struct ddsi_serdata;
struct peer_raw;

// Creates topic `name` of desc's type (desc->m_typename on the wire). With `raw` (kept, not
// copied: it must outlive the topic), every sample written is raw's bytes as they are, whatever
// the sample given to dds_write: how the tests put hostile CDR on the wire.
dds_entity_t peer_create_topic(dds_entity_t participant, const dds_topic_descriptor_t *desc,
                               const char *name, const struct peer_raw *raw);

// The same with the type named `type_name` on the wire instead of desc's (hostile discovery: a
// type of its own for each writer).
dds_entity_t peer_create_topic_named(dds_entity_t participant, const dds_topic_descriptor_t *desc,
                                     const char *name, const char *type_name);

// A sample taken with dds_takecdr from a reader of such a topic:
// its serialized size (the 4-byte encapsulation header included) ...
uint32_t peer_cdr_size(const struct ddsi_serdata *sd);
// ... its first n bytes (n <= peer_cdr_size) as they came off the wire ...
void peer_cdr_bytes(const struct ddsi_serdata *sd, size_t n, unsigned char *out);
// ... the sample, checked and decoded into a new sample of desc's type (free it with
// dds_sample_free(sample, desc, DDS_FREE_ALL)), or NULL when it does not decode ...
void *peer_cdr_to_sample(const struct ddsi_serdata *sd, const dds_topic_descriptor_t *desc);
// ... and its release.
void peer_cdr_release(struct ddsi_serdata *sd);

#endif
