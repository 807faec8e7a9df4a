// SPDX-License-Identifier: MIT
// Fuzz target for the answers of Prometheus's HTTP API the fleet view parses (PrometheusAnswer::read):
// the bytes of a server on the network, already bounded in size by PrometheusClient.
//
// Input: an answer's body. Properties: no crash; a refusal says why and keeps no series; at most
// kMaxSeries series, kMaxPoints points and kMaxLabels labels a series, each label within its bound;
// every time a finite number; the counts of what was dropped or skipped never negative; what the
// direct reader of the usual form takes (readUsual) is what the JSON document's reader gives
// (readGeneral), series by series, label by label, point by point, and so is what it takes with a
// label pool that met the same metric objects before.
#include "fleet/prometheusanswer.h"
#include "fuzzcheck.h"

#include <cmath>
#include <cstring>

namespace {
bool samePoint(const PrometheusAnswer::Point& a, const PrometheusAnswer::Point& b)
{
    return std::memcmp(&a.time, &b.time, sizeof a.time) == 0
        && (a.value == b.value || (std::isnan(a.value) && std::isnan(b.value)));
}

bool sameAnswer(const PrometheusAnswer& a, const PrometheusAnswer& b)
{
    if (a.error != b.error || a.warnings != b.warnings || a.droppedSeries != b.droppedSeries
        || a.droppedPoints != b.droppedPoints || a.badSamples != b.badSamples
        || a.series.size() != b.series.size())
        return false;
    for (qsizetype i = 0; i < a.series.size(); ++i) {
        const PrometheusAnswer::Series& x = a.series.at(i);
        const PrometheusAnswer::Series& y = b.series.at(i);
        if (x.labels != y.labels || x.points.size() != y.points.size())
            return false;
        for (qsizetype k = 0; k < x.points.size(); ++k)
            if (!samePoint(x.points.at(k), y.points.at(k)))
                return false;
    }
    return true;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray bytes = fuzz::bytes(data, size);
    const PrometheusAnswer a = PrometheusAnswer::read(bytes);
    PrometheusAnswer usual;
    if (PrometheusAnswer::readUsual(bytes, &usual)) {
        FUZZ_CHECK(sameAnswer(usual, PrometheusAnswer::readGeneral(bytes)), "the two readers disagree");
        // Read twice with one pool, the second time from the metric objects it keeps.
        PrometheusLabelPool pool;
        for (int time = 0; time < 2; ++time) {
            PrometheusAnswer pooled;
            FUZZ_CHECK(PrometheusAnswer::readUsual(bytes, &pooled, &pool), "the pool changed the form");
            FUZZ_CHECK(sameAnswer(pooled, usual), "the pool changed the answer");
        }
    }
    FUZZ_CHECK(a.droppedSeries >= 0 && a.droppedPoints >= 0 && a.badSamples >= 0, "a negative count");
    if (!a.ok()) {
        FUZZ_CHECK(a.series.isEmpty(), "a refused answer with series");
        FUZZ_CHECK(a.error.size() <= 3 * PrometheusAnswer::kMaxTextChars, "an error past its bound");
        return 0;
    }
    FUZZ_CHECK(a.series.size() <= PrometheusAnswer::kMaxSeries, "series past the bound");
    qsizetype points = 0;
    for (const PrometheusAnswer::Series& s : a.series) {
        FUZZ_CHECK(s.labels.size() <= PrometheusAnswer::kMaxLabels, "labels past the bound");
        for (const auto& [name, value] : s.labels)
            FUZZ_CHECK(name.size() <= PrometheusAnswer::kMaxTextChars + 1
                           && value.size() <= PrometheusAnswer::kMaxTextChars + 1,
                       "a label past its bound");
        for (const PrometheusAnswer::Point& p : s.points)
            FUZZ_CHECK(std::isfinite(p.time), "a time that is not a number");
        points += s.points.size();
    }
    FUZZ_CHECK(points <= PrometheusAnswer::kMaxPoints + a.series.size(), "points past the bound");
    FUZZ_CHECK(a.warnings.size() <= 5, "warnings past the bound");
    return 0;
}
