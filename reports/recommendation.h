// Which configuration to ship, per comparison group (device, resolution, light and framing:
// ConfigResult::group), never across groups: a millisecond on an iPad is not one on an iPhone,
// and a framing's quality is not another's.
//
// Rule: of the group's configurations within the frame budget, the cheapest whose frame does
// not differ visibly from the group's best-quality configuration (ConfigResult::vs_best): a
// difference nobody can see is a tie, and the tie goes to the cheaper. When every
// configuration within the budget differs visibly from the best, the knee of the Pareto front
// of those (pareto_knee) is recommended and the verdict says so.
//
// The rule uses the point estimate (frame_ms); the recommendation then says whether the
// chosen configuration's modelled range (frame_ms_low..high) straddles the budget, names the
// configuration the same rule picks with the slow end of each range instead, and names the
// runner-up (the rule's pick once the chosen one is set aside) and why it lost. Energy does
// not enter the rule (a frame within the budget is the goal); the sentences state each named
// configuration's mJ per frame and its range beside its ms.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

struct Recommendation {
  std::string group;
  std::optional<std::size_t> chosen;  // index into the rows; none when nothing fits the budget
  std::optional<std::size_t> best;    // the group's best quality (lowest metric)
  bool indistinguishable = false;     // chosen does not differ visibly from best
  // One sentence: what was chosen and why, and what it gives up against the best.
  std::string verdict;
  // The chosen range: low <= budget < high. `safe`: the rule applied to frame_ms_high (the
  // cheapest tie with the best whose slow end still fits); none when no tie fits at its slow
  // end. `range_note`: one sentence on both ("" when nothing is chosen).
  bool straddles_budget = false;
  std::optional<std::size_t> safe;
  std::string range_note;
  // The rule's pick with the chosen configuration set aside, and one sentence on why it
  // lost ("" when the group has no other candidate).
  std::optional<std::size_t> runner_up;
  std::string runner_up_note;
};

// One per group, in first-appearance order. `metric` is lower-is-better (flip_skin).
std::vector<Recommendation> recommend(const results::SweepTable& table, const std::string& metric);

// The metric recommendations and verdicts use: flip_skin when any row has it (the reference
// shows skin), else flip_frame.
std::string recommend_metric(const std::vector<results::ConfigResult>& rows);

// The groups of the table's rows, in first-appearance order.
std::vector<std::string> groups_in_order(const results::SweepTable& table);

// The best of `rows` by `metric` (lower is better); ties: the cheaper, then the earlier (the
// rule vs_finest and vs_best were measured against, driver/sweep/sweep_comparisons.h). nullptr when
// no row has the metric.
const results::ConfigResult* lowest_metric(const std::vector<const results::ConfigResult*>& rows,
                                           const std::string& metric);

// The rule above, for the report.
std::string recommendation_rule_text();

// A recommendation as results.json keeps it: ids instead of row indices, and its sentences.
nlohmann::json recommendation_json(const results::SweepTable& table, const Recommendation& r);

}  // namespace skinsim::reports
