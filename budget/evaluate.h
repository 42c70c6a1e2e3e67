// Checking a budget's limits against a measurement (and the stored baseline).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "budget/baseline_file.h"
#include "budget/budget_file.h"
#include "budget/metrics.h"

namespace skinsim::budget {

struct LimitResult {
  std::string budget;
  Limit limit;
  double measured = 0.0;
  double bound = 0.0;
  std::optional<double> baseline;  // for baseline-relative limits
  // Headroom in the metric's unit: bound - measured for <=, measured - bound for >=;
  // negative when exceeded.
  double margin = 0.0;
  bool passed = false;
  std::string message;  // why a failure matters (empty when passed)
};

// Evaluates every limit of `budget` in file order. `baseline` is the budget's baseline entry
// or null. Throws BudgetError naming `file` and the limit's line when a limit names a pass
// the frame does not have, or is relative to a baseline that has no entry or no value for it.
std::vector<LimitResult> evaluate_budget(const std::string& file, const Budget& budget,
                                         const Measurement& measurement,
                                         const BaselineEntry* baseline);

}  // namespace skinsim::budget
