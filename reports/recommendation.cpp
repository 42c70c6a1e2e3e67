#include "reports/recommendation.h"

#include <fmt/format.h>

#include <algorithm>

#include "reports/comparison.h"
#include "reports/pareto.h"

namespace skinsim::reports {

namespace {

std::string ms_range(const ConfigResult& r) {
  return fmt::format("{:.2f} ms ({:.2f} to {:.2f})", r.frame_ms, r.frame_ms_low, r.frame_ms_high);
}

std::string verdict_for(const std::vector<ConfigResult>& rows, const Recommendation& rec,
                        double budget_ms) {
  if (!rec.chosen) {
    return fmt::format("no configuration fits the {:.1f} ms budget", budget_ms);
  }
  const ConfigResult& c = rows[*rec.chosen];
  const ConfigResult& b = rows[*rec.best];
  if (*rec.chosen == *rec.best) {
    return fmt::format("{} at {}: the best quality of the group, and within the budget", c.id,
                       ms_range(c));
  }
  const std::string against =
      c.vs_best ? fmt::format(
                      "FLIP {:.4f} against it, {:.0f} pixels above the visibility "
                      "threshold",
                      c.vs_best->flip_mean, c.vs_best->visible_px)
                : "not compared";
  if (rec.indistinguishable) {
    return fmt::format(
        "{} at {}: not visibly different from the best, {} at {:.2f} ms ({}); it saves "
        "{:.2f} ms",
        c.id, ms_range(c), b.id, b.frame_ms, against, b.frame_ms - c.frame_ms);
  }
  return fmt::format(
      "{} at {}: every configuration within the budget differs visibly from the best, {} at "
      "{:.2f} ms ({}); this is the knee of the trade-off among them",
      c.id, ms_range(c), b.id, b.frame_ms, against);
}

}  // namespace

std::vector<Recommendation> recommend(const SweepTable& table, const std::string& metric) {
  std::vector<std::string> order;
  for (const ConfigResult& r : table.rows) {
    if (std::find(order.begin(), order.end(), r.group) == order.end()) order.push_back(r.group);
  }
  std::vector<Recommendation> out;
  for (const std::string& group : order) {
    Recommendation rec;
    rec.group = group;
    std::vector<ConfigResult> members;  // the group's rows, to reuse pareto_knee on them
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      const ConfigResult& r = table.rows[i];
      if (r.group != group || !r.quality.count(metric)) continue;
      members.push_back(r);
      index.push_back(i);
      if (!rec.best || r.quality.at(metric) < table.rows[*rec.best].quality.at(metric) ||
          (r.quality.at(metric) == table.rows[*rec.best].quality.at(metric) &&
           r.frame_ms < table.rows[*rec.best].frame_ms)) {
        rec.best = i;
      }
    }
    for (std::size_t k = 0; k < members.size(); ++k) {
      const ConfigResult& r = members[k];
      const bool tie = index[k] == rec.best || (r.vs_best && !r.vs_best->visible);
      if (!tie || r.frame_ms > table.budget_ms) continue;
      if (!rec.chosen || r.frame_ms < table.rows[*rec.chosen].frame_ms) rec.chosen = index[k];
    }
    rec.indistinguishable = rec.chosen.has_value();
    if (!rec.chosen) {
      if (const auto knee = pareto_knee(members, metric, false, table.budget_ms)) {
        rec.chosen = index[*knee];
      }
    }
    rec.verdict = verdict_for(table.rows, rec, table.budget_ms);
    out.push_back(std::move(rec));
  }
  return out;
}

std::string recommendation_rule_text() {
  return "One recommendation per group of comparable configurations (the same device, "
         "resolution, light and framing). Of the configurations within the frame budget, the "
         "cheapest whose frame does not differ visibly from the group's best-quality "
         "configuration: a difference below visibility is a tie, and the cheaper configuration "
         "wins. " +
         visibility_rule_text("the skin") +
         " If every configuration within the budget differs visibly from the best, the knee of "
         "their Pareto front is recommended instead.";
}

}  // namespace skinsim::reports
