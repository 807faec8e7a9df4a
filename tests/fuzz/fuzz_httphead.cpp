// SPDX-License-Identifier: MIT
// Fuzz target for the request head reader of the metrics server (`watch --metrics`), HttpHead::parse.
//
// Input: the bytes a client sent. Properties: the work is bounded by the limit (only its first bytes
// are read: a head that has not ended within it is too large, never incomplete); what a complete or
// malformed head is does not change with the bytes that follow it (a client cannot make the server
// read a head twice); a complete request has a method and a target path.
#include "fuzzcheck.h"
#include "watch/httphead.h"

namespace {
void check(const QByteArray& input, qsizetype limit)
{
    HttpHead::Request request;
    const HttpHead::Status status = HttpHead::parse(input, limit, &request);
    FUZZ_CHECK(status != HttpHead::Status::Incomplete || input.size() <= limit, "incomplete past the limit");
    FUZZ_CHECK(status != HttpHead::Status::TooLarge || input.size() > limit, "too large within the limit");
    if (status == HttpHead::Status::Complete) {
        FUZZ_CHECK(!request.method.isEmpty() && !request.method.contains(' '), "a request without a method");
        FUZZ_CHECK(request.path.size() <= limit && request.accept.size() <= limit, "parts past the limit");
    }
    if (status == HttpHead::Status::Complete || status == HttpHead::Status::Malformed) {
        HttpHead::Request again;
        const HttpHead::Status more = HttpHead::parse(input + "\r\n\r\nGET /x HTTP/1.1\n\n", limit, &again);
        FUZZ_CHECK(more == status, "the bytes after a head changed what it is");
        FUZZ_CHECK(status != HttpHead::Status::Complete
                       || (again.method == request.method && again.path == request.path
                           && again.accept == request.accept),
                   "the bytes after a head changed the request");
    }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    check(input, 8 * 1024); // the server's limit
    check(input, 64); // a small one, to reach "too large" often
    return 0;
}
