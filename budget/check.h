// `skinsim check` and `skinsim baseline` without the CLI: evaluate every budget of a file,
// or record the baseline every budget would be compared against.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "budget/baseline_file.h"
#include "budget/budget_file.h"
#include "budget/evaluate.h"

namespace skinsim::budget {

struct BudgetOutcome {
  std::string name;
  std::string device;
  std::vector<LimitResult> limits;
  double seconds = 0.0;  // wall time to measure it (JUnit reports it; not part of results)
};

struct CheckReport {
  std::vector<BudgetOutcome> budgets;
  std::vector<std::string> warnings;  // baseline provenance differences

  int limit_count() const;
  int failure_count() const;
  bool passed() const { return failure_count() == 0; }
};

// Measures and evaluates every budget of `file` in order. `baseline` is required when a
// limit is baseline-relative (BudgetError otherwise, naming the limit's line); when present,
// its provenance is compared with this tool and each budget's device profile.
CheckReport check_budgets(const BudgetFile& file, const std::optional<Baseline>& baseline,
                          const std::string& data_dir, int threads);

// Measures every budget of `file` (with quality metrics) and returns the baseline to store.
Baseline record_baseline(const BudgetFile& file, const std::string& data_dir, int threads);

}  // namespace skinsim::budget
