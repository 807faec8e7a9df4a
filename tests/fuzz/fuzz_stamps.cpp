// SPDX-License-Identifier: MIT
// Fuzz target for the timestamp formats: benchmarking_suite/TimeStamped and std_msgs/Header
// (ROS 1 serialized), benchmarking_suite/msg/TimeStamped and std_msgs/msg/Float64 (ROS 2, CDR), JSON stamps from devices, "sec.nsec" texts and Float64 seconds.
//
// The whole input goes to every decoder. Properties: what decodes encodes to something that
// decodes to the same stamp; a time text read back is the same time; errors come with a message.
#include "fuzzcheck.h"
#include "wire/stampcodec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    if (const Result<StampCodec::Decoded> stamp = StampCodec::decodeTimeStamped(input); stamp) {
        const auto again = StampCodec::decodeTimeStamped(StampCodec::encodeTimeStamped(*stamp));
        FUZZ_CHECK(again && again->sampleNs == stamp->sampleNs && again->timeNs == stamp->timeNs
                       && again->seq == stamp->seq && again->frameId == stamp->frameId,
                   "a TimeStamped message changes in a round trip");
    } else {
        FUZZ_CHECK(!stamp.error().toString().isEmpty(), "a TimeStamped message rejected without a message");
    }

    if (const Result<StampCodec::Decoded> stamp = StampCodec::decodeTimeStampedCdr(input); stamp) {
        const QByteArray encoded = StampCodec::encodeTimeStampedCdr(*stamp);
        const auto again = StampCodec::decodeTimeStampedCdr(encoded);
        FUZZ_CHECK(again && again->sampleNs == stamp->sampleNs && again->timeNs == stamp->timeNs
                       && again->frameId == stamp->frameId,
                   "a ROS 2 TimeStamped sample changes in a round trip");
    } else {
        FUZZ_CHECK(!stamp.error().toString().isEmpty(),
                   "a ROS 2 TimeStamped sample rejected without a message");
    }
    (void)StampCodec::decodeFloat64SecondsCdr(input);

    qsizetype consumed = -1;
    if (StampCodec::decodeHeader(input, &consumed))
        FUZZ_CHECK(consumed > 0 && consumed <= input.size(), "a header longer than its bytes");

    if (const Result<StampCodec::Decoded> stamp = StampCodec::decodeJson(input); stamp) {
        // encodeJson writes sample ids as times; an id that is no time ("frame-17") is hashed
        // on reading, and only the time survives the round trip.
        const bool hashedId = stamp->sampleNs == StampCodec::hashId(stamp->frameId.toUtf8());
        const auto again = StampCodec::decodeJson(StampCodec::encodeJson(stamp->sampleNs, stamp->timeNs));
        FUZZ_CHECK(again && (hashedId || again->sampleNs == stamp->sampleNs) && again->timeNs == stamp->timeNs,
                   "a JSON stamp changes in a round trip");
    } else {
        FUZZ_CHECK(!stamp.error().toString().isEmpty(), "a JSON stamp rejected without a message");
    }

    const QString text = QString::fromUtf8(input);
    if (const std::optional<qint64> ns = StampCodec::parseTime(text)) {
        const std::optional<qint64> again = StampCodec::parseTime(StampCodec::timeText(*ns));
        FUZZ_CHECK(again && *again == *ns, "a time changes when written as text and read back");
    }
    (void)StampCodec::decodeFloat64Seconds(input);
    FUZZ_CHECK(StampCodec::hashId(input) >= 0, "a negative hashed sample id");
    return 0;
}
