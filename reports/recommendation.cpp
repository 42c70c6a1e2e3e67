#include "reports/recommendation.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "reports/comparison.h"
#include "reports/pareto.h"

namespace skinsim::reports {

namespace {

// Time and energy per frame, each with its modelled range.
std::string cost_range(const results::ConfigResult& r) {
  return fmt::format("{:.2f} ms ({:.2f} to {:.2f}) and {:.3f} mJ ({:.3f} to {:.3f}) per frame",
                     r.frame_ms, r.frame_ms_low, r.frame_ms_high, r.energy_mj, r.energy_mj_low,
                     r.energy_mj_high);
}

// A group's rows with the metric, and their indices into the table's rows.
struct Members {
  std::vector<results::ConfigResult> rows;  // copies, to reuse pareto_knee on them
  std::vector<std::size_t> index;
};

// The rule over a group's members (less `excluded`), with `time` (frame_ms, or frame_ms_high
// for the slow end) held to the budget. Returns the pick and whether it ties with the best;
// with `knee`, when no tie fits, the Pareto knee of the members instead.
struct Pick {
  std::optional<std::size_t> index;
  bool tie = false;
};

Pick pick(const results::SweepTable& table, const Members& members, std::size_t best,
          const std::string& metric, std::optional<std::size_t> excluded,
          double results::ConfigResult::*time, bool knee) {
  Pick p;
  Members rest;
  for (std::size_t k = 0; k < members.rows.size(); ++k) {
    const results::ConfigResult& r = members.rows[k];
    const std::size_t i = members.index[k];
    if (i == excluded) continue;
    rest.rows.push_back(r);
    rest.index.push_back(i);
    const bool tie = i == best || (r.vs_best && !r.vs_best->visible);
    if (!tie || r.*time > table.budget_ms) continue;
    if (!p.index || r.*time < table.rows[*p.index].*time) p.index = i;
  }
  p.tie = p.index.has_value();
  if (!p.index && knee) {
    if (const auto k = pareto_knee(rest.rows, metric, false, table.budget_ms)) {
      p.index = rest.index[*k];
    }
  }
  return p;
}

std::string against_best(const results::ConfigResult& c) {
  return c.vs_best ? fmt::format(
                         "FLIP {:.4f} against it, {:.0f} pixels above the visibility "
                         "threshold",
                         c.vs_best->flip_mean, c.vs_best->visible_px)
                   : "not compared";
}

std::string verdict_for(const std::vector<results::ConfigResult>& rows, const Recommendation& rec,
                        double budget_ms) {
  if (!rec.chosen) {
    return fmt::format("no configuration fits the {:.1f} ms budget", budget_ms);
  }
  const results::ConfigResult& c = rows[*rec.chosen];
  const results::ConfigResult& b = rows[*rec.best];
  if (*rec.chosen == *rec.best) {
    return fmt::format("{} at {}: the best quality of the group, and within the budget", c.id,
                       cost_range(c));
  }
  if (rec.indistinguishable) {
    return fmt::format(
        "{} at {}: not visibly different from the best, {} at {:.2f} ms ({}); it saves "
        "{:.2f} ms",
        c.id, cost_range(c), b.id, b.frame_ms, against_best(c), b.frame_ms - c.frame_ms);
  }
  return fmt::format(
      "{} at {}: every configuration within the budget differs visibly from the best, {} at "
      "{:.2f} ms ({}); this is the knee of the trade-off among them",
      c.id, cost_range(c), b.id, b.frame_ms, against_best(c));
}

std::string range_note_for(const std::vector<results::ConfigResult>& rows,
                           const Recommendation& rec, double budget_ms) {
  const results::ConfigResult& c = rows[*rec.chosen];
  if (!rec.straddles_budget) {
    return fmt::format(
        "Its whole modelled range, {:.2f} to {:.2f} ms, is within the {:.1f} ms budget.",
        c.frame_ms_low, c.frame_ms_high, budget_ms);
  }
  std::string note = fmt::format(
      "Its modelled range, {:.2f} to {:.2f} ms, straddles the {:.1f} ms budget: with the "
      "device's uncertain figures at their slow ends it would miss it.",
      c.frame_ms_low, c.frame_ms_high, budget_ms);
  if (!rec.safe) {
    return note +
           " No configuration that looks the same as the best fits the budget at its slow end.";
  }
  const results::ConfigResult& s = rows[*rec.safe];
  return note + fmt::format(
                    " The cheapest that looks the same as the best and fits even at its slow end "
                    "is {} at {}.",
                    s.id, cost_range(s));
}

std::string runner_up_note_for(const std::vector<results::ConfigResult>& rows,
                               const Recommendation& rec, bool runner_up_ties) {
  const results::ConfigResult& c = rows[*rec.chosen];
  const results::ConfigResult& u = rows[*rec.runner_up];
  const double more = u.frame_ms - c.frame_ms;
  const std::string cost = more >= 0.0 ? fmt::format("costs {:.2f} ms more", more)
                                       : fmt::format("saves {:.2f} ms", -more);
  std::string why;
  if (rec.indistinguishable && runner_up_ties) {
    why = fmt::format("it also looks the same as the best, but {}", cost);
  } else if (rec.indistinguishable) {
    why = fmt::format("it {} but differs visibly from the best ({})", cost, against_best(u));
  } else {
    why = fmt::format("it {}, and is further from the knee of the trade-off ({})", cost,
                      against_best(u));
  }
  return fmt::format("Runner-up: {} at {}; {}.", u.id, cost_range(u), why);
}

}  // namespace

std::string recommend_metric(const std::vector<results::ConfigResult>& rows) {
  const bool any_skin = std::any_of(rows.begin(), rows.end(), [](const results::ConfigResult& r) {
    return r.quality.count("flip_skin") > 0;
  });
  return any_skin ? "flip_skin" : "flip_frame";
}

std::vector<std::string> groups_in_order(const results::SweepTable& table) {
  std::vector<std::string> order;
  for (const results::ConfigResult& r : table.rows) {
    if (std::find(order.begin(), order.end(), r.group) == order.end()) order.push_back(r.group);
  }
  return order;
}

const results::ConfigResult* lowest_metric(const std::vector<const results::ConfigResult*>& rows,
                                           const std::string& metric) {
  const results::ConfigResult* best = nullptr;
  for (const results::ConfigResult* r : rows) {
    const auto q = r->quality.find(metric);
    if (q == r->quality.end()) continue;
    if (!best || q->second < best->quality.at(metric) ||
        (q->second == best->quality.at(metric) && r->frame_ms < best->frame_ms)) {
      best = r;
    }
  }
  return best;
}

std::vector<Recommendation> recommend(const results::SweepTable& table, const std::string& metric) {
  std::vector<Recommendation> out;
  for (const std::string& group : groups_in_order(table)) {
    Recommendation rec;
    rec.group = group;
    Members members;
    std::vector<const results::ConfigResult*> candidates;
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      const results::ConfigResult& r = table.rows[i];
      if (r.group != group || !r.quality.count(metric)) continue;
      members.rows.push_back(r);
      members.index.push_back(i);
      candidates.push_back(&r);
    }
    if (const results::ConfigResult* best = lowest_metric(candidates, metric)) {
      rec.best = static_cast<std::size_t>(best - table.rows.data());
    }
    if (rec.best) {
      const Pick chosen = pick(table, members, *rec.best, metric, std::nullopt,
                               &results::ConfigResult::frame_ms, true);
      rec.chosen = chosen.index;
      rec.indistinguishable = chosen.tie;
    }
    rec.verdict = verdict_for(table.rows, rec, table.budget_ms);
    if (rec.chosen) {
      const results::ConfigResult& c = table.rows[*rec.chosen];
      rec.straddles_budget = c.frame_ms_high > table.budget_ms;
      rec.safe = pick(table, members, *rec.best, metric, std::nullopt,
                      &results::ConfigResult::frame_ms_high, false)
                     .index;
      rec.range_note = range_note_for(table.rows, rec, table.budget_ms);
      const Pick runner_up = pick(table, members, *rec.best, metric, rec.chosen,
                                  &results::ConfigResult::frame_ms, true);
      rec.runner_up = runner_up.index;
      if (rec.runner_up) rec.runner_up_note = runner_up_note_for(table.rows, rec, runner_up.tie);
    }
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
         "their Pareto front is recommended instead. The rule uses each frame time's point "
         "estimate; when the recommended configuration's modelled range reaches past the "
         "budget, the same rule applied to the slow end of every range names the safe "
         "choice. The runner-up is the rule's pick with the recommended configuration set "
         "aside.";
}

nlohmann::json recommendation_json(const results::SweepTable& table, const Recommendation& r) {
  const auto id = [&](const std::optional<std::size_t>& i) {
    return i ? nlohmann::json(table.rows[*i].id) : nlohmann::json(nullptr);
  };
  return {{"group", r.group},
          {"chosen", id(r.chosen)},
          {"best", id(r.best)},
          {"indistinguishable", r.indistinguishable},
          {"verdict", r.verdict},
          {"straddles_budget", r.straddles_budget},
          {"safe", id(r.safe)},
          {"range_note", r.range_note},
          {"runner_up", id(r.runner_up)},
          {"runner_up_note", r.runner_up_note}};
}

}  // namespace skinsim::reports
