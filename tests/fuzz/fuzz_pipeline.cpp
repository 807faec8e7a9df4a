// SPDX-License-Identifier: MIT
// Fuzz target for pipeline YAML (the suite's metrics-logger files and our hosts extension), the
// file `record --pipeline` and the Measure page read, and the labels built from its topics.
//
// Properties: an error has a message; a pipeline we accept is written and read back the same;
// every stage has a label; guessed hosts name only the pipeline's topics.
#include "fuzzcheck.h"
#include "latency/hostguess.h"
#include "latency/pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const Result<Pipeline> p = Pipeline::read(fuzz::bytes(data, size));
    if (!p) {
        FUZZ_CHECK(!p.error().toString().isEmpty(), "a pipeline rejected without a message");
        return 0;
    }
    const Result<Pipeline> again = Pipeline::read(p->toYaml());
    FUZZ_CHECK(again.ok(), "our own pipeline YAML is rejected");
    FUZZ_CHECK(*again == *p, "a pipeline changes when written and read back");

    for (int stage = 0; stage < p->stageCount(); ++stage) {
        FUZZ_CHECK(!p->stageLabel(stage).isEmpty(), "a stage without a label");
        (void)p->labels().longStageLabel(stage);
        (void)p->isCrossing(stage);
    }
    for (int i = 0; i < p->topicCount(); ++i) {
        FUZZ_CHECK(p->indexOf(p->topics().at(i)) >= 0, "a topic that indexOf() does not find");
        (void)p->component(i);
        (void)p->labels().shortTopic(i);
        (void)p->host(i);
    }
    (void)p->crossings();
    (void)p->outAndReturnCrossings();
    const QHash<QString, QString> guessed = HostGuess::ofTopics(p->topics());
    for (auto it = guessed.cbegin(); it != guessed.cend(); ++it)
        FUZZ_CHECK(p->topics().contains(it.key()), "a guessed host for a topic that is not there");
    return 0;
}
