// SPDX-License-Identifier: MIT
// Fuzz target for the payload views of the Discover page (text, pretty JSON, hex, and the
// automatic choice), with the display limit the page uses and a tiny one that cuts everything.
//
// Properties: every view of a non-empty payload says how large it is; a text or hex view is
// bounded by the limit, whatever the payload's size.
#include "fuzzcheck.h"
#include "wire/payloadtext.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray payload = fuzz::bytes(data, size);
    (void)PayloadText::isText(payload);
    for (const qsizetype limit : {qsizetype(64 * 1024), qsizetype(7)}) {
        for (const PayloadText::Mode mode : {PayloadText::Mode::Auto, PayloadText::Mode::Text,
                                             PayloadText::Mode::Json, PayloadText::Mode::Hex}) {
            const PayloadText::Rendered r = PayloadText::render(payload, mode, limit);
            if (!payload.isEmpty())
                FUZZ_CHECK(!r.note.isEmpty(), "a view that does not say what it shows");
            if (mode != PayloadText::Mode::Auto)
                FUZZ_CHECK(r.mode == mode, "a view in another mode than asked for");
            if (r.mode == PayloadText::Mode::Text || r.mode == PayloadText::Mode::Hex)
                FUZZ_CHECK(r.text.size() <= 5 * limit + 80, "a cut view longer than its limit allows");
        }
    }
    const QString hex = PayloadText::hexDump(payload.left(4096));
    if (!payload.isEmpty())
        FUZZ_CHECK(!hex.isEmpty(), "an empty hex dump of a non-empty payload");
    return 0;
}
