// Failure messages that say what moved, by how much, and why it matters: which pass, the
// unit the cost model says bounds it (docs/cost-model.md), and what that means for the
// frame budget.
#pragma once

#include <string>

#include "budget/baseline_file.h"
#include "budget/budget_file.h"
#include "budget/evaluate.h"
#include "budget/metrics.h"

namespace skinsim::budget {

std::string explain_failure(const Budget& budget, const LimitResult& result,
                            const Measurement& measurement, const BaselineEntry* baseline);

}  // namespace skinsim::budget
