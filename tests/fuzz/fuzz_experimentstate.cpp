// SPDX-License-Identifier: MIT
// Fuzz target for an experiment's state file (DIR/experiment.json, read by `experiment --resume`,
// `report DIR` and the Experiments page): JSON read against a fixed plan of four cells.
// Properties: a rejected file has a message; an accepted one gives one status per cell of the plan,
// in its order, each with the run path the runner would use (never the file's; none for a failed
// cell whose run was never written), a reason within its bound and a sample count that is not
// negative.
#include "experiment/experimentstate.h"
#include "fuzzcheck.h"

#include <QCoreApplication>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const ExperimentPlan plan = [] {
        const Result<ExperimentPlan> p = ExperimentPlan::read(
            "samples: 10\nfactors:\n  qos: [0, 1]\n  payload: [1000, 25%]\n", QStringLiteral("/plans"));
        FUZZ_CHECK(p && p->cells.size() == 4, "the fuzz target's own plan does not read");
        return *p;
    }();
    const Result<QList<CellStatus>> statuses = ExperimentState::parse(fuzz::bytes(data, size), plan);
    if (!statuses) {
        FUZZ_CHECK(!statuses.error().toString().isEmpty(), "a state file rejected without a message");
        return 0;
    }
    FUZZ_CHECK(statuses->size() == plan.cells.size(), "not one status per cell of the plan");
    for (qsizetype i = 0; i < statuses->size(); ++i) {
        const CellStatus& s = (*statuses)[i];
        FUZZ_CHECK(s.run == ExperimentState::runPathOf(plan.cells[i])
                       || (s.run.isEmpty() && s.state == CellStatus::Failed),
                   "a run path the state file chose");
        FUZZ_CHECK(s.reason.size() <= ExperimentState::kMaxReason, "a reason longer than its bound");
        FUZZ_CHECK(s.samples >= 0, "a negative sample count");
        FUZZ_CHECK(!CellStatus::stateName(s.state).isEmpty(), "a state without a name");
    }
    return 0;
}
