// SPDX-License-Identifier: MIT
// Fuzz target for the JSON lines of `bridgescope experiment` as the Experiments page reads them
// (ExperimentEvent::parse): the child's standard output is input like any other.
//
// Input: one line (and, for ExperimentEventReader, the same bytes as a stream of lines). Properties:
// the reader takes no more events than lines and refuses the rest with a count; an event written
// back with the codec (toLine) reads as the same event; an event has a known kind; a cell's index is not negative and
// bounded; counts are not negative; every total is finite and within its bound, and there are at
// most kMaxTotals of them; a reason within its bound.
#include "experiment/experimentevent.h"
#include "fuzzcheck.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray input = fuzz::bytes(data, size);
    ExperimentEventReader reader;
    const qsizetype lines = input.count('\n') + 1;
    const qsizetype read = reader.feed(input).size() + reader.feed("\n").size();
    FUZZ_CHECK(read + reader.refused() <= lines, "more events and refusals than lines");
    const auto e = ExperimentEvent::parse(input);
    if (!e)
        return 0;
    const QByteArray line = e->toLine();
    const auto again = ExperimentEvent::parse(line);
    FUZZ_CHECK(again && again->kind == e->kind && again->index == e->index && again->cell == e->cell,
               "an event the codec writes does not read back");
    if (e->kind == ExperimentEvent::Kind::Throughput) {
        FUZZ_CHECK(std::isfinite(e->rateHz) && std::isfinite(e->expected), "a throughput figure that is not finite");
        return 0;
    }
    FUZZ_CHECK(e->index >= 0 && e->index <= 1'000'000, "a cell index out of range");
    FUZZ_CHECK(e->samples >= 0 && e->of >= 0 && e->remainingS >= 0, "a negative count");
    FUZZ_CHECK(e->totalMs.size() <= ExperimentEvent::kMaxTotals, "more totals than a line may hold");
    for (double ms : e->totalMs)
        FUZZ_CHECK(std::isfinite(ms) && std::abs(ms) < ExperimentEvent::kMaxTotalMs, "a total out of range");
    FUZZ_CHECK(e->reason.size() <= ExperimentEvent::kMaxReasonChars, "a reason over its bound");
    FUZZ_CHECK(e->cell.size() <= 1000, "a cell id over its bound");
    return 0;
}
