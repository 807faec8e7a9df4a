// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QtGlobal>

/// The head of an HTTP/1 request, read from the bytes a client sent so far: a pure function, so the
/// metrics server and the fuzz target (tests/fuzz/fuzz_httphead.cpp) read requests the same way.
///
/// Lenient where RFC 9112 allows it: lines may end in CRLF or a bare LF, empty lines before the
/// request line are skipped, and the target may be an absolute URI (`http://host:port/metrics`,
/// as proxies and some scrapers send it), whose path is kept. Query and fragment are dropped.
namespace HttpHead {
enum class Status {
    Incomplete, ///< no end of head yet, and within the limit: wait for more
    Complete, ///< a request line of three parts, the last HTTP/1.x
    TooLarge, ///< no end of head within `maxBytes`
    Malformed, ///< the head ended, but its request line is not HTTP/1
};

struct Request
{
    QByteArray method;
    QByteArray path; ///< origin form, "/..." (the path of an absolute URI; "/" when it has none)
    QByteArray accept; ///< the last Accept header's value, trimmed
};

/// Reads the head in `bytes` (what came so far; bytes past the head are ignored). Only the first
/// `maxBytes` are looked at: the work is bounded by the limit, whatever was sent.
Status parse(const QByteArray& bytes, qsizetype maxBytes, Request* request);
} // namespace HttpHead
