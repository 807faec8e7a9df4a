// SPDX-License-Identifier: MIT
// Fuzz target for the suite CSV importer (the file users hand us most): parsing never crashes,
// never reads out of bounds (built with ASan and UBSan), and what it accepts survives a round trip:
// written again and read back, the topics and every sample are the same; and read in slices, as a
// file is read, it is the same as read in one piece.
//
// LLVMFuzzerTestOneInput is the libFuzzer entry point (clang -fsanitize=fuzzer links it to
// libFuzzer); without libFuzzer, fuzzdriver.cpp mutates the seed corpus for a fixed time.
#include "record/suitecsv.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {
[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "fuzz_suitecsv: %s\n", what);
    std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes = QByteArray::fromRawData(reinterpret_cast<const char*>(data), qsizetype(size));
    const Result<SuiteCsv::Data> parsed = SuiteCsv::parse(bytes, QStringLiteral("fuzz.csv"));
    // A file is read in chunks (issue 41): any slicing reads as one piece does, a quote, a CR LF
    // or the byte order mark cut between two included.
    const std::vector<qsizetype> slices {qsizetype(1 + size % 13), qsizetype(1 + (size / 13) % 5)};
    const Result<SuiteCsv::Data> sliced = SuiteCsv::parseInSlices(bytes, QStringLiteral("fuzz.csv"), slices);
    if (sliced.ok() != parsed.ok() || sliced.error().toString() != parsed.error().toString())
        fail("read in slices, the verdict differs");
    if (parsed
        && (sliced->topics != parsed->topics || sliced->samples != parsed->samples
            || sliced->problems != parsed->problems || sliced->incomplete != parsed->incomplete
            || sliced->malformed != parsed->malformed))
        fail("read in slices, the data differs");
    if (!parsed) {
        if (parsed.error().toString().isEmpty())
            fail("rejected without a message");
        return 0;
    }
    if (parsed->topics.isEmpty())
        fail("accepted without topics");
    for (const std::vector<qint64>& sample : parsed->samples)
        if (qsizetype(sample.size()) != parsed->topics.size())
            fail("a sample with the wrong number of stamps");
    if (parsed->malformed > 0 && parsed->problems.isEmpty())
        fail("skipped rows without saying where");
    for (const QString& problem : parsed->problems)
        if (!problem.startsWith(QStringLiteral("fuzz.csv:")))
            fail("a problem without its location");

    // The round trip: what we accepted, we write so that we read it the same way.
    const QByteArray again = SuiteCsv::write(parsed->topics, parsed->samples);
    const Result<SuiteCsv::Data> reread = SuiteCsv::parse(again, QStringLiteral("again.csv"));
    if (!reread)
        fail("our own output is rejected");
    if (reread->topics != parsed->topics)
        fail("topics change in a round trip");
    if (reread->samples != parsed->samples)
        fail("samples change in a round trip");
    if (reread->malformed != 0 || reread->incomplete != 0)
        fail("our own output has bad rows");
    return 0;
}
