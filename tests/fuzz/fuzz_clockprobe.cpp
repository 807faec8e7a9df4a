// SPDX-License-Identifier: MIT
// Fuzz target for the clock probe bytes (ClockProbe::decode), what the clock service reads from its
// UDP port and its MQTT topic and the prober from the answers.
//
// Input: a datagram or payload. Properties: only exactly ClockProbe::kSize bytes decode; what
// decodes encodes back to the same bytes (one meaning per message, no field left unchecked);
// names and reply topics stay within their bounds, and a host name is a valid topic level.
#include "clock/clockprobe.h"
#include "fuzzcheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    const Result<ClockProbe> decoded = ClockProbe::decode(input);
    if (!decoded.ok()) {
        FUZZ_CHECK(!decoded.error().message.isEmpty(), "a refusal without a reason");
        return 0;
    }
    FUZZ_CHECK(input.size() == ClockProbe::kSize, "decoded bytes of the wrong size");
    FUZZ_CHECK(decoded->encode() == input, "decode then encode changed the bytes");
    FUZZ_CHECK(decoded->name.toUtf8().size() <= ClockProbe::kMaxNameBytes, "a name past its bound");
    FUZZ_CHECK(decoded->name.isEmpty() || ClockProbe::isValidName(decoded->name), "an invalid host name");
    FUZZ_CHECK(decoded->replyTopic.toUtf8().size() <= ClockProbe::kMaxReplyTopicBytes,
               "a topic past its bound");
    FUZZ_CHECK(decoded->kind == ClockProbe::Kind::Probe || decoded->t3 >= decoded->t2,
               "an answer with t3 < t2");
    return 0;
}
