#include "budget/evaluate.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "budget/error.h"
#include "budget/explain.h"

namespace skinsim::budget {

namespace {

// The limit is met when the comparison holds; NaN never meets one.
bool within(const Limit& limit, double measured, double bound) {
  return limit.comparison == Comparison::kAtMost ? measured <= bound : measured >= bound;
}

}  // namespace

std::vector<LimitResult> evaluate_budget(const std::string& file, const Budget& budget,
                                         const Measurement& measurement,
                                         const BaselineEntry* baseline) {
  std::vector<LimitResult> results;
  for (const Limit& limit : budget.limits) {
    const std::string at =
        fmt::format("{}:{}: budget '{}', limit '{}'", file, limit.line, budget.name, limit.metric);
    const auto it = measurement.metrics.find(limit.metric);
    if (it == measurement.metrics.end()) {
      throw BudgetError(fmt::format("{}: the frame has no pass '{}' (its passes: {})", at,
                                    metric_scope(limit.metric),
                                    fmt::join(measurement.passes, ", ")));
    }
    LimitResult r;
    r.budget = budget.name;
    r.limit = limit;
    r.measured = it->second;
    if (limit.uses_baseline()) {
      if (!baseline) {
        throw BudgetError(fmt::format(
            "{}: is relative to the baseline, which has no entry for this budget (record it "
            "with `skinsim baseline {} --update`)",
            at, file));
      }
      const auto b = baseline->metrics.find(limit.metric);
      if (b == baseline->metrics.end()) {
        throw BudgetError(
            fmt::format("{}: the baseline has no value for this metric (re-record it with `skinsim "
                        "baseline {} --update`)",
                        at, file));
      }
      // An infinite baseline would make the bound infinite and the limit always pass (or
      // never); NaN would fail it as if the frame were too slow. Neither is a real baseline.
      if (!std::isfinite(b->second)) {
        throw BudgetError(fmt::format(
            "{}: the baseline value is {:g}, not a finite number (re-record it with `skinsim "
            "baseline {} --update`)",
            at, b->second, file));
      }
      r.baseline = b->second;
    }
    r.bound = limit.bound(r.baseline.value_or(0.0));
    r.margin =
        limit.comparison == Comparison::kAtMost ? r.bound - r.measured : r.measured - r.bound;
    r.passed = within(limit, r.measured, r.bound);
    if (!r.passed) r.message = explain_failure(budget, r, measurement, baseline);
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace skinsim::budget
