// Which configuration to ship, per comparison group (device, resolution, light and framing:
// ConfigResult::group), never across groups: a millisecond on an iPad is not one on an iPhone,
// and a framing's quality is not another's.
//
// Rule: of the group's configurations within the frame budget, the cheapest whose frame does
// not differ visibly from the group's best-quality configuration (ConfigResult::vs_best): a
// difference nobody can see is a tie, and the tie goes to the cheaper. When every
// configuration within the budget differs visibly from the best, the knee of the Pareto front
// of those (pareto_knee) is recommended and the verdict says so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "reports/sweep_table.h"

namespace skinsim::reports {

struct Recommendation {
  std::string group;
  std::optional<std::size_t> chosen;  // index into the rows; none when nothing fits the budget
  std::optional<std::size_t> best;    // the group's best quality (lowest metric)
  bool indistinguishable = false;     // chosen does not differ visibly from best
  // One sentence: what was chosen and why, and what it gives up against the best.
  std::string verdict;
};

// One per group, in first-appearance order. `metric` is lower-is-better (flip_skin).
std::vector<Recommendation> recommend(const SweepTable& table, const std::string& metric);

// The rule above, for the report.
std::string recommendation_rule_text();

}  // namespace skinsim::reports
